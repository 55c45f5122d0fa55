// impactsph ballistic-limit (docs/ballistic-limit.md): bracket the ballistic limit by running the case
// at several impact speeds at once, fit the Recht-Ipson curve, write CSV/JSON and a gnuplot PNG.
#include "app/ballistic_limit.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "app/gnuplot.hpp"
#include "app/picture.hpp"
#include "app/run_args.hpp"
#include "common/scoped_signals.hpp"
#include "app/solver_choice.hpp"
#include "common/case_file.hpp"
#include "common/checkpoint.hpp"
#include "common/driver.hpp"
#include "common/errors.hpp"
#include "common/mesh_solid.hpp"
#include "common/output.hpp"
#include "common/scene.hpp"
#include "common/units.hpp"

namespace fs = std::filesystem;

namespace impactsph {

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------------
// Formatting

// Impact speeds are run and named to 0.01 m/s, so a folder name, a CSV row and the run agree exactly.
double round_speed(double v) { return std::round(v * 100.0) / 100.0; }

// "298", "233.33", "416.7": the shortest form of a speed rounded to 0.01 m/s.
std::string speed_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", round_speed(v));
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

double parse_speed(const char* option, const std::string& text) {
  try {
    return parse_quantity(text, Dimension::Velocity);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string(option) + " " + text + ": " + e.what());
  }
}

// ---------------------------------------------------------------------------------------------------
// Ctrl-C: the first stops the search after the runs in flight; the second stops those too (each writes
// its checkpoint, so running the same command again continues them); a third kills the process.

std::atomic<int> g_signals{0};
std::atomic<bool> g_abort_runs{false};
extern "C" void on_search_stop(int sig) {
  const int n = g_signals.fetch_add(1) + 1;
  if (n == 2) g_abort_runs.store(true);
  if (n >= 3) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
  }
}

bool stop_requested() { return g_signals.load() != 0; }

// ---------------------------------------------------------------------------------------------------
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

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

// Lines starting with '#' and blank lines are skipped; the first other line is the header.
Reference read_reference(const fs::path& file) {
  Reference ref;
  ref.file = file;
  std::ifstream in(file);
  if (!in) return ref;
  auto fail = [&](int line, const std::string& what) {
    throw std::runtime_error(file.string() + ":" + std::to_string(line) + ": " + what);
  };
  int line_no = 0, iv = -1, ir = -1, is = -1;
  bool header = false;
  std::string line;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> f = split_csv(t);
    if (!header) {
      for (int k = 0; k < static_cast<int>(f.size()); ++k) {
        if (f[k] == "v_impact_m_s") iv = k;
        if (f[k] == "v_residual_m_s") ir = k;
        if (f[k] == "source") is = k;
      }
      if (iv < 0 || ir < 0 || is < 0)
        fail(line_no, "the header must name the columns v_impact_m_s,v_residual_m_s,source (got '" + t + "')");
      header = true;
      continue;
    }
    if (static_cast<int>(f.size()) <= std::max({iv, ir, is}))
      fail(line_no, "expected 3 columns v_impact_m_s,v_residual_m_s,source, got '" + t + "'");
    auto number = [&](int k, const char* column) {
      char* end = nullptr;
      const double v = std::strtod(f[k].c_str(), &end);
      if (f[k].empty() || *end != '\0' || !std::isfinite(v) || v < 0)
        fail(line_no, std::string(column) + " '" + f[k] + "' is not a speed in m/s (a number >= 0)");
      return v;
    };
    ReferencePoint p;
    p.v_impact = number(iv, "v_impact_m_s");
    p.v_residual = number(ir, "v_residual_m_s");
    p.source = f[is].empty() ? "reference" : f[is];
    if (std::find(ref.sources.begin(), ref.sources.end(), p.source) == ref.sources.end()) ref.sources.push_back(p.source);
    ref.points.push_back(p);
  }
  return ref;
}

// ---------------------------------------------------------------------------------------------------
// The p = 2 Recht-Ipson form of a rigid blunt projectile that pushes out a plug of its own diameter:
// a = m_p / (m_p + m_plug), from the nominal geometry (the lattice under-fills round bodies).

struct PlugForm {
  bool ok = false;
  double m_p = 0, m_plug = 0;  // kg, whole bodies
  std::string why;             // when not ok
  double a() const { return m_p / (m_p + m_plug); }
};

PlugForm plug_form(const CaseSpec& spec) {
  PlugForm f;
  const BodySpec& pb = spec.bodies[static_cast<std::size_t>(spec.observables.projectile_index)];
  const BodySpec& tb = spec.bodies[static_cast<std::size_t>(spec.observables.target_index)];
  const double speed = norm(pb.velocity);
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(pb.velocity[k]) > std::abs(pb.velocity[axis])) axis = k;
  if (!(speed > 0) || std::abs(pb.velocity[axis]) < 0.999 * speed) {
    f.why = "the impact is not along a coordinate axis";
    return f;
  }
  // Cross-section normal to the impact axis and extent along it; false when the body lies sideways.
  auto section = [&](const BodySpec& b, double& area, double& length) {
    if (b.shape == Shape::Sphere) {
      // The projectile's cross-section, and the length that gives its volume (4/3 r): the plug of a
      // sphere is the cylinder of its cross-section through the plate.
      area = kPi * b.radius * b.radius;
      length = 4.0 / 3.0 * b.radius;
      return true;
    }
    if (b.shape == Shape::Cylinder) {
      if (b.axis != axis) return false;
      area = kPi * b.radius * b.radius;
      length = shape_volume(b) / area;  // a nose counts by its volume
      return true;
    }
    if (b.shape == Shape::Mesh) {
      // The extent along the impact axis, and the mean cross-section that gives the mesh's volume.
      length = b.mesh->upper()[axis] - b.mesh->lower()[axis];
      area = shape_volume(b) / length;
      return true;
    }
    area = 1;
    for (int k = 0; k < 3; ++k)
      if (k != axis) area *= b.box_max[k] - b.box_min[k];
    length = b.box_max[axis] - b.box_min[axis];
    return true;
  };
  if (tb.shape == Shape::Sphere) {
    f.why = "the target is a sphere (no plate thickness)";
    return f;
  }
  double area_p, length_p, area_t, thickness;
  if (!section(pb, area_p, length_p) || !section(tb, area_t, thickness)) {
    f.why = "a cylinder's axis is not the impact direction";
    return f;
  }
  f.m_p = spec.materials[static_cast<std::size_t>(pb.material_index)].params.eos.rho0 * area_p * length_p;
  f.m_plug = spec.materials[static_cast<std::size_t>(tb.material_index)].params.eos.rho0 * area_p * thickness;
  f.ok = f.m_p > 0 && f.m_plug > 0;
  if (!f.ok) f.why = "a body has no mass";
  return f;
}

