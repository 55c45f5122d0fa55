// The parts of `impactsph ballistic-limit` that its files share (app/ballistic_limit.cpp: the search and its
// runs; app/ballistic_reference.cpp: reference.csv and the p = 2 curve of the case's geometry;
// app/ballistic_report.cpp: ballistic.csv, ballistic.json, the plot and report.md). Host only.
#pragma once
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "app/ballistic_limit.hpp"
#include "common/case_observables.hpp"
#include "common/case_spec.hpp"

namespace impactsph::ballistic {

namespace fs = std::filesystem;

// Impact speeds are run and named to 0.01 m/s, so a folder name, a CSV row and the run agree exactly.
double round_speed(double v);
// "298", "233.33", "416.7": the shortest form of a speed rounded to 0.01 m/s.
std::string speed_text(double v);
std::string fixed(double v, int digits);

// Reference figures: CASE_DIR/reference.csv with columns v_impact_m_s,v_residual_m_s,source.

struct ReferencePoint {
  double v_impact = 0, v_residual = 0;
  std::string source;
};

struct Reference {
  fs::path file;
  std::vector<ReferencePoint> points;
  std::vector<std::string> sources;  // in order of first appearance
};

// Lines starting with '#' and blank lines are skipped; the first other line is the header. No file: no points.
Reference read_reference(const fs::path& file);

// The p = 2 Recht-Ipson form of a rigid blunt projectile that pushes out a plug of its own diameter:
// a = m_p / (m_p + m_plug), from the nominal geometry (the lattice under-fills round bodies).

struct PlugForm {
  bool ok = false;
  double m_p = 0, m_plug = 0;  // kg, whole bodies
  std::string why;             // when not ok
  double a() const { return m_p / (m_p + m_plug); }
};

PlugForm plug_form(const CaseSpec& spec);

// Where a run's result came from: run here from the start, continued from the checkpoint a stopped
// search left in its folder, or read from the summary.json of a finished run of the same inputs.
enum class Origin { Ran, Continued, Reused };

struct Run {
  double v = 0;  // m/s
  fs::path dir;
  Origin origin = Origin::Ran;
  bool done = false;    // ran to its end (or settled)
  bool failed = false;  // threw; `error` says why
  bool diverged = false;
  std::string error;
  CaseObservables obs;
  double wall = 0;  // s, summary.json's wall_time_s (a failed run: its scene build and run)
  std::string picture_error;  // why its picture files could not be written
};

struct Search {
  BallisticOptions opt;
  CaseSpec spec;           // with the user's overrides, for names and geometry
  std::string projectile;  // body whose velocity is set
  fs::path out;
  int cores = 1, jobs = 1;
  double v_from = 0, v_to = 0, tolerance = 0;
  std::vector<Run> runs;  // every run started, in order
  std::mutex print_mutex;
};

// The outcome of a search as it stands: the bracket, the fits and the reference curve.
struct Outcome {
  std::string status = "running";  // running, done, interrupted, failed, bad-bracket
  bool bracketed = false;          // lo and hi are a non-perforating and a perforating run
  double lo = 0, hi = 0;
  RechtIpsonFit fit, fit_free;     // v_bl fixed at the estimate; all three free
  const Reference* reference = nullptr;
  PlugForm plug;
  bool reference_curve = false;    // reference p = 2 curve drawn
  double reference_v_bl = 0;
  std::string reference_v_bl_from;
  double reference_rms = -1;       // of the perforating runs against the reference curve
  double limit() const { return 0.5 * (lo + hi); }
};

// The runs that ran to their end, by speed.
std::vector<const Run*> sorted_done(const Search& s);
// DIR/ballistic.csv and DIR/ballistic.json, rewritten after every round.
void write_results(const Search& s, const Outcome& o);
// Writes DIR/ballistic_curve.gp and draws DIR/ballistic_curve.png with it. Returns an error message, or
// "" when the PNG is there.
std::string draw_plot(const Search& s, const Outcome& o);
// DIR/report.md: the figures of the search, its plot, its runs, and the pictures at the end of its key
// runs (the two that bracket the limit and the fastest), drawn here one after another.
void write_report(const Search& s, const Outcome& o, const std::string& plot_error);

}  // namespace impactsph::ballistic
