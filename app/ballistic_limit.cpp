// impactsph ballistic-limit (docs/ballistic-limit.md): bracket the ballistic limit by running the case
// at several impact speeds at once, fit the Recht-Ipson curve, write CSV/JSON and a gnuplot PNG. This file:
// the search and its runs; the reference, the outputs and the fit are in the files ballistic_search.hpp names.
#include "app/ballistic_limit.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "app/ballistic_search.hpp"
#include "app/picture.hpp"
#include "app/run_args.hpp"
#include "app/solver_choice.hpp"
#include "common/case_file.hpp"
#include "common/checkpoint.hpp"
#include "common/driver.hpp"
#include "common/errors.hpp"
#include "common/output.hpp"
#include "common/scene.hpp"
#include "common/scoped_signals.hpp"
#include "common/units.hpp"

namespace fs = std::filesystem;

namespace impactsph {

namespace ballistic {

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

}  // namespace ballistic

using namespace ballistic;

namespace {

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

}  // namespace

namespace ballistic {
namespace {

// The checks of every input, before the first run (a search may take hours), and the search they set up.
void prepare(const BallisticOptions& opt, Search& s) {
  s.opt = opt;
  s.v_from = round_speed(parse_speed("--from", opt.from));
  s.v_to = round_speed(parse_speed("--to", opt.to));
  s.tolerance = parse_speed("--tolerance", opt.tolerance);
  if (!(s.v_from > 0)) throw std::runtime_error("--from " + opt.from + ": the impact speed must be above 0 m/s");
  if (!(s.v_from < s.v_to))
    throw std::runtime_error("--from (" + speed_text(s.v_from) + " m/s) must be below --to (" + speed_text(s.v_to) +
                             " m/s): give a speed that does not perforate and one that does");
  if (!(s.tolerance >= 0.05))
    throw std::runtime_error("--tolerance " + opt.tolerance + ": must be at least 0.05 m/s (runs are set to 0.01 m/s)");
  if (opt.split != "thirds" && opt.split != "recht-ipson")
    throw std::runtime_error("--split " + opt.split + ": expected thirds (even splits) or recht-ipson (splits placed "
                             "at the limit the perforating runs' Recht-Ipson curve points to)");
  if (!(opt.coarse_margin >= 0 && opt.coarse_margin < 0.5))
    throw std::runtime_error("--coarse-margin " + std::to_string(opt.coarse_margin) +
                             ": expected a share of the coarse limit from 0 to 0.5, such as 0.05");
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
  check_solver_choice(opt.backend, opt.precision);
  if (!opt.coarse_spacing.empty()) {
    double coarse = 0;
    try {
      coarse = parse_quantity(opt.coarse_spacing, Dimension::Length);
    } catch (const std::exception& e) {
      throw std::runtime_error("--coarse " + opt.coarse_spacing + ": " + e.what());
    }
    if (!(coarse > s.spec.numerics.spacing))
      throw std::runtime_error("--coarse " + opt.coarse_spacing + ": the coarse search's spacing must be larger than "
                               "the search's own (" + format_quantity(s.spec.numerics.spacing, Dimension::Length) +
                               "), such as twice it");
    load_case_file(opt.case_file, opt.sets, opt.coarse_spacing);  // its scene's inputs are checked now too
  }
  s.out = opt.out.empty() ? fs::path("runs") / (s.spec.name + "-ballistic") : fs::path(opt.out);
  fs::create_directories(s.out);
  s.cores = std::max(1, omp_get_num_procs());
  s.jobs = opt.jobs > 0 ? opt.jobs : s.cores;
}

void print_banner(const Search& s) {
  if (s.opt.quiet) return;
  const double rounds = std::ceil(std::log(std::max(1.0, (s.v_to - s.v_from) / s.tolerance)) / std::log(s.jobs + 1.0));
  std::printf("ballistic-limit: %s at spacing %s, %s to %s m/s until the bracket is %s m/s wide\n",
              s.spec.name.c_str(), format_quantity(s.spec.numerics.spacing, Dimension::Length).c_str(),
              speed_text(s.v_from).c_str(), speed_text(s.v_to).c_str(), speed_text(s.tolerance).c_str());
  const std::string solver = s.opt.backend == "reference"
                                 ? "reference (double)"
                                 : "gpu port (" + s.opt.precision + "; the CUDA build on a device, else the host build)";
  std::printf("  solver: %s; splits: %s\n", solver.c_str(),
              s.opt.split == "thirds" ? "even" : "at the Recht-Ipson limit of the perforating runs, where they have one");
  std::printf("  %d run%s at a time, %d thread%s each; the 2 ends, then at most about %.0f round%s of %d; results in "
              "%s\n",
              s.jobs, s.jobs > 1 ? "s" : "", std::max(1, s.cores / s.jobs), s.cores / s.jobs > 1 ? "s" : "", rounds,
              rounds == 1 ? "" : "s", s.jobs, s.out.string().c_str());
  std::printf("  %9s      %-10s  %13s  %9s\n", "v_impact", "perforated", "v_residual", "wall");
  std::fflush(stdout);
}

// A failed run ends the search: its speed would leave a hole in the bracket. Prints each and returns
// whether there was one.
bool report_failures(const Search& s) {
  bool any = false, diverged = false;
  for (const Run& r : s.runs)
    if (r.failed) {
      any = true;
      diverged |= r.diverged;
      std::fprintf(stderr, "error: the run at %s m/s %s: %s\n  its output is in %s\n", speed_text(r.v).c_str(),
                   r.diverged ? "diverged" : "failed", r.error.c_str(), r.dir.string().c_str());
    }
  if (any && diverged) std::fprintf(stderr, "Try a smaller numerics.cfl (--set numerics.cfl=0.1) or another --spacing.\n");
  return any;
}

void add_runs(Search& s, std::vector<Run> batch) {
  for (Run& r : batch) s.runs.push_back(std::move(r));
}

// Says which end of a bracket is wrong and what to try (the user's --from and --to).
void explain_bad_bracket(const Search& s, const Run& low, const Run& high) {
  const ObservablesSpec& os = s.spec.observables;
  const double end_us = s.spec.time.end * 1e6;
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
}

// How an attempt to bracket the limit ended.
enum class Bracketing { Done, Interrupted, Failed, Bad };

// Runs the ends lo and hi together and checks that they straddle the limit. With `widen` (ends taken from a
// coarser search rather than given by the user), an end on the wrong side becomes the other end and a new
// end is tried as far again beyond it, within the user's --from and --to, until the two straddle the limit.
Bracketing bracket(Search& s, Outcome& o, double lo, double hi, bool widen) {
  std::vector<double> todo{lo, hi};
  for (;;) {
    const std::size_t first = s.runs.size();
    add_runs(s, run_batch(s, todo));
    if (report_failures(s)) return Bracketing::Failed;
    if (s.runs.size() < first + todo.size() || stop_requested()) return Bracketing::Interrupted;
    const Run* low = nullptr;
    const Run* high = nullptr;
    for (std::size_t k = first; k < s.runs.size(); ++k) {
      if (!s.runs[k].done) return Bracketing::Interrupted;
      if (s.runs[k].v == lo) low = &s.runs[k];
      if (s.runs[k].v == hi) high = &s.runs[k];
    }
    const bool low_ok = !low || !low->obs.perforated, high_ok = !high || high->obs.perforated;
    if (low && high && (!low_ok || !high_ok) && !widen) {
      explain_bad_bracket(s, *low, *high);
      return Bracketing::Bad;
    }
    if (!low_ok) {  // the limit is below lo: lo is an upper end
      hi = lo;
      lo = std::max(s.v_from, round_speed(lo - (high ? high->v - lo : lo * 0.1)));
      if (lo >= hi) return Bracketing::Bad;
      todo = {lo};
    } else if (!high_ok) {
      lo = hi;
      hi = std::min(s.v_to, round_speed(hi + (low ? hi - low->v : hi * 0.1)));
      if (hi <= lo) return Bracketing::Bad;
      todo = {hi};
    } else {
      o.bracketed = true;
      o.lo = lo;
      o.hi = hi;
      return Bracketing::Done;
    }
    if (!s.opt.quiet) std::printf("  the limit is outside the coarse bracket: trying %s m/s\n", speed_text(todo[0]).c_str());
  }
}

// The limit the perforating runs' Recht-Ipson curve points to (p = 2, a and v_bl fitted), when at least two
// of them have a residual velocity; -1 otherwise.
double recht_ipson_estimate(const Search& s, const Outcome& o) {
  std::vector<double> vi, vr;
  for (const Run* r : sorted_done(s))
    if (r->obs.perforated && r->obs.residual_velocity > 0) {
      vi.push_back(r->v);
      vr.push_back(r->obs.residual_velocity);
    }
  if (vi.size() < 2) return -1;
  const RechtIpsonFit f = fit_recht_ipson(vi, vr, {1.0, 2.0, o.limit()}, true, false, true);
  return f.ok ? f.curve.v_bl : -1;
}

// The speeds of the next round within (lo, hi): s.jobs of them, evenly, or (--split recht-ipson, where the
// perforating runs point to a limit inside the bracket) spread over 0.9 tolerance about that limit, so that
// the round closes the bracket where the estimate holds.
std::vector<double> split_points(const Search& s, const Outcome& o) {
  std::vector<double> points;
  auto add = [&](double v) {
    v = round_speed(v);
    if (v > o.lo && v < o.hi && (points.empty() || v > points.back())) points.push_back(v);
  };
  const double estimate = s.opt.split == "recht-ipson" ? recht_ipson_estimate(s, o) : -1;
  const double width = 0.9 * s.tolerance;
  if (estimate - 0.5 * width > o.lo && estimate + 0.5 * width < o.hi && o.hi - o.lo > 2 * s.tolerance) {
    if (!s.opt.quiet) std::printf("  recht-ipson: the perforating runs point to %.1f m/s\n", estimate);
    if (s.jobs == 1) add(estimate);
    for (int k = 0; k < s.jobs && s.jobs > 1; ++k) add(estimate - 0.5 * width + width * k / (s.jobs - 1));
    if (static_cast<int>(points.size()) == s.jobs) return points;
    points.clear();
  }
  for (int k = 1; k <= s.jobs; ++k) add(o.lo + (o.hi - o.lo) * k / (s.jobs + 1));
  return points;
}

// Splits [lo, hi] round by round (split_points), keeping the part where the verdict changes, until it is
// within the tolerance. Non-monotonic verdicts (a higher speed that stops) follow the lowest perforation and
// are listed in `inversions`. Returns false when a run failed.
bool narrow(Search& s, Outcome& o, std::vector<std::string>& inversions) {
  while (o.hi - o.lo > s.tolerance && !stop_requested()) {
    const std::vector<double> points = split_points(s, o);
    if (points.empty()) break;
    std::vector<Run> batch = run_batch(s, points);
    std::vector<std::pair<double, bool>> verdicts{{o.lo, false}, {o.hi, true}};
    for (const Run& r : batch)
      if (r.done) verdicts.emplace_back(r.v, r.obs.perforated);
    add_runs(s, std::move(batch));
    if (report_failures(s)) return false;
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
  return true;
}

// The coarse search (--coarse): the same search at the coarse spacing into DIR/coarse-<spacing>, quietly
// but for its result. Returns its exit status and its bracket in lo, hi.
int coarse_search(const Search& s, double& lo, double& hi) {
  BallisticOptions c = s.opt;
  c.spacing = s.opt.coarse_spacing;
  c.coarse_spacing.clear();
  c.out = (s.out / ("coarse-" + s.opt.coarse_spacing)).string();
  if (!s.opt.quiet) std::printf("  first the same search at %s:\n", s.opt.coarse_spacing.c_str());
  const int status = ballistic_limit_command(c);
  const nlohmann::json j = read_json_or_null(fs::path(c.out) / "ballistic.json");
  if (status != 0 || !j.is_object() || !j.contains("bracket_m_s") || !j.at("bracket_m_s").is_array())
    return status != 0 ? status : 3;
  lo = j.at("bracket_m_s").at(0).get<double>();
  hi = j.at("bracket_m_s").at(1).get<double>();
  return 0;
}

}  // namespace
}  // namespace ballistic


int ballistic_limit_command(const BallisticOptions& opt) {
  Search s;
  prepare(opt, s);
  const Reference reference = read_reference(fs::path(opt.case_file).parent_path() / "reference.csv");
  Outcome o;
  if (!reference.points.empty()) o.reference = &reference;

  // The first bracket: the user's ends, or the coarse search's widened by the margin on each side.
  double lo = s.v_from, hi = s.v_to;
  const bool from_coarse = !opt.coarse_spacing.empty();
  if (from_coarse) {
    if (const int status = coarse_search(s, lo, hi); status != 0) return status;
    const double margin = opt.coarse_margin * 0.5 * (lo + hi);
    lo = std::max(s.v_from, round_speed(lo - margin));
    hi = std::min(s.v_to, round_speed(hi + margin));
    if (!opt.quiet)
      std::printf("  the coarse search bracketed the limit; here from %s to %s m/s (its bracket and %.0f %% of its "
                  "limit on each side)\n",
                  speed_text(lo).c_str(), speed_text(hi).c_str(), 100 * opt.coarse_margin);
  }
  print_banner(s);
  g_signals.store(0);
  g_abort_runs.store(false);
  const ScopedSignals signals(on_search_stop);
  auto finish = [&](const char* status, int exit_status) {
    o.status = status;
    write_results(s, o);
    return exit_status;
  };
  switch (bracket(s, o, lo, hi, from_coarse)) {
    case Bracketing::Failed: return finish("failed", 3);
    case Bracketing::Bad: return finish("bad-bracket", 4);
    case Bracketing::Interrupted:
      std::printf("interrupted before the limit was bracketed; results so far in %s\n", s.out.string().c_str());
      return finish("interrupted", 130);
    case Bracketing::Done: break;
  }
  write_results(s, o);
  std::vector<std::string> inversions;
  if (!narrow(s, o, inversions)) return finish("failed", 3);
  const bool interrupted = stop_requested() && o.hi - o.lo > s.tolerance;
  const double end_us = s.spec.time.end * 1e6;
  const ObservablesSpec& os = s.spec.observables;
  (void)os;

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