// ---------------------------------------------------------------------------------------------------
// Runs

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

// The observables of a finished run of the search's solver with this fingerprint in `dir`, if
// summary.json holds one. `impactsph run` with the same case file, --spacing and --set values (and
// --backend, --precision) gives the same fingerprint and solver, so a run made by hand counts too.
bool read_finished_run(const Search& s, const fs::path& dir, const std::string& fingerprint, Run& r) {
  const nlohmann::json j = read_json_or_null(dir / "summary.json");
  if (!j.is_object() || j.value("fingerprint", "") != fingerprint || !j.value("completed", false) ||
      !solver_is(j.value("solver", ""), s.opt.backend, s.opt.precision) || !j.contains("observables"))
    return false;
  try {
    const nlohmann::json& o = j.at("observables");
    r.obs.projectile = r.obs.target = true;
    r.obs.residual_velocity = o.at("residual_velocity").get<double>();
    r.obs.residual_mass = o.at("residual_mass").get<double>();
    r.obs.plug_velocity = o.at("plug_velocity").get<double>();
    r.obs.plug_mass = o.at("plug_mass").get<double>();
    r.obs.perforated = o.at("perforated").get<bool>();
    const nlohmann::json& settled = o.at("settled_time");  // null: not settled by time.end
    r.obs.settled_time = settled.is_null() ? -1.0 : settled.get<double>();
    r.wall = j.value("wall_time_s", 0.0);
  } catch (const std::exception&) {
    return false;  // written by another version: run it again
  }
  return true;
}

// A checkpoint in `dir` that a run of these inputs on the search's solver wrote (run.json, which the
// search's runs write as `impactsph run` does, says the backend and precision).
bool has_checkpoint_of(const Search& s, const fs::path& dir, const std::string& fingerprint) {
  if (!fs::exists(checkpoint_path(dir))) return false;
  const nlohmann::json run = read_json_or_null(dir / "run.json");
  if (!run.is_object() || run.value("backend", "reference") != s.opt.backend ||
      run.value("precision", "double") != s.opt.precision)
    return false;
  try {
    return read_checkpoint(checkpoint_path(dir)).fingerprint == fingerprint;
  } catch (const std::exception&) {
    return false;  // damaged or of another format: start afresh
  }
}

