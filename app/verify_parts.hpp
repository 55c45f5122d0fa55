// The parts of `impactsph verify` (app/verify.cpp) shared by its files: the report it fills, the points and
// side-by-side runs in it, the experiments it compares with, and the functions of each part (internal;
// app/verify.hpp is the interface). verify.cpp: common helpers, the CSV files and the report's sections,
// verify_command; verify_studies.cpp: the runs (analytic cases, side by side, validation cases);
// verify_speed.cpp: the plots and the speed-against-error study.
#pragma once
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/recht_ipson.hpp"
#include "common/output.hpp"
#include "gpu/solver.hpp"
#include "verification/field_diff.hpp"
#include "verification/harness.hpp"
#include "verification/measures.hpp"

namespace impactsph::verify_detail {

namespace fs = std::filesystem;
using verification::RunCost;

// One measured error (or observable) of one run.
struct Point {
  std::string series;  // e.g. "elastic wave: velocity L1"
  double spacing = 0;  // m
  double value = 0;    // the error (relative, signed) or the observable (SI)
  RunCost cost;
  std::string backend = "reference", precision = "double";
  std::string solver = "reference (double, OpenMP)";  // as the solver names itself
};

struct Skip {
  std::string what, why;
};

// The reference and the gpu port stepped side by side on one scene (section "CPU against GPU port").
struct Side {
  std::string backend, precision, name;
  double wall_s = 0;               // stable_time_step + step calls of this solver
  double dt_deviation = 0;         // largest |dt_own / dt_reference - 1| of its own CFL step
  verification::FieldDiffs diff;   // at the end, against the reference
  verification::ElasticWaveMeasure wave;
};

struct SideBySide {
  std::string what;
  double spacing = 0, end_time = 0;
  std::size_t particles = 0;
  long steps = 0;
  bool wave = false;
  Side ref;
  std::vector<Side> ports;
};

// The finite-element answer of a validation case (verification/fe2d, `impactsph taylor-fe`): the reference
// line of the Taylor-bar section beside the experiment.
struct FiniteElementAnswer {
  bool ran = false;
  int elements_across = 0;
  std::size_t elements = 0;
  long steps = 0;
  double final_length = 0, impact_face_diameter = 0;  // m
  double wall_s = 0;
};

struct Report {
  FiniteElementAnswer taylor_fe;   // the Taylor bar by finite elements
  std::vector<SideBySide> cross;   // CPU against GPU port
  std::vector<Point> errors;       // against closed forms: convergence
  std::vector<Point> observables;  // validation: against experiment
  std::vector<Skip> skipped;
  std::vector<std::string> sections;  // Markdown of the CFL study and remarks
  int failures = 0;
  fs::path dir;  // the report folder
  struct Picture {
    std::string what, stem, error;  // error: why DIR/STEM.png was not drawn
  };
  std::vector<Picture> pictures;  // one per case: its finest run at its end
};

// Observed order p of |e| = C h^p: least-squares line through (log h, log |e|) (GSL, verification
// harness fit_line); the standard error of the slope says how well the points follow one power.
struct Order {
  bool ok = false;
  double p = 0, stderr_p = 0, log_c = 0;  // log C with h in mm
  int points = 0;
};

// The figures the validation observables are compared with, read from each case's expected.toml when
// verify starts (cases/NAME/expected.toml, common/expected.hpp): the Taylor bar's final length and
// impact-face diameter, the 8 mm plate's Recht-Ipson curve of the experiments (the residual velocity at
// kPlateSpeed is a (v^p - v_bl^p)^(1/p)) and the ceramic tile's residual velocity and mass, with their targets.
struct Experiments {
  double taylor_length = 0, taylor_length_tolerance = 0, taylor_diameter = 0;
  RechtIpson plate_curve;
  double tile_velocity = 0, tile_velocity_tolerance = 0, tile_mass = 0, tile_mass_tolerance = 0;
};

// A validation observable: its series, the experiment (SI) and how the report writes it.
struct Observable {
  std::string series;
  double experiment = 0;
  double scale = 1;  // SI to the unit
  const char* unit = "";
  const char* format = "%.2f";
};

struct Cfl {
  std::string what;
  double at_02 = 0, at_01 = 0;
};

// A solver of the validation runs: the reference, or the gpu port in one precision (its CUDA build
// when a device is present, else its host build) with the host copies deferred, as `impactsph run
// --backend gpu` runs it.
struct Solver {
  std::string backend = "reference", precision = "double";
  verification::MakeStepper make;  // empty: the reference
};

// One measure of a case: the series of its points, its target (the |relative error| within which the
// case's tests, or for the validation cases the issue, call a run good; 0: none) and, for a validation
// observable, the experiment (then the points hold the observable, else the relative error).
struct Measure {
  std::string series, label;
  double target = 0;
  bool observable = false;
};

// A question: the runs that have all of `measures` (one run per spacing and solver), answered by the
// cheapest run within the targets of those with one, or else the closest.
struct Question {
  std::string what;
  std::vector<int> measures;
};

struct Study {
  std::string title, stem;        // stem: the chart is speed_error_<stem>.png
  std::string against;            // "the closed form" or "the experiment"
  std::string source;             // where the targets come from
  std::vector<Measure> measures;  // one panel each
  std::vector<Question> questions;
};

// One run of a question: a spacing and solver, the relative error of each of its measures (NaN: missing).
struct StudyRun {
  double spacing = 0;
  std::string solver;
  RunCost cost;
  std::vector<double> errors;
  bool complete() const {
    for (double e : errors)
      if (!std::isfinite(e)) return false;
    return true;
  }
  // The worst error relative to its target over the measures with one (<= 1: within every target).
  double worst(const Study& st, const Question& q) const {
    double w = 0;
    for (std::size_t k = 0; k < q.measures.size(); ++k) {
      const double t = st.measures[q.measures[k]].target;
      if (t > 0) w = std::max(w, std::abs(errors[k]) / t);
    }
    return w;
  }
};

// Set once by verify_command before any study runs.
inline Experiments g_experiments;
inline constexpr double kPlateSpeed = 298;  // m/s, F scenario 1
// The README's target for the plate's residual velocity at kPlateSpeed ("How far the answers go").
inline constexpr double kPlateResidualTarget = 0.10;

// verify.cpp
std::string solver_label(const Point& p);
std::string series_key(const Point& p);
verification::AtEnd picture_at_end(Report& r, const std::string& what, const std::string& stem, PictureField field);
std::string fmt(const char* f, double v);
std::string mm(double m);
std::string shell_output(const std::string& cmd);
std::string git_commit();
std::string load_average();
std::string utc_now();
Order fit_order(const std::vector<Point>& pts);
std::vector<std::string> series_names(const std::vector<Point>& pts, bool reference_only = false);
std::vector<Point> of_series(const std::vector<Point>& pts, const std::string& name);
void progress(const std::string& what, const RunCost& c, const std::string& result);
std::string cost_cells(const RunCost& c);
void write_results_csv(const Report& r, const fs::path& file);
void write_crosscheck_csv(const Report& r, const fs::path& file);
std::string speed_section(const Report& r, const std::vector<Study>& charted, int threads);
std::string crosscheck_section(const Report& r);
std::string taylor_fe_sentence(const FiniteElementAnswer& fe);
double finite_element_value(const FiniteElementAnswer& fe, const std::string& series);

// verify_studies.cpp
double seconds_since(std::chrono::steady_clock::time_point t0);
SideBySide side_by_side(const std::string& what, const std::string& file, const std::string& h,
                        const std::vector<std::string>& sets, const std::vector<gpu::Precision>& precisions,
                        bool wave, long max_steps, const verification::AtEnd& at_end = {});
void wave_points(Report& r, const Side& s);
std::vector<std::string> port_spacings(const std::string& suite);
void elastic_wave(Report& r, const std::string& cases, const std::string& suite);
void plate_side_by_side(Report& r, const std::string& cases);
void hugoniot(Report& r, const std::string& cases, double speed);
Experiments read_experiments(const std::string& cases);
std::vector<Observable> validation_observables();
Observable validation_observable(const std::string& series);
std::vector<Solver> port_solvers();
Point observable_point(const std::string& series, double value, const verification::ObservableRun& o,
                       const Solver& solver);
std::optional<verification::ObservableRun> validation_runs(
    Report& r, const std::string& what, const std::string& file, const std::string& h,
    const std::vector<std::string>& sets, const fs::path& runs, const std::string& stem, bool port,
    const verification::AtEnd& at_end,
    const std::function<std::string(const verification::ObservableRun&, const Solver&)>& record);
bool contains(const std::vector<std::string>& v, const std::string& x);
void taylor_bar(Report& r, const std::string& cases, const fs::path& runs, std::vector<Cfl>& cfl);
void plate(Report& r, const std::string& cases, const fs::path& runs, std::vector<Cfl>& cfl);
void ceramic_tile(Report& r, const std::string& cases, const fs::path& runs);

// verify_speed.cpp
std::string header(const fs::path& png, const std::string& title, const std::string& xlabel, const std::string& ylabel);
std::string convergence_script(const Report& r, const fs::path& png);
std::vector<Study> studies();
std::vector<Point> measure_points(const Report& r, const Measure& m);
bool study_has_points(const Report& r, const Study& st);
std::vector<std::string> study_solvers(const Report& r, const Study& st);
std::string spacing_mm(double m);
std::vector<StudyRun> question_runs(const Report& r, const Study& st, const Question& q);
std::string percent(double target);
std::string solver_words(const std::string& label);
std::string answer(const Report& r, const Study& st, const Question& q, int threads);
std::string log_tics(double lo, double hi);
std::string study_script(const Report& r, const Study& st, const fs::path& png, int threads);
std::string study_table(const Report& r, const Study& st, const Question& q);
// A series of a validation plot: its points' name and the values (SI) drawn as reference lines, the
// experiment's and, where a second method gives one, the finite elements' (NaN: none).
struct PlotSeries {
  std::string name;
  double experiment = 0;
  double finite_element = std::nan("");
};
std::string observable_script(const Report& r, const fs::path& png, const std::string& title,
                              const std::vector<PlotSeries>& series, double scale, const std::string& ylabel);

}  // namespace impactsph::verify_detail
