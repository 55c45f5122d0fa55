// impactsph verify: runs the analytic cases over spacings, measures their errors with the verification
// library (verification/measures.hpp, the same code as the CTests), fits the observed order, and writes
// the report with its plots.
#include "app/verify.hpp"
#include "app/verify_parts.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "app/gnuplot.hpp"
#include "app/picture.hpp"
#include "app/recht_ipson.hpp"
#include "app/run_args.hpp"
#include "common/case_file.hpp"
#include "common/driver.hpp"
#include "common/expected.hpp"
#include "common/output.hpp"
#include "gpu/solver.hpp"
#include "reference/solver.hpp"
#include "verification/field_diff.hpp"
#include "verification/harness.hpp"
#include "verification/measures.hpp"

namespace fs = std::filesystem;

namespace impactsph {
namespace verify_detail {

// The solver of a point in a legend or table: "reference, double", "gpu port host build, float" or "gpu
// port CUDA, float" (which build of the port ran, from the name it gives itself).
std::string solver_label(const Point& p) {
  if (p.backend == "reference") return "reference, " + p.precision;
  return std::string("gpu port ") + (p.solver.find("CUDA") != std::string::npos ? "CUDA" : "host build") + ", " +
         p.precision;
}

// The series of a point with its solver; the reference's points keep the bare series name.
std::string series_key(const Point& p) {
  return p.backend == "reference" ? p.series : p.series + " (" + solver_label(p) + ")";
}




// A look at a run's end that draws its picture (app/picture.hpp) into the report folder as STEM.png.
verification::AtEnd picture_at_end(Report& r, const std::string& what, const std::string& stem, PictureField field) {
  return [&r, what, stem, field](const Scene& scene, double time) {
    r.pictures.push_back({what, stem, write_and_draw_picture(r.dir, stem, scene, scene.particles, time, field)});
  };
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string mm(double m) { return fmt("%.4g", m * 1e3); }

std::string shell_output(const std::string& cmd) {
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return "";
  std::string s;
  char buf[256];
  while (std::fgets(buf, sizeof buf, p)) s += buf;
  pclose(p);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

std::string git_commit() {
  const std::string dir = IMPACTSPH_SOURCE_DIR;
  const std::string head = shell_output("git -C '" + dir + "' rev-parse --short=12 HEAD 2>/dev/null");
  if (head.empty()) return "unknown (not a git checkout)";
  const std::string dirty = shell_output("git -C '" + dir + "' status --porcelain --untracked-files=no 2>/dev/null");
  return head + (dirty.empty() ? "" : " with uncommitted changes");
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a.empty() ? "unknown" : a + " " + b + " " + c;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return buf;
}


Order fit_order(const std::vector<Point>& pts) {
  std::vector<double> x, y;
  for (const Point& q : pts)
    if (q.value != 0 && std::isfinite(q.value)) {
      x.push_back(std::log(q.spacing * 1e3));
      y.push_back(std::log(std::abs(q.value)));
    }
  Order o;
  o.points = static_cast<int>(x.size());
  if (x.size() < 3) return o;
  const verification::LineFit f = verification::fit_line(x, y);
  o.ok = true;
  o.p = f.slope;
  o.stderr_p = f.slope_stderr;
  o.log_c = f.intercept;
  return o;
}

// The series (with their solver: series_key) in order of appearance; `reference_only` leaves out the
// gpu port's.
std::vector<std::string> series_names(const std::vector<Point>& pts, bool reference_only) {
  std::vector<std::string> names;
  for (const Point& p : pts)
    if ((!reference_only || p.backend == "reference") &&
        std::find(names.begin(), names.end(), series_key(p)) == names.end())
      names.push_back(series_key(p));
  return names;
}

std::vector<Point> of_series(const std::vector<Point>& pts, const std::string& name) {
  std::vector<Point> out;
  for (const Point& p : pts)
    if (series_key(p) == name) out.push_back(p);
  return out;
}

void progress(const std::string& what, const RunCost& c, const std::string& result) {
  std::printf("  %-44s %8s mm %8zu particles %6ld steps %8.1f s  %s\n", what.c_str(), mm(c.spacing).c_str(),
              c.particles, c.steps, c.wall_s, result.c_str());
  std::fflush(stdout);
}

std::string cost_cells(const RunCost& c) {
  return std::to_string(c.particles) + " | " + std::to_string(c.steps) + " | " + fmt("%.3g", c.particle_steps()) +
         " | " + fmt("%.2f", c.wall_s) + " | " + fmt("%.3g", c.wall_s > 0 ? c.particle_steps() / c.wall_s : 0.0);
}

// ---------------------------------------------------------------------------------------------------
// Report

void write_results_csv(const Report& r, const fs::path& file) {
  std::string csv = "kind,series,spacing_m,value,particles,steps,particle_steps,wall_s,backend,precision\n";
  auto rows = [&](const std::vector<Point>& pts, const char* kind) {
    for (const Point& p : pts)
      csv += std::string(kind) + ",\"" + p.series + "\"," + fmt("%.6g", p.spacing) + "," + fmt("%.8g", p.value) + "," +
             std::to_string(p.cost.particles) + "," + std::to_string(p.cost.steps) + "," + fmt("%.6g", p.cost.particle_steps()) +
             "," + fmt("%.4f", p.cost.wall_s) + "," + p.backend + "," + p.precision + "\n";
  };
  rows(r.errors, "relative_error");
  rows(r.observables, "observable_SI");
  write_text_atomic(file, csv);
}

// One row per solver of each side-by-side run: the field differences against the reference (empty for
// the reference itself), the cost, and the speed ratio (reference wall time / this solver's).
void write_crosscheck_csv(const Report& r, const fs::path& file) {
  std::string csv = "case,spacing_m,particles,steps,end_time_s,solver,backend,precision";
  for (const char* f : verification::FieldDiffs::names) csv += std::string(",") + f + "_rel_l2," + f + "_rel_max";
  csv += ",dt_deviation,wall_s,particle_steps_per_s,speed_ratio_reference_over_this\n";
  for (const SideBySide& c : r.cross) {
    const double ps = double(c.particles) * double(c.steps);
    auto row = [&](const Side& s, bool port) {
      csv += "\"" + c.what + "\"," + fmt("%.6g", c.spacing) + "," + std::to_string(c.particles) + "," +
             std::to_string(c.steps) + "," + fmt("%.6g", c.end_time) + ",\"" + s.name + "\"," + s.backend + "," +
             s.precision;
      for (const verification::FieldDiff& d : s.diff.field)
        csv += port ? "," + fmt("%.4e", d.l2) + "," + fmt("%.4e", d.max) : std::string(",,");
      csv += (port ? "," + fmt("%.4e", s.dt_deviation) : std::string(",")) + "," + fmt("%.4f", s.wall_s) + "," +
             fmt("%.6g", s.wall_s > 0 ? ps / s.wall_s : 0.0) + "," + fmt("%.4f", s.wall_s > 0 ? c.ref.wall_s / s.wall_s : 0.0) +
             "\n";
    };
    row(c.ref, false);
    for (const Side& s : c.ports) row(s, true);
  }
  write_text_atomic(file, csv);
}

// The report's section "Speed against error, per case": the answers first, then each case's chart and table.
std::string speed_section(const Report& r, const std::vector<Study>& charted, int threads) {
  std::ostringstream md;
  md << "## Speed against error, per case\n\n"
     << "What an answer of a given accuracy costs on this machine (" << threads << " thread" << (threads > 1 ? "s" : "")
     << "): for each case, the wall time of each run (one spacing on one backend in one precision) against the "
        "|relative error| of the case's observables, log-log, one panel per observable with its target as a dashed "
        "line, one series per solver through its spacings, each point labelled with its spacing. On the elastic "
        "wave the gpu port stepped beside the reference (section \"CPU against GPU port\"; each solver's wall time "
        "is its own); on the validation cases every run is one of its own through the run driver, as `impactsph "
        "run` runs it (the port copies its state to the host only for output). The tables give each run's "
        "particles, steps and particle-steps.\n\n";
  if (charted.empty()) return md.str() + "No run completed (see Skipped).\n\n";
  md << "The cheapest run within the target (a run is within when every targeted observable of it is):\n\n";
  for (const Study& st : charted)
    for (const Question& q : st.questions) md << answer(r, st, q, threads);
  md << "\n";
  for (const Study& st : charted) {
    md << "### " << st.title << "\n\nTargets (" << st.source << "): ";
    for (std::size_t k = 0; k < st.measures.size(); ++k)
      md << (k ? ", " : "") << st.measures[k].label << " "
         << (st.measures[k].target > 0 ? percent(st.measures[k].target) : std::string("none"));
    md << ".\n\n![" << st.title << ": wall time against error](speed_error_" << st.stem << ".png)\n\n";
    for (const Question& q : st.questions) {
      if (st.questions.size() > 1) md << q.what << ":\n\n";
      md << study_table(r, st, q) << "\n";
    }
  }
  return md.str();
}

// The report's section "CPU against GPU port".
std::string crosscheck_section(const Report& r) {
  std::ostringstream md;
  md << "## CPU against GPU port\n\n";
  if (r.cross.empty()) {
    md << "No side-by-side run completed (see Skipped).\n\n";
    return md.str();
  }
  std::vector<std::string> names;
  for (const SideBySide& c : r.cross)
    for (const Side& s : c.ports)
      if (std::find(names.begin(), names.end(), s.name) == names.end()) names.push_back(s.name);
  md << "The reference and the gpu port ran side by side in this verify run, on the same scene, thread count "
        "and machine, as verification/crosscheck does: every solver takes the reference's CFL step, so the fields "
        "are compared at the same times. The gpu port ran as ";
  for (std::size_t k = 0; k < names.size(); ++k) md << (k ? ", " : "") << "`" << names[k] << "`";
  md << " (the name it gives itself: `host OpenMP build` is its CPU build, `CUDA` the device build; "
     << (gpu::cuda_built() ? "this program has the CUDA build" : "this program was built without CUDA") << ", and "
     << gpu::cuda::device_count() << " CUDA device" << (gpu::cuda::device_count() == 1 ? " was" : "s were")
     << " found).\n\n"
     << "Field differences at the end, relative to the reference (verification/field_diff.hpp, the definitions of "
        "crosscheck): L2 = |a - b|_2 / |b|_2 over the particles, max = max_i |a_i - b_i| / max_i |b_i|, for the "
        "displacement x - x_0, the velocity, the density and the stress S - P I. \"own dt\" is the largest "
        "relative deviation of the CFL step the port computes for itself from the reference's.\n\n"
     << "| case | spacing [mm] | particles | steps | t [us] | gpu port | displacement L2 / max | velocity L2 / max | "
        "density L2 / max | stress L2 / max | own dt |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SideBySide& c : r.cross)
    for (const Side& s : c.ports) {
      md << "| " << c.what << " | " << mm(c.spacing) << " | " << c.particles << " | " << c.steps << " | "
         << fmt("%.4g", c.end_time * 1e6) << " | " << s.precision << " |";
      for (const verification::FieldDiff& d : s.diff.field) md << " " << fmt("%.2e", d.l2) << " / " << fmt("%.2e", d.max) << " |";
      md << " " << fmt("%.1e", s.dt_deviation) << " |\n";
    }
  bool wave = false;
  for (const SideBySide& c : r.cross) wave |= c.wave;
  if (wave) {
    md << "\nElastic-wave observables of each solver (measured by the same code, verification/measures.cpp), and "
          "the port's relative difference from the reference:\n\n"
       << "| spacing [mm] | solver | wave speed [m/s] | difference | stress amplitude [MPa] | difference | "
          "velocity-profile L1 error | difference |\n|---|---|---|---|---|---|---|---|\n";
    auto rel = [](double a, double b) { return b != 0 ? a / b - 1 : a - b; };
    for (const SideBySide& c : r.cross) {
      if (!c.wave) continue;
      const verification::ElasticWaveMeasure& b = c.ref.wave;
      md << "| " << mm(c.spacing) << " | reference | " << fmt("%.2f", b.speed) << " | | " << fmt("%.4g", b.stress * 1e-6)
         << " | | " << fmt("%.5f", b.velocity_l1) << " | |\n";
      for (const Side& s : c.ports) {
        const verification::ElasticWaveMeasure& a = s.wave;
        md << "| " << mm(c.spacing) << " | gpu port, " << s.precision << " | " << fmt("%.2f", a.speed) << " | "
           << fmt("%+.2e", rel(a.speed, b.speed)) << " | " << fmt("%.4g", a.stress * 1e-6) << " | "
           << fmt("%+.2e", rel(a.stress, b.stress)) << " | " << fmt("%.5f", a.velocity_l1) << " | "
           << fmt("%+.2e", rel(a.velocity_l1, b.velocity_l1)) << " |\n";
      }
    }
  }
  md << "\nSpeed, measured in this run: wall time of each solver's stable_time_step and step calls (the steps "
        "alternate between the solvers, so a change of the machine's load hits them alike; the port also copies "
        "its state to the host after every step, as in crosscheck). Ratio = reference wall time / port wall "
        "time (above 1: the port is faster).\n\n"
     << "| case | spacing [mm] | particle-steps | reference [s] | reference particle-steps/s | gpu port | port [s] | "
        "port particle-steps/s | ratio |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const SideBySide& c : r.cross) {
    const double ps = double(c.particles) * double(c.steps);
    for (const Side& s : c.ports)
      md << "| " << c.what << " | " << mm(c.spacing) << " | " << fmt("%.3g", ps) << " | " << fmt("%.2f", c.ref.wall_s)
         << " | " << fmt("%.3g", c.ref.wall_s > 0 ? ps / c.ref.wall_s : 0.0) << " | " << s.precision << " | "
         << fmt("%.2f", s.wall_s) << " | " << fmt("%.3g", s.wall_s > 0 ? ps / s.wall_s : 0.0) << " | "
         << fmt("%.2f", s.wall_s > 0 ? c.ref.wall_s / s.wall_s : 0.0) << " |\n";
  }
  md << "\nPer solver and run: crosscheck.csv.\n\n";
  return md.str();
}

// The Taylor-bar section's sentence on its finite-element answer (verification/fe2d).
std::string taylor_fe_sentence(const FiniteElementAnswer& fe) {
  if (!fe.ran) return "The finite-element answer was not computed (see Skipped).";
  return "The solid lines are the same case by axisymmetric finite elements with the same material models (`impactsph "
         "taylor-fe`, " + std::to_string(fe.elements_across) + " elements across the radius, " +
         std::to_string(fe.elements) + " elements, " + std::to_string(fe.steps) + " steps, " + fmt("%.1f", fe.wall_s) +
         " s; verification/fe2d/README.md): final length " + mm(fe.final_length) + " mm (" +
         fmt("%+.1f %%", 100 * (fe.final_length / g_experiments.taylor_length - 1)) + " against the experiment), "
         "impact-face diameter " + mm(fe.impact_face_diameter) + " mm (" +
         fmt("%+.1f %%", 100 * (fe.impact_face_diameter / g_experiments.taylor_diameter - 1)) +
         "; twice the outer radius of the wall's node row, which the shifted SPH measure follows); the table's "
         "column \"against finite elements\".";
}

// The finite elements' value of a Taylor-bar series (m), NaN for any other series or when they did not run.
double finite_element_value(const FiniteElementAnswer& fe, const std::string& series) {
  if (!fe.ran) return std::nan("");
  if (series == "Taylor bar: final length") return fe.final_length;
  if (series == "Taylor bar: impact-face diameter") return fe.impact_face_diameter;
  return std::nan("");
}

}  // namespace verify_detail

using namespace verify_detail;

int verify_command(const VerifyOptions& opt) {
  if (opt.suite != "fast" && opt.suite != "full" && opt.suite != "smoke")
    throw std::runtime_error("--suite " + opt.suite +
                             ": valid suites are fast (elastic wave, Hugoniot), full (+ "
                             "Taylor bar, 8 mm plate, ceramic tile, CFL sensitivity) and smoke (the elastic wave at 3 "
                             "coarse spacings: CI's check of the command)");
  const std::string cases = opt.cases.empty() ? std::string(IMPACTSPH_CASES) : opt.cases;
  g_experiments = read_experiments(cases);
  for (const char* c : {"elastic-wave-convergence", "hugoniot-4340"})
    if (!fs::is_regular_file(fs::path(cases) / c / "case.toml"))
      throw std::runtime_error("no " + (fs::path(cases) / c / "case.toml").string() +
                               ": give the folder of the case folders with --cases DIR");
  const fs::path out = opt.out.empty() ? fs::path("runs") / ("verify-" + opt.suite) : fs::path(opt.out);
  fs::create_directories(out);
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  const int threads = omp_get_max_threads();
  const bool full = opt.suite == "full";
  const std::string started = utc_now(), load_before = load_average(), commit = git_commit();
  const auto t0 = std::chrono::steady_clock::now();
  std::printf("verify: %s suite, %d thread%s, report in %s\n", opt.suite.c_str(), threads, threads > 1 ? "s" : "",
              out.string().c_str());
  std::fflush(stdout);

  Report r;
  r.dir = out;
  std::vector<Cfl> cfl;
  const bool smoke = opt.suite == "smoke";
  elastic_wave(r, cases, opt.suite);
  if (smoke) {
    r.skipped.push_back({"elastic wave at 0.5 and 0.4 mm, Hugoniot", "smoke suite: only what CI can afford"});
    r.skipped.push_back({"gpu port beside the reference: elastic wave at 1 and 0.8 mm, 8 mm plate (100 steps)",
                         "smoke suite: the port runs at 2 mm only"});
  } else {
    hugoniot(r, cases, 500);
    hugoniot(r, cases, 1000);
    plate_side_by_side(r, cases);
    if (!full)
      r.skipped.push_back({"gpu port beside the reference: elastic wave at 0.5 mm",
                           "full suite only: 2 x 6.6e6 particle-steps of the port (double and float), which would "
                           "make the fast suite's elastic-wave study three times as long"});
  }
  if (!smoke)
    r.skipped.push_back({"gpu port on the Hugoniot",
                         "not run: the Hugoniot's measure (verification/measures.cpp) "
                         "steps the reference only"});
  if (full) {
    taylor_bar(r, cases, out / "runs", cfl);
    plate(r, cases, out / "runs", cfl);
    ceramic_tile(r, cases, out / "runs");
    r.skipped.push_back(
        {"gpu port on the Taylor bar at 0.635 and 0.508 mm, the 8 mm plate at 1.6 and 1.333 mm, the "
         "ceramic tile at 1.27 mm",
         "not run: double and float would add twice the particle-steps of those runs; the port runs "
         "at the coarsest spacings of each case"});
    r.skipped.push_back({"ceramic tile at 1.0583 mm",
                         "not run: 27768 particles, about 1650 steps (4.6e7 particle-steps, "
                         "cases/ceramic-tile/README.md), as many as the tile's other runs together"});
    r.skipped.push_back({"ceramic tile at 0.79375 mm (the case's own spacing)",
                         "not run: 65822 particles, 2229 steps, 23 min on two shared threads "
                         "(verification/reports/bodies-as-specified), longer than the rest of the suite"});
  } else {
    r.skipped.push_back({"elastic wave at 0.4 mm", "full suite only (--suite full): 16e6 particle-steps"});
    r.skipped.push_back({"Taylor bar over spacing (1.27-0.508 mm)", "full suite only (--suite full)"});
    r.skipped.push_back({"8 mm plate residual velocity over spacing (4-1.33 mm)", "full suite only (--suite full)"});
    r.skipped.push_back(
        {"ceramic tile residual velocity and mass over spacing (1.5875, 1.27 mm)", "full suite only (--suite full)"});
    r.skipped.push_back({"CFL sensitivity (Taylor bar, 8 mm plate)", "full suite only (--suite full)"});
  }
  const double total_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // Plots
  std::vector<std::string> plot_errors;
  auto draw = [&](const std::string& stem, const std::function<std::string(const fs::path&)>& script) {
    const std::string e = draw_gnuplot(out / (stem + ".png"), out / (stem + ".gp"), script);
    if (!e.empty()) plot_errors.push_back(e);
  };
  draw("convergence", [&](const fs::path& png) { return convergence_script(r, png); });
  std::vector<Study> charted;
  for (const Study& st : studies())
    if (study_has_points(r, st)) {
      charted.push_back(st);
      draw("speed_error_" + st.stem, [&](const fs::path& png) { return study_script(r, st, png, threads); });
    }
  if (full) {
    draw("taylor_bar", [&](const fs::path& png) {
      const double no_answer = std::nan("");
      const FiniteElementAnswer& fe = r.taylor_fe;
      return observable_script(r, png, "Taylor bar (OFHC copper, 190 m/s): final shape against spacing",
                               {{"Taylor bar: final length", g_experiments.taylor_length,
                                 fe.ran ? fe.final_length : no_answer},
                                {"Taylor bar: impact-face diameter", g_experiments.taylor_diameter,
                                 fe.ran ? fe.impact_face_diameter : no_answer}},
                               1e3, "[mm]");
    });
    draw("plate_8mm", [&](const fs::path& png) {
      return observable_script(r, png, "8 mm Weldox 460 E plate at 298 m/s: residual velocity against spacing",
                               {{"8 mm plate at 298 m/s: residual velocity", recht_ipson(g_experiments.plate_curve, kPlateSpeed)}}, 1.0,
                               "residual velocity [m/s]");
    });
  }
  write_results_csv(r, out / "results.csv");
  write_crosscheck_csv(r, out / "crosscheck.csv");

  // report.md
  std::ostringstream md;
  md << "# Verification report (" << opt.suite << " suite)\n\n"
     << "Written by `" << report_command(opt.command_line) << "`.\n\n"
     << "| | |\n|---|---|\n"
     << "| date | " << started << " |\n"
     << "| git commit (at the start) | " << commit << " |\n"
     << "| CPU | " << cpu_model() << ", " << omp_get_num_procs() << " cores |\n"
     << "| threads per run | " << threads << " (runs one after another) |\n"
     << "| load average (1, 5, 15 min) | " << load_before << " at the start, " << load_average() << " at the end |\n"
     << "| wall time of the suite | " << fmt("%.1f", total_wall) << " s (" << fmt("%.1f", total_wall / 60)
     << " min) |\n"
     << "| solvers | reference (double, OpenMP); gpu port beside it (section \"CPU against GPU port\")"
     << (full ? " and on its own on the validation cases (section \"Speed against error, per case\")" : "") << " |\n\n"
     << "Wall times are measured on a machine whose cores may be shared with other work (see the load average); "
        "they are the stepping loop's, without the scene build. Errors are relative and signed in the tables; the "
        "plots and fits use their magnitude. The observed order p is the slope of the least-squares line through "
        "(log h, log |e|) (GSL `gsl_fit_linear`), given with its standard error: a large standard error means the "
        "points do not follow one power of h.\n\n";

  md << "## Convergence against closed forms\n\n"
     << "Elastic wave (cases/elastic-wave-convergence, a 4 mm section that the spacings divide): c_L = sqrt((K + 4G/3)/rho) = " << fmt("%.1f", verification::ElasticWaveExact::c_l())
     << " m/s, stress rho c_L v = " << fmt("%.2f", verification::ElasticWaveExact::stress() / 1e6)
     << " MPa, velocity profile a 10 m/s rectangle of length 2 L_flyer (L1 error relative to its area). Hugoniot "
        "(cases/hugoniot-4340): Us = c0 + s up, P = rho0 Us up with up = V/2.\n\n"
     << "![error against spacing](convergence.png)\n\n"
     << "| series | observed order p | std. error | points |\n|---|---|---|---|\n";
  for (const std::string& s : series_names(r.errors)) {
    const Order o = fit_order(of_series(r.errors, s));
    md << "| " << s << " | " << (o.ok ? fmt("%.2f", o.p) : "-") << " | " << (o.ok ? fmt("%.2f", o.stderr_p) : "-")
       << " | " << o.points << " |\n";
  }
  md << "\nThe plot shows the reference's points; the table of orders has the gpu port's series too (labelled "
        "with the build and precision that ran), fitted over the spacings where the port ran (see its points "
        "column), so an order of the port is comparable with the reference's over the same spacings only.\n\n"
     << "| series | solver | spacing [mm] | relative error | particles | steps | particle-steps | wall [s] | "
        "particle-steps/s |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Point& p : r.errors)
    md << "| " << p.series << " | " << solver_label(p) << " | " << mm(p.spacing) << " | " << fmt("%+.3e", p.value)
       << " | " << cost_cells(p.cost) << " |\n";
  md << "\n" << speed_section(r, charted, threads) << crosscheck_section(r);

  if (full) {
    md << "## Validation observables against spacing\n\n"
       << "Taylor bar: experiment final length " << mm(g_experiments.taylor_length) << " mm, impact-face diameter "
       << mm(g_experiments.taylor_diameter)
       << " mm (Johnson and Cook 1983, as reported by Zerilli and Armstrong 1987), against the shifted face measure "
          "2 (r_max(t) + R0 - r_max(0)), which starts at the bar's true diameter (the lattice measure reads 2-7 % high; "
          "issue 19), with the case's dissipation (the limited viscosity, h = 2 dx: cases/taylor-bar/case.toml). "
       << taylor_fe_sentence(r.taylor_fe) << " 8 mm plate at 298 m/s: the experiments' "
          "Recht-Ipson curve (p = " << fmt("%.3g", g_experiments.plate_curve.p) << ", a = "
       << fmt("%.3g", g_experiments.plate_curve.a) << ", v_bl = " << fmt("%.4g", g_experiments.plate_curve.v_bl)
       << " m/s) gives " << fmt("%.1f", recht_ipson(g_experiments.plate_curve, kPlateSpeed))
       << " m/s (cases/plate-8mm/README.md). Ceramic tile "
          "(the case as committed, PAM contact, at 12.7 mm / k for k = 8 and 10: its tile lattice is cubic there; "
          "the finer 1.0583 mm and the case's own 0.79375 mm are not run, see Skipped): experiment residual velocity "
       << fmt("%.0f", g_experiments.tile_velocity) << " m/s, residual mass " << fmt("%.2f", g_experiments.tile_mass * 1e3)
       << " g (Nemat-Nasser et al. 2002, cases/ceramic-tile/README.md). The plots show the reference's runs; the "
          "table has the gpu port's too.\n\n"
       << "![Taylor bar](taylor_bar.png)\n\n![8 mm plate](plate_8mm.png)\n\n"
       << "| observable | solver | spacing [mm] | value | against experiment | against finite elements | particles | "
          "steps | particle-steps | wall [s] | particle-steps/s |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Point& p : r.observables) {
      const Observable o = validation_observable(p.series);
      const double fe = finite_element_value(r.taylor_fe, p.series);
      md << "| " << p.series << " | " << solver_label(p) << " | " << spacing_mm(p.spacing) << " | "
         << fmt(o.format, p.value * o.scale) << " " << o.unit << " | "
         << fmt("%+.1f %%", 100 * (p.value / o.experiment - 1)) << " | "
         << (std::isfinite(fe) ? fmt("%+.1f %%", 100 * (p.value / fe - 1)) : std::string("-")) << " | "
         << cost_cells(p.cost) << " |\n";
    }
    md << "\n## Time-step sensitivity (CFL 0.2 against 0.1)\n\n"
       << "Halving the CFL number halves the time step. Target: the observables move by less than 1 %.\n\n"
       << "| observable | CFL 0.2 | CFL 0.1 | change | within 1 % |\n|---|---|---|---|---|\n";
    for (const Cfl& c : cfl) {
      const bool speed = c.what.find("velocity") != std::string::npos;
      const double change = c.at_01 / c.at_02 - 1;
      md << "| " << c.what << " | " << (speed ? fmt("%.2f m/s", c.at_02) : fmt("%.3f mm", c.at_02 * 1e3)) << " | "
         << (speed ? fmt("%.2f m/s", c.at_01) : fmt("%.3f mm", c.at_01 * 1e3)) << " | " << fmt("%+.2f %%", 100 * change)
         << " | " << (std::abs(change) < 0.01 ? "yes" : "**no**") << " |\n";
    }
    md << "\n";
  }
  if (!r.pictures.empty()) {
    md << "## The finest run of each case at its end\n\n"
       << "As `impactsph run` draws it (picture.png: a cut through the model, docs/case-files.md `[output]`), "
          "coloured by the speed (elastic wave), the pressure (Hugoniot), the damage (ceramic tile) or the plastic "
          "strain; each PNG has its gnuplot script and data beside it.\n\n";
    for (const Report::Picture& p : r.pictures) {
      if (p.error.empty()) md << "![" << p.what << "](" << p.stem << ".png)\n\n";
      else md << "- " << p.what << ": not drawn: " << p.error << "\n\n";
    }
  }
  md << "## Skipped\n\n";
  if (r.skipped.empty()) md << "Nothing was skipped.\n";
  for (const Skip& s : r.skipped) md << "- " << s.what << ": " << s.why << "\n";
  if (!plot_errors.empty()) {
    md << "\n## Plots not drawn\n\n";
    for (const std::string& e : plot_errors) md << "- " << e << "\n";
  }
  md << "\nAll figures are in results.csv (one row per measured value).\n";
  write_text_atomic(out / "report.md", md.str());

  std::printf("\nobserved orders (least squares in log-log):\n");
  for (const std::string& s : series_names(r.errors)) {
    const Order o = fit_order(of_series(r.errors, s));
    if (o.ok) std::printf("  %-40s %6.2f +- %.2f\n", s.c_str(), o.p, o.stderr_p);
  }
  for (const Cfl& c : cfl)
    std::printf("  CFL 0.2 -> 0.1: %-45s %+.2f %%\n", c.what.c_str(), 100 * (c.at_01 / c.at_02 - 1));
  std::printf("verify: %.1f s; report %s\n", total_wall, (out / "report.md").string().c_str());
  for (const std::string& e : plot_errors) std::fprintf(stderr, "error: %s\n", e.c_str());
  if (r.failures > 0) {
    std::fprintf(stderr, "error: %d run%s failed; see the Skipped section of the report\n", r.failures,
                 r.failures > 1 ? "s" : "");
    return 3;
  }
  return plot_errors.empty() ? 0 : 1;
}

}  // namespace impactsph