Run run_one(const Search& s, double v, int threads) {
  Run r;
  r.v = v;
  r.dir = s.out / ("v_" + speed_text(v));
  std::vector<std::string> sets = s.opt.sets;
  sets.push_back(s.projectile + ".velocity=" + speed_text(v) + " m/s");
  const std::string fingerprint = run_fingerprint(s.opt.case_file, s.opt.spacing, sets);
  if (read_finished_run(s, r.dir, fingerprint, r)) {
    r.origin = Origin::Reused;
    r.done = true;
    return r;
  }
  // The OpenMP thread count is a per-thread setting: each concurrent run takes its share of the cores.
  omp_set_num_threads(threads);
  const auto t0 = std::chrono::steady_clock::now();
  try {
    CaseSpec spec = load_case_file(s.opt.case_file, sets, s.opt.spacing);
    Scene scene = build_scene(spec);
    const std::unique_ptr<Stepper> solver = make_stepper(scene, s.opt.backend, s.opt.precision);
    RunOptions ro;
    ro.out_dir = r.dir;
    ro.quiet = true;
    ro.threads = threads;
    ro.fingerprint = fingerprint;
    ro.restart = has_checkpoint_of(s, r.dir, fingerprint);
    if (ro.restart) r.origin = Origin::Continued;
    ro.install_signal_handlers = false;  // process-wide; the search handles Ctrl-C (ScopedSignals below)
    ro.stop = &g_abort_runs;
    // summary.json records the single run this stands for.
    ro.command_line = {"impactsph", "run", s.opt.case_file};
    if (!s.opt.spacing.empty()) ro.command_line.insert(ro.command_line.end(), {"--spacing", s.opt.spacing});
    for (const std::string& x : sets) ro.command_line.insert(ro.command_line.end(), {"--set", x});
    if (s.opt.backend != "reference" || s.opt.precision != "double")
      ro.command_line.insert(ro.command_line.end(), {"--backend", s.opt.backend, "--precision", s.opt.precision});
    ro.command_line.insert(ro.command_line.end(), {"--out", r.dir.string()});
    if (!ro.restart) {
      // The inputs, as `impactsph run` writes them, so that `impactsph run --restart DIR` continues it too.
      fs::create_directories(r.dir);
      const nlohmann::json inputs{{"case_file", fs::absolute(s.opt.case_file).string()}, {"spacing", s.opt.spacing},
                                  {"set", sets}, {"threads", threads}, {"backend", s.opt.backend},
                                  {"precision", s.opt.precision}};
      write_text_atomic(r.dir / "run.json", inputs.dump(2) + "\n");
    }
    const RunResult res = run_simulation(scene, *solver, ro);
    // The picture's data and script; the report draws those of its key runs, one after another.
    if (!res.interrupted && spec.output.picture) {
      try {
        write_picture_files(r.dir, "picture", scene, scene.particles, res.clock.time, spec.output.picture_field);
      } catch (const std::exception& e) {
        r.picture_error = e.what();
      }
    }
    r.obs = res.observables;
    r.done = !res.interrupted;
    r.wall = res.wall_seconds;  // as summary.json records it, with the time of the run it continues
    return r;
  } catch (const DivergenceError& e) {
    r.failed = r.diverged = true;
    r.error = e.what();
  } catch (const std::exception& e) {
    r.failed = true;
    r.error = e.what();
  }
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

void print_run(Search& s, const Run& r) {
  if (s.opt.quiet) return;
  std::lock_guard<std::mutex> lock(s.print_mutex);
  if (r.failed) {
    const std::string first_line = r.error.substr(0, r.error.find('\n'));
    std::printf("  %9s m/s  %s: %s\n", speed_text(r.v).c_str(), r.diverged ? "diverged" : "failed", first_line.c_str());
  } else {
    const char* origin = r.origin == Origin::Reused ? "  (finished earlier in this folder)"
                         : r.origin == Origin::Continued ? "  (continued from its checkpoint)" : "";
    if (!r.done)
      std::printf("  %9s m/s  stopped; its checkpoint is in %s\n", speed_text(r.v).c_str(), r.dir.string().c_str());
    else
      std::printf("  %9s m/s  %-10s  %9.1f m/s  %7.1f s%s%s\n", speed_text(r.v).c_str(), r.obs.perforated ? "yes" : "no",
                  r.obs.residual_velocity, r.wall, r.obs.settled_time < 0 ? "  (not settled by time.end)" : "", origin);
  }
  std::fflush(stdout);
}

// Runs the speeds `vs`, up to s.jobs at once, each on its own std::thread. After Ctrl-C no further run
// starts and the ones in flight finish. Returns the runs that were started, in the order of `vs`.
std::vector<Run> run_batch(Search& s, const std::vector<double>& vs) {
  const int concurrent = std::max(1, std::min(s.jobs, static_cast<int>(vs.size())));
  const int threads = std::max(1, s.cores / concurrent);
  std::vector<Run> results(vs.size());
  std::vector<char> started(vs.size(), 0);
  std::atomic<std::size_t> next{0};
  std::mutex m;
  std::condition_variable cv;
  int alive = concurrent;
  auto worker = [&] {
    while (!stop_requested()) {
      const std::size_t i = next++;
      if (i >= vs.size()) break;
      started[i] = 1;
      results[i] = run_one(s, vs[i], threads);
      print_run(s, results[i]);
    }
    std::lock_guard<std::mutex> lock(m);
    --alive;
    cv.notify_all();
  };
  std::vector<std::thread> pool;
  for (int k = 0; k < concurrent; ++k) pool.emplace_back(worker);
  bool announced = false;
  {
    std::unique_lock<std::mutex> lock(m);
    while (alive > 0) {
      cv.wait_for(lock, std::chrono::milliseconds(200));
      if (stop_requested() && !announced) {
        announced = true;
        std::lock_guard<std::mutex> print_lock(s.print_mutex);
        std::fprintf(stderr, "\nstopping: no new runs; waiting for the runs in flight to finish (Ctrl-C again "
                             "stops them at their next step with a checkpoint; the same command continues them)\n");
      }
    }
  }
  for (std::thread& t : pool) t.join();
  std::vector<Run> out;
  for (std::size_t i = 0; i < vs.size(); ++i)
    if (started[i]) out.push_back(std::move(results[i]));
  return out;
}

// ---------------------------------------------------------------------------------------------------
// Results

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

std::vector<const Run*> sorted_done(const Search& s) {
  std::vector<const Run*> runs;
  for (const Run& r : s.runs)
    if (r.done) runs.push_back(&r);
  std::sort(runs.begin(), runs.end(), [](const Run* a, const Run* b) { return a->v < b->v; });
  return runs;
}

nlohmann::json fit_json(const RechtIpsonFit& f, bool v_bl_fixed) {
  if (!f.ok) return f.message.empty() ? nlohmann::json(nullptr) : nlohmann::json{{"error", f.message}};
  return {{"a", f.curve.a},           {"p", f.curve.p},       {"v_bl_m_s", f.curve.v_bl},
          {"v_bl_fixed", v_bl_fixed}, {"rms_m_s", f.rms},     {"points", f.points}};
}

void write_results(const Search& s, const Outcome& o) {
  std::string csv = "v_impact_m_s,perforated,residual_velocity_m_s,plug_velocity_m_s,plug_mass_kg,settled_time_s,wall_s\n";
  for (const Run* r : sorted_done(s)) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s,%d,%.6g,%.6g,%.6g,", speed_text(r->v).c_str(), r->obs.perforated ? 1 : 0,
                  r->obs.residual_velocity, r->obs.plug_velocity, r->obs.plug_mass);
    csv += buf;
    if (r->obs.settled_time >= 0) {
      std::snprintf(buf, sizeof buf, "%.6g", r->obs.settled_time);
      csv += buf;
    }
    std::snprintf(buf, sizeof buf, ",%.3f\n", r->wall);
    csv += buf;
  }
  write_text_atomic(s.out / "ballistic.csv", csv);

  nlohmann::json j;
  j["case"] = s.spec.name;
  j["case_file"] = report_path(s.opt.case_file);
  j["spacing_m"] = s.spec.numerics.spacing;
  j["set"] = s.opt.sets;
  j["command_line"] = report_arguments(s.opt.command_line);
  j["from_m_s"] = s.v_from;
  j["to_m_s"] = s.v_to;
  j["tolerance_m_s"] = s.tolerance;
  j["jobs"] = s.jobs;
  j["backend"] = s.opt.backend;
  j["precision"] = s.opt.precision;
  j["status"] = o.status;
  j["limit_m_s"] = o.bracketed ? nlohmann::json(o.limit()) : nlohmann::json(nullptr);
  j["bracket_m_s"] = o.bracketed ? nlohmann::json::array({o.lo, o.hi}) : nlohmann::json(nullptr);
  j["a"] = o.fit.ok ? nlohmann::json(o.fit.curve.a) : nlohmann::json(nullptr);
  j["p"] = o.fit.ok ? nlohmann::json(o.fit.curve.p) : nlohmann::json(nullptr);
  j["recht_ipson"] = fit_json(o.fit, true);
  j["recht_ipson_free"] = fit_json(o.fit_free, false);
  if (o.reference_curve) {
    j["reference"] = {{"file", o.reference->file.string()},
                      {"v_bl_m_s", o.reference_v_bl},
                      {"v_bl_from", o.reference_v_bl_from},
                      {"p", 2.0},
                      {"a", o.plug.a()},
                      {"projectile_mass_kg", o.plug.m_p},
                      {"plug_mass_kg", o.plug.m_plug},
                      {"rms_of_runs_m_s", o.reference_rms >= 0 ? nlohmann::json(o.reference_rms) : nlohmann::json(nullptr)}};
  }
  nlohmann::json runs = nlohmann::json::array();
  for (const Run& r : s.runs) {
    const char* origin = r.origin == Origin::Reused ? "reused" : r.origin == Origin::Continued ? "continued" : "ran";
    nlohmann::json x{{"v_impact_m_s", round_speed(r.v)}, {"dir", r.dir.string()}, {"wall_s", r.wall}, {"origin", origin}};
    if (r.failed) {
      x["error"] = r.error;
    } else if (!r.done) {
      x["error"] = "stopped before its end";
    } else {
      x["perforated"] = r.obs.perforated;
      x["residual_velocity_m_s"] = r.obs.residual_velocity;
      x["residual_mass_kg"] = r.obs.residual_mass;
      x["plug_velocity_m_s"] = r.obs.plug_velocity;
      x["plug_mass_kg"] = r.obs.plug_mass;
      x["settled_time_s"] = r.obs.settled_time >= 0 ? nlohmann::json(r.obs.settled_time) : nlohmann::json(nullptr);
    }
    runs.push_back(x);
  }
  j["runs"] = runs;
  write_text_atomic(s.out / "ballistic.json", j.dump(2) + "\n");
}

// ---------------------------------------------------------------------------------------------------
// The plot (gnuplot, pngcairo)

