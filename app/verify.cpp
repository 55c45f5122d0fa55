// impactsph verify: runs the analytic cases over spacings, measures their errors with the verification
// library (verification/measures.hpp, the same code as the CTests), fits the observed order, and writes
// the report with its plots.
#include "app/verify.hpp"

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
#include <sstream>
#include <stdexcept>

#include "app/ballistic_limit.hpp"
#include "app/gnuplot.hpp"
#include "common/driver.hpp"
#include "common/output.hpp"
#include "verification/harness.hpp"
#include "verification/measures.hpp"

namespace fs = std::filesystem;

namespace impactsph {

namespace {

using verification::RunCost;

// One measured error (or observable) of one run.
struct Point {
  std::string series;  // e.g. "elastic wave: velocity L1"
  double spacing = 0;  // m
  double value = 0;    // the error (relative, signed) or the observable (SI)
  RunCost cost;
};

struct Skip {
  std::string what, why;
};

struct Report {
  std::vector<Point> errors;       // against closed forms: convergence
  std::vector<Point> observables;  // validation: against experiment
  std::vector<Skip> skipped;
  std::vector<std::string> sections;  // Markdown of the CFL study and remarks
  int failures = 0;
};

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

// Observed order p of |e| = C h^p: least-squares line through (log h, log |e|) (GSL, verification
// harness fit_line); the standard error of the slope says how well the points follow one power.
struct Order {
  bool ok = false;
  double p = 0, stderr_p = 0, log_c = 0;  // log C with h in mm
  int points = 0;
};

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

std::vector<std::string> series_names(const std::vector<Point>& pts) {
  std::vector<std::string> names;
  for (const Point& p : pts)
    if (std::find(names.begin(), names.end(), p.series) == names.end()) names.push_back(p.series);
  return names;
}

std::vector<Point> of_series(const std::vector<Point>& pts, const std::string& name) {
  std::vector<Point> out;
  for (const Point& p : pts)
    if (p.series == name) out.push_back(p);
  return out;
}

void progress(const std::string& what, const RunCost& c, const std::string& result) {
  std::printf("  %-28s %8s mm %8zu particles %6ld steps %8.1f s  %s\n", what.c_str(), mm(c.spacing).c_str(),
              c.particles, c.steps, c.wall_s, result.c_str());
  std::fflush(stdout);
}

// ---------------------------------------------------------------------------------------------------
// The studies

void elastic_wave(Report& r, const std::string& cases, bool full, bool smoke) {
  // A spacing must divide the 4 mm section, the 20 mm flyer and the 80 mm bar, or the lattice leaves gaps
  // at the faces (cases/elastic-wave-convergence/case.toml).
  const std::string file = cases + "/elastic-wave-convergence/case.toml";
  std::vector<const char*> spacings{"2 mm", "1 mm", "0.8 mm"};
  if (!smoke) spacings.push_back("0.5 mm");
  if (full) spacings.push_back("0.4 mm");  // 16e6 particle-steps: 2 to 5 minutes on one core
  for (const char* h : spacings) {
    try {
      const verification::ElasticWaveMeasure m = verification::measure_elastic_wave(file, h, {"output.vtu=false"});
      r.errors.push_back({"elastic wave: velocity profile L1", m.cost.spacing, m.velocity_l1, m.cost});
      r.errors.push_back({"elastic wave: wave speed", m.cost.spacing, m.speed_error(), m.cost});
      r.errors.push_back({"elastic wave: stress amplitude", m.cost.spacing, m.stress_error(), m.cost});
      progress("elastic wave", m.cost,
               "L1 " + fmt("%.4f", m.velocity_l1) + ", speed " + fmt("%+.3f %%", 100 * m.speed_error()) + ", stress " +
                   fmt("%+.2f %%", 100 * m.stress_error()));
    } catch (const std::exception& e) {
      ++r.failures;
      r.skipped.push_back({std::string("elastic wave at ") + h, std::string("failed: ") + e.what()});
    }
  }
}

void hugoniot(Report& r, const std::string& cases, double speed) {
  const std::string file = cases + "/hugoniot-4340/case.toml";
  const std::string tag = "Hugoniot " + fmt("%.0f", speed) + " m/s";
  // A spacing must divide the 1.5 mm section and the 10 mm plates (no gap at the impact face): 3 to 15
  // particles across.
  for (const char* h : {"0.5 mm", "0.25 mm", "0.125 mm", "0.1 mm"}) {
    try {
      const verification::HugoniotMeasure m = verification::measure_hugoniot(file, h, speed);
      r.errors.push_back({tag + ": shock pressure", m.cost.spacing, m.pressure_error(), m.cost});
      r.errors.push_back({tag + ": shock speed", m.cost.spacing, m.us_error(), m.cost});
      progress(tag, m.cost, "P " + fmt("%+.2f %%", 100 * m.pressure_error()) + ", Us " + fmt("%+.2f %%", 100 * m.us_error()));
    } catch (const std::exception& e) {
      ++r.failures;
      r.skipped.push_back({tag + " at " + h, std::string("failed: ") + e.what()});
    }
  }
}

// Experiment (shared/data/validation.md): Taylor bar final length 16.21 mm, impact-face diameter 13.56 mm.
constexpr double kTaylorLength = 16.21e-3, kTaylorDiameter = 13.56e-3;
// 8 mm plate at 298 m/s: the experiments' Recht-Ipson curve, p = 2, a = m_p/(m_p + m_plug) = 0.909,
// v_bl = 152.5 m/s (cases/plate-8mm/README.md): 232.7 m/s.
const RechtIpson kPlateCurve{0.909, 2.0, 152.5};
constexpr double kPlateSpeed = 298;

struct Cfl {
  std::string what;
  double at_02 = 0, at_01 = 0;
};

void taylor_bar(Report& r, const std::string& cases, const fs::path& runs, std::vector<Cfl>& cfl) {
  const std::string file = cases + "/taylor-bar/case.toml";
  // A cylinder has round(L/h) layers of h: these spacings give the bar its 25.4 mm exactly (20 to 50 layers).
  for (const char* h : {"1.27 mm", "0.8467 mm", "0.635 mm", "0.508 mm"}) {
    try {
      const verification::ObservableRun o = verification::run_observables(
          file, h, {"output.vtu=false"}, (runs / ("taylor-bar-" + std::string(h))).string());
      r.observables.push_back({"Taylor bar: final length", o.cost.spacing, o.observables.final_length, o.cost});
      r.observables.push_back({"Taylor bar: impact-face diameter", o.cost.spacing, o.observables.impact_face_diameter, o.cost});
      progress("Taylor bar", o.cost,
               "L " + mm(o.observables.final_length) + " mm, D " + mm(o.observables.impact_face_diameter) + " mm");
      if (std::string(h) == "0.8467 mm") {
        const verification::ObservableRun half = verification::run_observables(
            file, h, {"output.vtu=false", "numerics.cfl=0.1"}, (runs / "taylor-bar-0.8467 mm-cfl0.1").string());
        progress("Taylor bar, CFL 0.1", half.cost,
                 "L " + mm(half.observables.final_length) + " mm, D " + mm(half.observables.impact_face_diameter) + " mm");
        cfl.push_back({"Taylor bar at 0.8467 mm: final length", o.observables.final_length, half.observables.final_length});
        cfl.push_back({"Taylor bar at 0.8467 mm: impact-face diameter", o.observables.impact_face_diameter,
                       half.observables.impact_face_diameter});
      }
    } catch (const std::exception& e) {
      ++r.failures;
      r.skipped.push_back({std::string("Taylor bar at ") + h, std::string("failed: ") + e.what()});
    }
  }
}

void plate(Report& r, const std::string& cases, const fs::path& runs, std::vector<Cfl>& cfl) {
  const std::string file = cases + "/plate-8mm/case.toml";
  const std::string v = "projectile.velocity=" + fmt("%.0f", kPlateSpeed) + " m/s";
  // Spacings that divide the 8 mm plate (a cylinder has round(L/h) layers; more would overlap the
  // projectile): 2 to 6 layers.
  for (const char* h : {"4 mm", "2 mm", "1.6 mm", "1.3333333 mm"}) {
    try {
      const verification::ObservableRun o = verification::run_observables(
          file, h, {"output.vtu=false", v}, (runs / ("plate-8mm-" + std::string(h))).string());
      r.observables.push_back({"8 mm plate at 298 m/s: residual velocity", o.cost.spacing, o.observables.residual_velocity, o.cost});
      progress("8 mm plate, 298 m/s", o.cost, "v_r " + fmt("%.2f m/s", o.observables.residual_velocity) +
                                                  (o.observables.settled_time < 0 ? " (not settled)" : ""));
      if (std::string(h) == "2 mm") {
        const verification::ObservableRun half = verification::run_observables(
            file, h, {"output.vtu=false", v, "numerics.cfl=0.1"}, (runs / "plate-8mm-2 mm-cfl0.1").string());
        progress("8 mm plate, CFL 0.1", half.cost, "v_r " + fmt("%.2f m/s", half.observables.residual_velocity));
        cfl.push_back({"8 mm plate at 2 mm, 298 m/s: residual velocity", o.observables.residual_velocity,
                       half.observables.residual_velocity});
      }
    } catch (const std::exception& e) {
      ++r.failures;
      r.skipped.push_back({std::string("8 mm plate at ") + h, std::string("failed: ") + e.what()});
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// Plots

const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

std::string header(const fs::path& png, const std::string& title, const std::string& xlabel, const std::string& ylabel) {
  std::ostringstream g;
  g << "# Drawn by impactsph verify; to redraw, run gnuplot on this file from the folder verify ran in (the\n"
    << "# output path below is relative to it).\n"
    << "set terminal pngcairo size 1000,750 enhanced font 'Sans,11'\n"
    << "set output " << gp_quote(png.string()) << "\n"
    << "set title " << gp_quote(title) << " noenhanced\n"
    << "set xlabel " << gp_quote(xlabel) << "\nset ylabel " << gp_quote(ylabel) << "\n"
    << "set grid\nset key below left Left reverse noenhanced\n";
  return g.str();
}

// Error against spacing in log-log, each series with its fitted power law.
std::string convergence_script(const Report& r, const fs::path& png) {
  std::ostringstream g;
  g << header(png, "Convergence against the closed forms (|relative error| against spacing)", "spacing h [mm]",
              "|relative error|")
    << "set logscale xy\nset format y '10^{%L}'\n";
  std::vector<std::string> plots;
  int k = 0;
  for (const std::string& s : series_names(r.errors)) {
    const std::vector<Point> pts = of_series(r.errors, s);
    std::ostringstream d;
    for (const Point& p : pts)
      if (p.value != 0) d << gp_number(p.spacing * 1e3) << " " << gp_number(std::abs(p.value)) << "\n";
    const std::string block = "$s" + std::to_string(k);
    g << block << " << EOD\n" << d.str() << "EOD\n";
    const std::string colour = kColours[k % 8];
    const Order o = fit_order(pts);
    plots.push_back(block + " u 1:2 w p pt " + std::to_string(5 + 2 * (k % 4)) + " ps 1.4 lc rgb '" + colour + "' t " +
                    gp_quote(s + (o.ok ? ": order " + fmt("%.2f", o.p) : "")));
    if (o.ok)
      plots.push_back("exp(" + gp_number(o.log_c) + ")*x**(" + gp_number(o.p) + ") w l lw 1.5 dt 2 lc rgb '" + colour +
                      "' notitle");
    ++k;
  }
  g << "plot ";
  for (std::size_t i = 0; i < plots.size(); ++i) g << (i ? ", \\\n     " : "") << plots[i];
  g << "\nunset output\n";
  return g.str();
}

// Wall time against error: what an answer of a given accuracy costs (one point per spacing; backend
// reference, precision double, the only pair in this build).
std::string speed_script(const Report& r, const fs::path& png, int threads) {
  std::ostringstream g;
  g << header(png, "Speed against error: reference solver, double, " + std::to_string(threads) + " thread(s)",
              "|relative error|", "wall time [s]")
    << "set logscale xy\nset format x '10^{%L}'\n";
  std::vector<std::string> plots;
  int k = 0;
  for (const std::string& s : series_names(r.errors)) {
    std::ostringstream d;
    for (const Point& p : of_series(r.errors, s))
      if (p.value != 0 && p.cost.wall_s > 0) d << gp_number(std::abs(p.value)) << " " << gp_number(p.cost.wall_s) << "\n";
    const std::string block = "$w" + std::to_string(k);
    g << block << " << EOD\n" << d.str() << "EOD\n";
    plots.push_back(block + " u 1:2 w lp pt " + std::to_string(5 + 2 * (k % 4)) + " ps 1.4 lc rgb '" + kColours[k % 8] +
                    "' t " + gp_quote(s + " (reference, double)"));
    ++k;
  }
  g << "plot ";
  for (std::size_t i = 0; i < plots.size(); ++i) g << (i ? ", \\\n     " : "") << plots[i];
  g << "\nunset output\n";
  return g.str();
}

// Observables against spacing, in mm or m/s, with the experiment as a horizontal line.
std::string observable_script(const Report& r, const fs::path& png, const std::string& title,
                              const std::vector<std::pair<std::string, double>>& series, double scale,
                              const std::string& ylabel) {
  std::ostringstream g;
  g << header(png, title, "spacing h [mm]", ylabel) << "set xrange [0:*]\n";
  std::vector<std::string> plots;
  int k = 0;
  for (const auto& [name, experiment] : series) {
    std::ostringstream d;
    for (const Point& p : of_series(r.observables, name)) d << gp_number(p.spacing * 1e3) << " " << gp_number(p.value * scale) << "\n";
    const std::string block = "$o" + std::to_string(k);
    g << block << " << EOD\n" << d.str() << "EOD\n";
    const std::string colour = kColours[k % 8];
    plots.push_back(block + " u 1:2 w lp pt 7 ps 1.4 lc rgb '" + colour + "' t " + gp_quote(name + ", simulated"));
    plots.push_back(gp_number(experiment * scale) + " w l lw 2 dt 2 lc rgb '" + colour + "' t " +
                    gp_quote(name + ", experiment " + fmt("%.4g", experiment * scale)));
    ++k;
  }
  g << "plot ";
  for (std::size_t i = 0; i < plots.size(); ++i) g << (i ? ", \\\n     " : "") << plots[i];
  g << "\nunset output\n";
  return g.str();
}

// ---------------------------------------------------------------------------------------------------
// Report

std::string cost_cells(const RunCost& c) {
  return std::to_string(c.particles) + " | " + std::to_string(c.steps) + " | " + fmt("%.3g", c.particle_steps()) + " | " +
         fmt("%.2f", c.wall_s) + " | " + fmt("%.3g", c.wall_s > 0 ? c.particle_steps() / c.wall_s : 0.0);
}

void write_results_csv(const Report& r, const fs::path& file) {
  std::string csv = "kind,series,spacing_m,value,particles,steps,particle_steps,wall_s,backend,precision\n";
  auto rows = [&](const std::vector<Point>& pts, const char* kind) {
    for (const Point& p : pts)
      csv += std::string(kind) + ",\"" + p.series + "\"," + fmt("%.6g", p.spacing) + "," + fmt("%.8g", p.value) + "," +
             std::to_string(p.cost.particles) + "," + std::to_string(p.cost.steps) + "," + fmt("%.6g", p.cost.particle_steps()) +
             "," + fmt("%.4f", p.cost.wall_s) + ",reference,double\n";
  };
  rows(r.errors, "relative_error");
  rows(r.observables, "observable_SI");
  write_text_atomic(file, csv);
}

}  // namespace

int verify_command(const VerifyOptions& opt) {
  if (opt.suite != "fast" && opt.suite != "full" && opt.suite != "smoke")
    throw std::runtime_error("--suite " + opt.suite + ": valid suites are fast (elastic wave, Hugoniot), full (+ "
                             "Taylor bar, 8 mm plate, CFL sensitivity) and smoke (the elastic wave at 3 coarse "
                             "spacings: CI's check of the command)");
  const std::string cases = opt.cases.empty() ? std::string(IMPACTSPH_CASES) : opt.cases;
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
  std::vector<Cfl> cfl;
  const bool smoke = opt.suite == "smoke";
  elastic_wave(r, cases, full, smoke);
  if (smoke) {
    r.skipped.push_back({"elastic wave at 0.5 and 0.4 mm, Hugoniot", "smoke suite: only what CI can afford"});
  } else {
    hugoniot(r, cases, 500);
    hugoniot(r, cases, 1000);
  }
  if (full) {
    taylor_bar(r, cases, out / "runs", cfl);
    plate(r, cases, out / "runs", cfl);
  } else {
    r.skipped.push_back({"elastic wave at 0.4 mm", "full suite only (--suite full): 16e6 particle-steps"});
    r.skipped.push_back({"Taylor bar over spacing (1.27-0.508 mm)", "full suite only (--suite full)"});
    r.skipped.push_back({"8 mm plate residual velocity over spacing (4-1.33 mm)", "full suite only (--suite full)"});
    r.skipped.push_back({"CFL sensitivity (Taylor bar, 8 mm plate)", "full suite only (--suite full)"});
  }
  r.skipped.push_back({"backend gpu, precision float",
                       "this build has the reference solver only (double, OpenMP); the CUDA port and `run --backend/"
                       "--precision` come from another branch"});
  const double total_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // Plots
  std::vector<std::string> plot_errors;
  auto draw = [&](const std::string& stem, const std::function<std::string(const fs::path&)>& script) {
    const std::string e = draw_gnuplot(out / (stem + ".png"), out / (stem + ".gp"), script);
    if (!e.empty()) plot_errors.push_back(e);
  };
  draw("convergence", [&](const fs::path& png) { return convergence_script(r, png); });
  draw("speed_vs_error", [&](const fs::path& png) { return speed_script(r, png, threads); });
  if (full) {
    draw("taylor_bar", [&](const fs::path& png) {
      return observable_script(r, png, "Taylor bar (OFHC copper, 190 m/s): final shape against spacing",
                               {{"Taylor bar: final length", kTaylorLength}, {"Taylor bar: impact-face diameter", kTaylorDiameter}},
                               1e3, "[mm]");
    });
    draw("plate_8mm", [&](const fs::path& png) {
      return observable_script(r, png, "8 mm Weldox 460 E plate at 298 m/s: residual velocity against spacing",
                               {{"8 mm plate at 298 m/s: residual velocity", recht_ipson(kPlateCurve, kPlateSpeed)}}, 1.0,
                               "residual velocity [m/s]");
    });
  }
  write_results_csv(r, out / "results.csv");

  // report.md
  std::ostringstream md;
  md << "# Verification report (" << opt.suite << " suite)\n\n"
     << "Written by `";
  for (std::size_t k = 0; k < opt.command_line.size(); ++k) md << (k ? " " : "") << opt.command_line[k];
  md << "`.\n\n"
     << "| | |\n|---|---|\n"
     << "| date | " << started << " |\n"
     << "| git commit (at the start) | " << commit << " |\n"
     << "| CPU | " << cpu_model() << ", " << omp_get_num_procs() << " cores |\n"
     << "| threads per run | " << threads << " (runs one after another) |\n"
     << "| load average (1, 5, 15 min) | " << load_before << " at the start, " << load_average() << " at the end |\n"
     << "| wall time of the suite | " << fmt("%.1f", total_wall) << " s (" << fmt("%.1f", total_wall / 60) << " min) |\n"
     << "| solver | reference (double, OpenMP) |\n\n"
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
  md << "\n| series | spacing [mm] | relative error | particles | steps | particle-steps | wall [s] | particle-steps/s |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const Point& p : r.errors)
    md << "| " << p.series << " | " << mm(p.spacing) << " | " << fmt("%+.3e", p.value) << " | " << cost_cells(p.cost) << " |\n";
  md << "\n## Speed against error\n\nOne point per spacing; backend reference, precision double (the only pair in "
        "this build).\n\n![wall time against error](speed_vs_error.png)\n\n";

  if (full) {
    md << "## Validation observables against spacing\n\n"
       << "Taylor bar: experiment final length " << mm(kTaylorLength) << " mm, impact-face diameter "
       << mm(kTaylorDiameter) << " mm (shared/data/validation.md). 8 mm plate at 298 m/s: the experiments' "
          "Recht-Ipson curve (p = 2, a = 0.909, v_bl = 152.5 m/s) gives "
       << fmt("%.1f", recht_ipson(kPlateCurve, kPlateSpeed)) << " m/s (cases/plate-8mm/README.md).\n\n"
       << "![Taylor bar](taylor_bar.png)\n\n![8 mm plate](plate_8mm.png)\n\n"
       << "| observable | spacing [mm] | value | against experiment | particles | steps | particle-steps | wall [s] | "
          "particle-steps/s |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const Point& p : r.observables) {
      const bool speed = p.series.find("velocity") != std::string::npos;
      const double exp = speed ? recht_ipson(kPlateCurve, kPlateSpeed)
                               : (p.series.find("length") != std::string::npos ? kTaylorLength : kTaylorDiameter);
      md << "| " << p.series << " | " << mm(p.spacing) << " | "
         << (speed ? fmt("%.2f m/s", p.value) : fmt("%.3f mm", p.value * 1e3)) << " | " << fmt("%+.1f %%", 100 * (p.value / exp - 1))
         << " | " << cost_cells(p.cost) << " |\n";
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