std::string plot_script(const Search& s, const Outcome& o, const fs::path& png) {
  const std::vector<const Run*> runs = sorted_done(s);
  std::vector<double> xs;
  double y_max = 10;
  for (const Run* r : runs) {
    xs.push_back(r->v);
    if (r->obs.perforated) y_max = std::max(y_max, r->obs.residual_velocity);
  }
  if (o.reference)
    for (const ReferencePoint& p : o.reference->points) {
      xs.push_back(p.v_impact);
      y_max = std::max(y_max, p.v_residual);
    }
  const double x_lo = *std::min_element(xs.begin(), xs.end()), x_hi = *std::max_element(xs.begin(), xs.end());
  const double pad = 0.06 * std::max(x_hi - x_lo, 0.2 * x_hi);
  const double x0 = std::max(0.0, x_lo - pad), x1 = x_hi + pad;
  if (o.fit.ok) y_max = std::max(y_max, recht_ipson(o.fit.curve, x1));
  if (o.fit_free.ok) y_max = std::max(y_max, recht_ipson(o.fit_free.curve, x1));
  if (o.reference_curve) y_max = std::max(y_max, recht_ipson({o.plug.a(), 2, o.reference_v_bl}, x1));
  y_max *= 1.1;

  std::ostringstream g;
  g << "# Drawn by impactsph ballistic-limit; run `gnuplot ballistic_curve.gp` in this folder to redraw.\n";
  g << "set terminal pngcairo size 900,600 enhanced font 'Sans,11'\n";
  g << "set output " << gp_quote(png.string()) << "\n";
  char title[256];
  std::snprintf(title, sizeof title, "%s: ballistic limit %.1f m/s (spacing %s, %zu runs)", s.spec.name.c_str(),
                o.limit(), format_quantity(s.spec.numerics.spacing, Dimension::Length).c_str(), runs.size());
  g << "set title " << gp_quote(title) << " noenhanced\n";
  g << "set xlabel 'impact velocity v_i [m/s]'\nset ylabel 'residual velocity v_r [m/s]'\n";
  g << "set grid\nset key top left Left reverse box opaque\nset xzeroaxis lt -1\nset samples 1000\n";
  g << "set xrange [" << gp_number(x0) << ":" << gp_number(x1) << "]\n";
  g << "set yrange [" << gp_number(-0.04 * y_max) << ":" << gp_number(y_max) << "]\n";
  // The final bracket, shaded, and the estimate as a dashed line labelled on its left, where v_r = 0 and
  // no curve runs.
  g << "set object 1 rect from " << gp_number(o.lo) << ", graph 0 to " << gp_number(o.hi)
    << ", graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind\n";
  g << "set arrow 1 from " << gp_number(o.limit()) << ", graph 0 to " << gp_number(o.limit())
    << ", graph 1 nohead dt 2 lc rgb '#555555'\n";
  g << "set label 1 " << gp_quote("v_{bl} = " + fixed(o.limit(), 1) + " m/s") << " at " << gp_number(o.limit())
    << ", graph 0.12 offset -0.8,0 right textcolor rgb '#555555'\n";
  g << "ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0\n";

  std::ostringstream perf, stopped;
  for (const Run* r : runs) {
    if (r->obs.perforated) perf << gp_number(r->v) << " " << gp_number(r->obs.residual_velocity) << "\n";
    else stopped << gp_number(r->v) << "\n";
  }
  std::vector<std::string> plots;
  if (o.fit.ok) {
    const RechtIpson& c = o.fit.curve;
    g << "a1 = " << gp_number(c.a) << "; p1 = " << gp_number(c.p) << "; v1 = " << gp_number(c.v_bl) << "\n";
    plots.push_back("ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t " +
                    gp_quote("Recht-Ipson fit: a = " + fixed(c.a, 3) + ", p = " + fixed(c.p, 2) + ", v_{bl} = " +
                             fixed(c.v_bl, 1) + " m/s (fixed)"));
  }
  if (o.fit_free.ok) {
    const RechtIpson& c = o.fit_free.curve;
    g << "a2 = " << gp_number(c.a) << "; p2 = " << gp_number(c.p) << "; v2 = " << gp_number(c.v_bl) << "\n";
    plots.push_back("ri(x, a2, p2, v2) w l lw 1.5 dt 2 lc rgb '#ff7f0e' t " +
                    gp_quote("Recht-Ipson fit, all free: a = " + fixed(c.a, 3) + ", p = " + fixed(c.p, 2) +
                             ", v_{bl} = " + fixed(c.v_bl, 1) + " m/s"));
  }
  if (o.reference_curve) {
    g << "a3 = " << gp_number(o.plug.a()) << "; v3 = " << gp_number(o.reference_v_bl) << "\n";
    plots.push_back("ri(x, a3, 2, v3) w l lw 1.5 dt 3 lc rgb '#2ca02c' t " +
                    gp_quote("reference: p = 2, a = m_p/(m_p+m_{plug}) = " + fixed(o.plug.a(), 3) + ", v_{bl} = " +
                             fixed(o.reference_v_bl, 1) + " m/s"));
  }
  if (!perf.str().empty()) {
    g << "$perforated << EOD\n" << perf.str() << "EOD\n";
    plots.push_back("$perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated'");
  }
  if (!stopped.str().empty()) {
    g << "$stopped << EOD\n" << stopped.str() << "EOD\n";
    plots.push_back("$stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated'");
  }
  if (o.reference) {
    // One marker per source: experiments as black triangles, other simulations as open shapes.
    const char* styles[] = {"pt 4 ps 1.6 lw 2 lc rgb '#9467bd'", "pt 12 ps 1.8 lw 2 lc rgb '#8c564b'",
                            "pt 8 ps 1.6 lw 2 lc rgb '#e377c2'"};
    int other = 0;
    for (std::size_t k = 0; k < o.reference->sources.size(); ++k) {
      const std::string& src = o.reference->sources[k];
      std::ostringstream d;
      for (const ReferencePoint& p : o.reference->points)
        if (p.source == src) d << gp_number(p.v_impact) << " " << gp_number(p.v_residual) << "\n";
      const std::string block = "$reference" + std::to_string(k);
      g << block << " << EOD\n" << d.str() << "EOD\n";
      const std::string style = src == "experiment" ? "pt 9 ps 2 lc rgb 'black'" : styles[other++ % 3];
      plots.push_back(block + " u 1:2 w p " + style + " t " + gp_quote(src + " (reference.csv)") + " noenhanced");
    }
  }
  g << "plot ";
  for (std::size_t k = 0; k < plots.size(); ++k) g << (k ? ", \\\n     " : "") << plots[k];
  g << "\nunset output\n";
  return g.str();
}

// Writes DIR/ballistic_curve.gp and draws DIR/ballistic_curve.png with it. Returns an error message, or
// "" when the PNG is there.
std::string draw_plot(const Search& s, const Outcome& o) {
  return draw_gnuplot(s.out / "ballistic_curve.png", s.out / "ballistic_curve.gp",
                      [&](const fs::path& png) { return plot_script(s, o, png); });
}

// DIR/report.md: the figures of the search, its plot, its runs, and the pictures at the end of its key
// runs (the two that bracket the limit and the fastest), drawn here one after another.
void write_report(const Search& s, const Outcome& o, const std::string& plot_error) {
  auto num = [](const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return std::string(buf);
  };
  const std::vector<const Run*> runs = sorted_done(s);
  std::ostringstream md;
  md << "# Ballistic limit: " << s.spec.name << "\n\n"
     << "Written by `" << report_command(s.opt.command_line) << "`; the figures are also in ballistic.json and "
     << "ballistic.csv, each run in its folder v_SPEED/.\n\n"
     << "| | |\n|---|---|\n"
     << "| case | `" << report_path(s.opt.case_file) << "` at spacing "
     << format_quantity(s.spec.numerics.spacing, Dimension::Length) << " |\n"
     << "| status | " << o.status << " |\n";
  if (o.bracketed)
    md << "| bracket | not perforated at " << speed_text(o.lo) << " m/s, perforated at " << speed_text(o.hi)
       << " m/s (" << runs.size() << " runs) |\n"
       << "| ballistic limit | " << num("%.1f", o.limit()) << " m/s |\n";
  if (o.fit.ok)
    md << "| Recht-Ipson, v_bl fixed | a = " << num("%.4f", o.fit.curve.a) << ", p = " << num("%.3f", o.fit.curve.p)
       << ", rms residual " << num("%.2f", o.fit.rms) << " m/s over " << o.fit.points << " perforating runs |\n";
  if (o.fit_free.ok)
    md << "| Recht-Ipson, all free | a = " << num("%.4f", o.fit_free.curve.a) << ", p = "
       << num("%.3f", o.fit_free.curve.p) << ", v_bl = " << num("%.1f", o.fit_free.curve.v_bl) << " m/s"
       << (o.fit_free.message.empty() ? "" : " (" + o.fit_free.message + ")") << " |\n";
  if (o.reference_curve)
    md << "| reference | v_bl = " << num("%.1f", o.reference_v_bl) << " m/s (" << o.reference_v_bl_from
       << "), simulated limit " << num("%+.1f", 100 * (o.limit() - o.reference_v_bl) / o.reference_v_bl) << " % |\n";
  md << "\n"
     << (plot_error.empty() ? "![residual velocity against impact velocity](ballistic_curve.png)\n"
                            : "The plot was not drawn: " + plot_error + "\n")
     << "\n| impact velocity [m/s] | perforated | residual velocity [m/s] | plug mass [g] | plug velocity [m/s] | "
        "settled at [us] | wall [s] |\n|---|---|---|---|---|---|---|\n";
  for (const Run* r : runs)
    md << "| " << speed_text(r->v) << " | " << (r->obs.perforated ? "yes" : "no") << " | "
       << num("%.1f", r->obs.residual_velocity) << " | " << num("%.2f", r->obs.plug_mass * 1e3) << " | "
       << num("%.1f", r->obs.plug_velocity) << " | "
       << (r->obs.settled_time >= 0 ? num("%.1f", r->obs.settled_time * 1e6) : std::string("not settled")) << " | "
       << num("%.1f", r->wall) << " |\n";

  std::vector<std::pair<const Run*, std::string>> key;
  auto add_key = [&](const Run* r, const std::string& why) {
    if (!r) return;
    for (auto& k : key)
      if (k.first == r) {
        k.second += "; " + why;
        return;
      }
    key.emplace_back(r, why);
  };
  auto at = [&](double v) -> const Run* {
    for (const Run* r : runs)
      if (r->v == v) return r;
    return nullptr;
  };
  if (o.bracketed) {
    add_key(at(o.lo), "the fastest that did not perforate");
    add_key(at(o.hi), "the slowest that perforated");
  }
  if (!runs.empty()) add_key(runs.back(), "the fastest run");
  if (!key.empty() && s.spec.output.picture) {
    md << "\n## The key runs at their end\n\nA cut through the model coloured by "
       << picture_field_label(s.spec.output.picture_field)
       << " (docs/case-files.md, `[output]`); each run folder holds picture.gp and picture.dat to redraw it.\n";
    for (const auto& [r, why] : key) {
      const std::string name = r->dir.filename().string();
      const std::string error = r->picture_error.empty() ? draw_picture(r->dir, "picture") : r->picture_error;
      md << "\n### " << speed_text(r->v) << " m/s: " << why << "\n\n";
      if (error.empty())
        md << "![" << speed_text(r->v) << " m/s at its end](" << name << "/picture.png)\n";
      else
        md << "Not drawn: " << error << "\n";
    }
  }
  write_text_atomic(s.out / "report.md", md.str());
}

// ---------------------------------------------------------------------------------------------------
// Recht-Ipson fit with GSL. Parameters are fitted as logarithms (a, p and v_bl stay positive) and
// speeds are scaled by the largest impact speed (a and p do not change, the problem is well scaled).

struct FitData {
  const std::vector<double>* x;  // v_impact / scale
  const std::vector<double>* y;  // v_residual / scale
  RechtIpson fixed;              // scaled v_bl; the values of the parameters not fitted
  bool free[3];                  // a, p, v_bl
};

RechtIpson unpack(const gsl_vector* q, const FitData& d) {
  RechtIpson c = d.fixed;
  std::size_t k = 0;
  if (d.free[0]) c.a = std::exp(gsl_vector_get(q, k++));
  if (d.free[1]) c.p = std::exp(gsl_vector_get(q, k++));
  if (d.free[2]) c.v_bl = std::exp(gsl_vector_get(q, k++));
  return c;
}

// The model and its derivatives along a, p and v_bl at one point.
void model(const RechtIpson& c, double x, double& g, double deriv[3]) {
  const double xp = std::pow(x, c.p), bp = std::pow(c.v_bl, c.p), u = xp - bp;
  if (!(u > 1e-12 * xp)) {  // at or below the limit the curve is 0 and flat
    g = deriv[0] = deriv[1] = deriv[2] = 0;
    return;
  }
  const double r = std::pow(u, 1.0 / c.p);
  g = c.a * r;
  deriv[0] = r;
  deriv[1] = c.a * r * (-std::log(u) / (c.p * c.p) + (xp * std::log(x) - bp * std::log(c.v_bl)) / (c.p * u));
  deriv[2] = -c.a * r / u * std::pow(c.v_bl, c.p - 1);
}

int fit_f(const gsl_vector* q, void* data, gsl_vector* f) {
  const FitData& d = *static_cast<const FitData*>(data);
  const RechtIpson c = unpack(q, d);
  for (std::size_t i = 0; i < d.x->size(); ++i) {
    double g, deriv[3];
    model(c, (*d.x)[i], g, deriv);
    gsl_vector_set(f, i, g - (*d.y)[i]);
  }
  return GSL_SUCCESS;
}

int fit_df(const gsl_vector* q, void* data, gsl_matrix* J) {
  const FitData& d = *static_cast<const FitData*>(data);
  const RechtIpson c = unpack(q, d);
  const double value[3] = {c.a, c.p, c.v_bl};
  for (std::size_t i = 0; i < d.x->size(); ++i) {
    double g, deriv[3];
    model(c, (*d.x)[i], g, deriv);
    std::size_t k = 0;
    for (int j = 0; j < 3; ++j)
      if (d.free[j]) gsl_matrix_set(J, i, k++, deriv[j] * value[j]);  // d/d(log q) = q d/dq
  }
  return GSL_SUCCESS;
}

}  // namespace

double recht_ipson(const RechtIpson& c, double v) {
  if (!(v > c.v_bl)) return 0;
  return c.a * std::pow(std::pow(v, c.p) - std::pow(c.v_bl, c.p), 1.0 / c.p);
}

RechtIpsonFit fit_recht_ipson(const std::vector<double>& v_impact, const std::vector<double>& v_residual,
                              const RechtIpson& start, bool fit_a, bool fit_p, bool fit_v_bl) {
  RechtIpsonFit out;
  out.curve = start;
  out.points = static_cast<int>(v_impact.size());
  const std::size_t n = v_impact.size(), k = static_cast<std::size_t>(fit_a) + fit_p + fit_v_bl;
  if (n < k || k == 0) {
    out.message = "needs at least " + std::to_string(k) + " perforating runs, has " + std::to_string(n);
    return out;
  }
  if (!(start.a > 0 && start.p > 0 && start.v_bl > 0)) {
    out.message = "the start values must be positive";
    return out;
  }
  const double scale = *std::max_element(v_impact.begin(), v_impact.end());
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = v_impact[i] / scale;
    y[i] = v_residual[i] / scale;
  }
  FitData data{&x, &y, {start.a, start.p, start.v_bl / scale}, {fit_a, fit_p, fit_v_bl}};

  gsl_error_handler_t* old_handler = gsl_set_error_handler_off();  // report failures, do not abort
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  gsl_multifit_nlinear_workspace* w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, k);
  gsl_vector* q0 = gsl_vector_alloc(k);
  {
    std::size_t j = 0;
    if (fit_a) gsl_vector_set(q0, j++, std::log(data.fixed.a));
    if (fit_p) gsl_vector_set(q0, j++, std::log(data.fixed.p));
    if (fit_v_bl) gsl_vector_set(q0, j++, std::log(data.fixed.v_bl));
  }
  gsl_multifit_nlinear_fdf fdf;
  fdf.f = fit_f;
  fdf.df = fit_df;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = k;
  fdf.params = &data;
  int info = 0;
  int status = gsl_multifit_nlinear_init(q0, &fdf, w);
  if (status == GSL_SUCCESS) status = gsl_multifit_nlinear_driver(500, 1e-10, 1e-10, 0.0, nullptr, nullptr, &info, w);
  // "No progress" at an exact or flat minimum still leaves the best point found.
  if (status == GSL_SUCCESS || status == GSL_ENOPROG) {
    RechtIpson c = unpack(gsl_multifit_nlinear_position(w), data);
    c.v_bl *= scale;
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += std::pow(recht_ipson(c, v_impact[i]) - v_residual[i], 2);
    out.curve = c;
    out.rms = std::sqrt(sum / static_cast<double>(n));
    out.ok = std::isfinite(c.a) && std::isfinite(c.p) && std::isfinite(c.v_bl) && std::isfinite(out.rms);
    if (!out.ok) out.message = "the fit ran off to infinite parameters";
    else if (n == k) out.message = "exact: as many runs as parameters";
  } else {
    out.message = std::string("the fit did not converge (") + gsl_strerror(status) + ")";
  }
  gsl_vector_free(q0);
  gsl_multifit_nlinear_free(w);
  gsl_set_error_handler(old_handler);
  return out;
}

int ballistic_limit_command(const BallisticOptions& opt) {
  Search s;
  s.opt = opt;
  // Check everything before the first run: a search may take hours.
  s.v_from = round_speed(parse_speed("--from", opt.from));
  s.v_to = round_speed(parse_speed("--to", opt.to));
  s.tolerance = parse_speed("--tolerance", opt.tolerance);
  if (!(s.v_from > 0)) throw std::runtime_error("--from " + opt.from + ": the impact speed must be above 0 m/s");
  if (!(s.v_from < s.v_to))
    throw std::runtime_error("--from (" + speed_text(s.v_from) + " m/s) must be below --to (" + speed_text(s.v_to) +
                             " m/s): give a speed that does not perforate and one that does");
  if (!(s.tolerance >= 0.05))
    throw std::runtime_error("--tolerance " + opt.tolerance + ": must be at least 0.05 m/s (runs are set to 0.01 m/s)");
  s.spec = load_case_file(opt.case_file, opt.sets, opt.spacing);
  const ObservablesSpec& os = s.spec.observables;
  if (os.projectile_index < 0 || os.target_index < 0)
    throw CaseError(s.spec.source_file, 0, "observables",
                    "ballistic-limit needs [observables] projectile = \"...\" and target = \"...\" to tell "
                    "perforation (docs/case-files.md)");
  s.projectile = os.projectile;
  for (const std::string& set : opt.sets) {
    const std::string key = trim(set.substr(0, set.find('=')));
    if (key == s.projectile + ".velocity" || key == "bodies." + s.projectile + ".velocity")
      throw std::runtime_error("--set " + set + ": ballistic-limit sets the impact speed of '" + s.projectile +
                               "' itself (--from, --to); leave it out");
  }
  if (opt.backend != "reference" && opt.backend != "gpu")
    throw std::runtime_error("--backend " + opt.backend + ": expected reference or gpu");
  if (opt.precision != "double" && opt.precision != "float")
    throw std::runtime_error("--precision " + opt.precision + ": expected double or float");
  if (opt.backend == "reference" && opt.precision != "double")
    throw std::runtime_error("--precision " + opt.precision + ": the reference solver runs in double only (use --backend gpu)");
  const Reference reference = read_reference(fs::path(opt.case_file).parent_path() / "reference.csv");
  s.out = opt.out.empty() ? fs::path("runs") / (s.spec.name + "-ballistic") : fs::path(opt.out);
  fs::create_directories(s.out);
  s.cores = std::max(1, omp_get_num_procs());
  s.jobs = opt.jobs > 0 ? opt.jobs : s.cores;

  Outcome o;
  if (!reference.points.empty()) o.reference = &reference;
  if (!opt.quiet) {
    const double rounds = std::ceil(std::log(std::max(1.0, (s.v_to - s.v_from) / s.tolerance)) / std::log(s.jobs + 1.0));
    std::printf("ballistic-limit: %s at spacing %s, %s to %s m/s until the bracket is %s m/s wide\n",
                s.spec.name.c_str(), format_quantity(s.spec.numerics.spacing, Dimension::Length).c_str(),
                speed_text(s.v_from).c_str(), speed_text(s.v_to).c_str(), speed_text(s.tolerance).c_str());
    const std::string solver = opt.backend == "reference"
                                   ? "reference (double)"
                                   : "gpu port (" + opt.precision + "; the CUDA build on a device, else the host build)";
    std::printf("  solver: %s\n", solver.c_str());
    std::printf("  %d run%s at a time, %d thread%s each; the 2 ends, then about %.0f round%s of %d; results in %s\n",
                s.jobs, s.jobs > 1 ? "s" : "", std::max(1, s.cores / s.jobs), s.cores / s.jobs > 1 ? "s" : "", rounds,
                rounds == 1 ? "" : "s", s.jobs, s.out.string().c_str());
    std::printf("  %9s      %-10s  %13s  %9s\n", "v_impact", "perforated", "v_residual", "wall");
    std::fflush(stdout);
  }

  g_signals.store(0);
  g_abort_runs.store(false);
  const ScopedSignals signals(on_search_stop);
  auto add = [&](std::vector<Run> batch) {
    for (Run& r : batch) s.runs.push_back(std::move(r));
  };
  // A failed run ends the search: its speed would leave a hole in the bracket.
  auto report_failures = [&]() {
    bool any = false, diverged = false;
    for (const Run& r : s.runs)
      if (r.failed) {
        any = true;
        diverged |= r.diverged;
        std::fprintf(stderr, "error: the run at %s m/s %s: %s\n  its output is in %s\n", speed_text(r.v).c_str(),
                     r.diverged ? "diverged" : "failed", r.error.c_str(), r.dir.string().c_str());
      }
    if (any && diverged)
      std::fprintf(stderr, "Try a smaller numerics.cfl (--set numerics.cfl=0.1) or another --spacing.\n");
    return any;
  };
  auto finish_failed = [&](const char* status, int exit_status) {
    o.status = status;
    write_results(s, o);
    return exit_status;
  };

  // The two ends must straddle the limit.
  add(run_batch(s, {s.v_from, s.v_to}));
  if (report_failures()) return finish_failed("failed", 3);
  if (s.runs.size() < 2 || !s.runs[0].done || !s.runs[1].done) {
    o.status = "interrupted";
    write_results(s, o);
    std::printf("interrupted before both ends had run; results so far in %s\n", s.out.string().c_str());
    return 130;
  }
  const Run& low = s.runs[0];
  const Run& high = s.runs[1];
  const double end_us = s.spec.time.end * 1e6;
  if (low.obs.perforated || !high.obs.perforated) {
    // A run that had not settled by time.end may still change its verdict (near the limit a projectile
    // can be slowing to a stop in the hole at time.end): continuing it keeps every other run of the search.
    auto continue_hint = [&](const Run& r) {
      if (r.obs.settled_time >= 0) return std::string();
      char buf[640];
      std::snprintf(buf, sizeof buf,
                    " It had not settled by time.end = %.4g us, so its verdict may still change: continue it with "
                    "`impactsph run --restart %s --end %.4gus` and run this command again (it takes the longer run "
                    "from its folder).",
                    end_us, report_path(r.dir).c_str(), 1.5 * end_us);
      return std::string(buf);
    };
    if (low.obs.perforated)
      std::fprintf(stderr,
                   "error: the low end is wrong: --from %s m/s already perforates '%s' (projectile residual velocity "
                   "%.1f m/s, plug %.1f m/s), so the ballistic limit is below it. Try a lower --from, e.g. --from "
                   "%s.%s\n",
                   speed_text(low.v).c_str(), os.target.c_str(), low.obs.residual_velocity, low.obs.plug_velocity,
                   speed_text(0.5 * low.v).c_str(), continue_hint(low).c_str());
    if (!high.obs.perforated)
      std::fprintf(stderr,
                   "error: the high end is wrong: --to %s m/s does not perforate '%s' by time.end = %.4g us "
                   "(projectile residual velocity %.1f m/s), so the limit is above it, or the plug had not left "
                   "yet. Try a higher --to, e.g. --to %s.%s\n",
                   speed_text(high.v).c_str(), os.target.c_str(), end_us, high.obs.residual_velocity,
                   speed_text(2 * high.v).c_str(), continue_hint(high).c_str());
    std::fprintf(stderr, "Both runs are in %s.\n", s.out.string().c_str());
    return finish_failed("bad-bracket", 4);
  }
  o.bracketed = true;
  o.lo = low.v;
  o.hi = high.v;
  write_results(s, o);

  // Split [lo, hi] into jobs + 1 parts, run the interior points at once, keep the part where the
  // verdict changes. Non-monotonic verdicts (a higher speed that stops) follow the lowest perforation.
  std::vector<std::string> inversions;
  while (o.hi - o.lo > s.tolerance && !stop_requested()) {
    std::vector<double> points;
    for (int k = 1; k <= s.jobs; ++k) {
      const double v = round_speed(o.lo + (o.hi - o.lo) * k / (s.jobs + 1));
      if (v > o.lo && v < o.hi && (points.empty() || v > points.back())) points.push_back(v);
    }
    if (points.empty()) break;
    std::vector<Run> batch = run_batch(s, points);
    std::vector<std::pair<double, bool>> verdicts{{o.lo, false}, {o.hi, true}};
    for (const Run& r : batch)
      if (r.done) verdicts.emplace_back(r.v, r.obs.perforated);
    add(std::move(batch));
    if (report_failures()) return finish_failed("failed", 3);
    std::sort(verdicts.begin(), verdicts.end());
    std::size_t first = 0;
    while (!verdicts[first].second) ++first;
    for (std::size_t i = first + 1; i < verdicts.size(); ++i)
      if (!verdicts[i].second)
        inversions.push_back(speed_text(verdicts[i].first) + " m/s did not perforate but " +
                             speed_text(verdicts[first].first) + " m/s did");
    o.lo = verdicts[first - 1].first;
    o.hi = verdicts[first].first;
    write_results(s, o);
  }
  const bool interrupted = stop_requested() && o.hi - o.lo > s.tolerance;

  // Fits to the perforating runs.
  std::vector<double> vi, vr;
  for (const Run* r : sorted_done(s))
    if (r->obs.perforated && r->obs.residual_velocity > 0) {
      vi.push_back(r->v);
      vr.push_back(r->obs.residual_velocity);
    }
  RechtIpson start{1.0, 2.0, o.limit()};
  if (!vi.empty()) {  // a from the p = 2 form through the median point
    std::vector<double> ratios;
    for (std::size_t i = 0; i < vi.size(); ++i)
      if (vi[i] > o.limit()) ratios.push_back(vr[i] / std::sqrt(vi[i] * vi[i] - o.limit() * o.limit()));
    if (!ratios.empty()) {
      std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
      start.a = ratios[ratios.size() / 2];
    }
  }
  o.fit = fit_recht_ipson(vi, vr, start, true, true, false);
  if (vi.size() >= 3) o.fit_free = fit_recht_ipson(vi, vr, o.fit.ok ? o.fit.curve : start, true, true, true);
  if (o.fit_free.ok && (o.fit_free.curve.v_bl < o.lo || o.fit_free.curve.v_bl > o.hi)) {
    // The runs themselves say where the limit is; a free v_bl outside that is the fit extrapolating.
    if (!o.fit_free.message.empty()) o.fit_free.message += "; ";
    o.fit_free.message += "its v_bl is outside the bracket, so the perforating runs do not pin it down";
  }

  // The reference p = 2 curve, with the reference's own limit: fitted to its perforating points with
  // a and p fixed, or else the highest speed it lists as stopped.
  std::string reference_note;
  if (o.reference) {
    o.plug = plug_form(s.spec);
    std::vector<const ReferencePoint*> pts;
    for (const ReferencePoint& p : reference.points)
      if (p.source == "experiment") pts.push_back(&p);
    o.reference_v_bl_from = "experiment";
    if (pts.empty()) {
      for (const ReferencePoint& p : reference.points) pts.push_back(&p);
      o.reference_v_bl_from = "all sources";
    }
    std::vector<double> rx, ry;
    double stopped_max = 0;
    for (const ReferencePoint* p : pts) {
      if (p->v_residual > 0) {
        rx.push_back(p->v_impact);
        ry.push_back(p->v_residual);
      } else {
        stopped_max = std::max(stopped_max, p->v_impact);
      }
    }
    if (!o.plug.ok) {
      reference_note = "reference: no p = 2 curve (" + o.plug.why + ")";
    } else if (!rx.empty()) {
      const double min_perf = *std::min_element(rx.begin(), rx.end());
      const double v0 = stopped_max > 0 && stopped_max < min_perf ? stopped_max : 0.9 * min_perf;
      const RechtIpsonFit f = fit_recht_ipson(rx, ry, {o.plug.a(), 2.0, v0}, false, false, true);
      if (f.ok) {
        o.reference_curve = true;
        o.reference_v_bl = f.curve.v_bl;
        o.reference_v_bl_from += " points, p = 2 fit";
      } else {
        reference_note = "reference: no p = 2 curve (" + f.message + ")";
      }
    } else if (stopped_max > 0) {
      o.reference_curve = true;
      o.reference_v_bl = stopped_max;
      o.reference_v_bl_from += " limit";
    }
    if (o.reference_curve && !vi.empty()) {
      double sum = 0;
      for (std::size_t i = 0; i < vi.size(); ++i)
        sum += std::pow(recht_ipson({o.plug.a(), 2.0, o.reference_v_bl}, vi[i]) - vr[i], 2);
      o.reference_rms = std::sqrt(sum / static_cast<double>(vi.size()));
    }
  }

  o.status = interrupted ? "interrupted" : "done";
  write_results(s, o);

  // The report.
  int unsettled = 0, done_runs = 0;
  for (const Run& r : s.runs)
    if (r.done) {
      ++done_runs;
      if (r.obs.settled_time < 0) ++unsettled;
    }
  if (interrupted)
    std::printf("interrupted: the bracket is still %s m/s wide (tolerance %s m/s)\n", speed_text(o.hi - o.lo).c_str(),
                speed_text(s.tolerance).c_str());
  std::printf("bracket: not perforated at %s m/s, perforated at %s m/s (%d runs)\n", speed_text(o.lo).c_str(),
              speed_text(o.hi).c_str(), done_runs);
  std::printf("ballistic limit: %.1f m/s\n", o.limit());
  if (o.fit.ok)
    std::printf("recht-ipson: a = %.4f, p = %.3f (v_bl fixed at %.1f m/s), rms residual %.2f m/s over %d perforating "
                "runs%s\n",
                o.fit.curve.a, o.fit.curve.p, o.fit.curve.v_bl, o.fit.rms, o.fit.points,
                o.fit.message.empty() ? "" : (" (" + o.fit.message + ")").c_str());
  else
    std::printf("recht-ipson: not fitted: %s\n", o.fit.message.c_str());
  if (o.fit_free.ok)
    std::printf("recht-ipson, all free: a = %.4f, p = %.3f, v_bl = %.1f m/s, rms residual %.2f m/s%s\n",
                o.fit_free.curve.a, o.fit_free.curve.p, o.fit_free.curve.v_bl, o.fit_free.rms,
                o.fit_free.message.empty() ? "" : (" (" + o.fit_free.message + ")").c_str());
  else if (vi.size() >= 3)
    std::printf("recht-ipson, all free: not fitted: %s\n", o.fit_free.message.c_str());
  if (o.reference_curve) {
    std::printf("reference: v_bl = %.1f m/s (%s of %s), simulated limit %+.1f%%\n", o.reference_v_bl,
                o.reference_v_bl_from.c_str(), reference.file.filename().string().c_str(),
                100 * (o.limit() - o.reference_v_bl) / o.reference_v_bl);
    std::printf("reference: p = 2, a = m_p/(m_p + m_plug) = %.1f g/(%.1f g + %.1f g) = %.4f", o.plug.m_p * 1e3,
                o.plug.m_p * 1e3, o.plug.m_plug * 1e3, o.plug.a());
    if (o.reference_rms >= 0) std::printf("; the perforating runs lie %.2f m/s rms from it", o.reference_rms);
    std::printf("\n");
  } else if (!reference_note.empty()) {
    std::printf("%s\n", reference_note.c_str());
  }
  for (const std::string& x : inversions)
    std::printf("warning: perforation is not monotonic in the speed: %s; the bracket follows the lowest "
                "perforation. A finer --spacing or a longer time.end may settle it.\n",
                x.c_str());
  if (unsettled > 0)
    std::printf("note: %d of %d runs ended at time.end = %.4g us before the residual velocity settled; their "
                "verdicts may change with a longer time.end\n",
                unsettled, done_runs, end_us);

  const std::string plot_error = draw_plot(s, o);
  write_report(s, o, plot_error);
  if (!plot_error.empty()) {
    std::fprintf(stderr, "error: %s\n", plot_error.c_str());
    return 1;
  }
  std::printf("results: %s (report.md, ballistic.csv, ballistic.json, ballistic_curve.png, v_*/)\n", s.out.string().c_str());
  return interrupted ? 130 : 0;
}

}  // namespace impactsph
