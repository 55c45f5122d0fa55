// impactsph sweep: the runs as child processes, resume, the Slurm script (the sweep file is read in
// sweep_file.cpp, the table written in sweep_table.cpp).
// A run is `impactsph run CASE --spacing S --set K=V ... --out DIR --threads T --quiet` in a child
// process of its own (its own process group, so a terminal's Ctrl-C reaches the sweep only, and the sweep
// passes SIGTERM on to every run in flight, which then writes its checkpoint and stops).
#include "app/sweep.hpp"

#include <fcntl.h>
#include <omp.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "app/run_args.hpp"
#include "app/sweep_parts.hpp"
#include "common/scoped_signals.hpp"
#include "common/case_file.hpp"
#include "common/errors.hpp"
#include "common/output.hpp"
#include "common/units.hpp"

namespace fs = std::filesystem;

namespace impactsph {

namespace sweep_detail {

FolderState folder_state(const SweepRun& r, const std::filesystem::path& dir) {
  FolderState f;
  const nlohmann::json record = read_json_or_null(dir / "sweep_run.json");
  const bool same_run = record.is_object() && record.value("fingerprint", "") == r.fingerprint &&
                        record.value("backend", "") == r.backend && record.value("precision", "") == r.precision;
  const nlohmann::json summary = read_json_or_null(dir / "summary.json");
  const bool summary_ours = summary.is_object() && summary.value("fingerprint", "") == r.fingerprint;
  if (summary_ours && summary.value("completed", false) && (same_run || !record.is_object())) {
    f.state = RunState::Complete;
    f.summary = summary;
    return f;
  }
  if (same_run && record.value("status", "") == "failed") {
    f.state = RunState::Failed;
    f.error = record.value("error", "");
    if (summary_ours) f.summary = summary;
    return f;
  }
  if (same_run && fs::exists(dir / "checkpoint.bin") && fs::exists(dir / "run.json")) {
    f.state = RunState::Stopped;
    if (summary_ours) f.summary = summary;
    return f;
  }
  if (fs::exists(dir / "summary.json") || fs::exists(dir / "checkpoint.bin")) f.state = RunState::Stale;
  return f;
}

}  // namespace sweep_detail

namespace {

using namespace sweep_detail;

std::string shell_quote(const std::string& s) {
  bool plain = !s.empty();
  for (char c : s)
    plain &= std::isalnum(static_cast<unsigned char>(c)) || std::string("/._-+=,:@%").find(c) != std::string::npos;
  if (plain) return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The arguments of `impactsph run` for a run (without the program name).
std::vector<std::string> run_arguments(const SweepSpec& spec, const SweepRun& r, const fs::path& dir, int threads) {
  std::vector<std::string> a{"run", spec.case_file};
  if (!r.spacing.empty()) a.insert(a.end(), {"--spacing", r.spacing});
  for (const std::string& s : r.sets) a.insert(a.end(), {"--set", s});
  if (!r.backend.empty()) a.insert(a.end(), {"--backend", r.backend});
  if (!r.precision.empty()) a.insert(a.end(), {"--precision", r.precision});
  a.insert(a.end(), {"--out", dir.string(), "--threads", std::to_string(threads), "--quiet"});
  return a;
}

// The arguments that continue a stopped run from its checkpoint (the case and overrides are in run.json).
std::vector<std::string> restart_arguments(const SweepRun& r, const fs::path& dir, int threads) {
  std::vector<std::string> a{"run", "--restart", dir.string(), "--threads", std::to_string(threads), "--quiet"};
  if (!r.backend.empty()) a.insert(a.end(), {"--backend", r.backend});
  if (!r.precision.empty()) a.insert(a.end(), {"--precision", r.precision});
  return a;
}

// What a run folder holds, judged against the run the sweep file asks for.

void write_record(const SweepRun& r, const fs::path& dir, const std::string& status, const std::string& error,
                  const std::vector<std::string>& args) {
  nlohmann::json j{{"name", r.name},           {"fingerprint", r.fingerprint}, {"backend", r.backend},
                   {"precision", r.precision}, {"status", status},             {"arguments", args}};
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [k, v] : r.parameters) params[k] = v;
  j["parameters"] = params;
  if (!error.empty()) j["error"] = error;
  write_text_atomic(dir / "sweep_run.json", j.dump(2) + "\n");
}

// ---------------------------------------------------------------------------------------------------
// Signals: the first SIGINT/SIGTERM stops the sweep (the runs in flight get SIGTERM and write their
// checkpoints); a second kills the runs at once.

std::atomic<int> g_signals{0};
extern "C" void on_sweep_signal(int) { g_signals.fetch_add(1); }

std::string this_executable() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot find the impactsph executable (/proc/self/exe): " + ec.message());
  return p.string();
}

// Starts `exe args...` in its own process group with stdout and stderr appended to `log`.
pid_t spawn(const std::string& exe, const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> all{exe};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : all) argv.push_back(s.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("cannot start a run (fork): ") + std::strerror(errno));
  if (pid == 0) {
    setpgid(0, 0);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
      close(fd);
    }
    execv(exe.c_str(), argv.data());
    std::fprintf(stderr, "cannot run %s: %s\n", exe.c_str(), std::strerror(errno));
    _exit(127);
  }
  setpgid(pid, pid);  // also here, so a signal sent right after fork finds the group
  return pid;
}

std::string last_lines(const fs::path& log, std::size_t n) {
  std::ifstream in(log);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) lines.push_back(line);
  std::string s;
  for (std::size_t k = lines.size() > n ? lines.size() - n : 0; k < lines.size(); ++k) s += (s.empty() ? "" : "\n") + lines[k];
  return s;
}

// ---------------------------------------------------------------------------------------------------
// Slurm

void emit_slurm(const SweepSpec& spec, const SweepOptions& opt, const fs::path& out, const std::string& exe) {
  const fs::path abs_out = fs::absolute(out).lexically_normal();
  const int threads = opt.threads_per_run;
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# Written by `impactsph sweep " << spec.file << " --emit slurm`: one array task per run of the sweep\n"
    << "# '" << spec.name << "'. Submit with ./submit.sh (this array, then collect.slurm when it ends).\n"
    << "# A task that finds its run's checkpoint continues it (run --restart); Slurm's SIGTERM at the time\n"
    << "# limit makes a run write its checkpoint, so resubmitting continues the runs that were cut off.\n"
    << "#SBATCH --job-name=" << name_part(spec.name) << "\n"
    << "#SBATCH --array=0-" << spec.runs.size() - 1 << "\n"
    << "#SBATCH --ntasks=1\n"
    << "#SBATCH --cpus-per-task=" << threads << "\n"
    << "#SBATCH --output=" << (abs_out / "slurm-%A_%a.out").string() << "\n";
  for (const auto& [k, v] : spec.slurm) s << "#SBATCH --" << k << "=" << v << "\n";
  for (const std::string& e : spec.slurm_extra) s << "#SBATCH " << e << "\n";
  s << "set -euo pipefail\n"
    << "IMPACTSPH=${IMPACTSPH:-" << shell_quote(exe) << "}\n"
    << "export OMP_NUM_THREADS=" << threads << "\n"
    << "case \"$SLURM_ARRAY_TASK_ID\" in\n";
  for (std::size_t i = 0; i < spec.runs.size(); ++i) {
    const SweepRun& r = spec.runs[i];
    const fs::path dir = abs_out / r.name;
    s << "  " << i << ")\n    DIR=" << shell_quote(dir.string()) << "\n    ARGS=(";
    const std::vector<std::string> args = run_arguments(spec, r, dir, threads);
    for (std::size_t k = 0; k < args.size(); ++k) s << (k ? " " : "") << shell_quote(args[k]);
    s << ")\n    RESTART=(";
    const std::vector<std::string> restart = restart_arguments(r, dir, threads);
    for (std::size_t k = 0; k < restart.size(); ++k) s << (k ? " " : "") << shell_quote(restart[k]);
    s << ")\n    ;;\n";
  }
  s << "  *) echo \"no run for array task $SLURM_ARRAY_TASK_ID (0-" << spec.runs.size() - 1 << ")\" >&2; exit 2 ;;\n"
    << "esac\n"
    << "mkdir -p \"$DIR\"\n"
    << "if [ -f \"$DIR/checkpoint.bin\" ] && [ -f \"$DIR/run.json\" ]; then\n"
    << "  exec \"$IMPACTSPH\" \"${RESTART[@]}\"\n"
    << "fi\n"
    << "exec \"$IMPACTSPH\" \"${ARGS[@]}\"\n";
  write_text_atomic(out / "sweep.slurm", s.str());

  std::ostringstream c;
  c << "#!/bin/bash\n"
    << "# Written by `impactsph sweep --emit slurm`: builds the sweep table (sweep.csv, sweep.md) from the run\n"
    << "# folders once the array has ended (submit.sh makes it depend on the array).\n"
    << "#SBATCH --job-name=" << name_part(spec.name) << "-collect\n"
    << "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n"
    << "#SBATCH --output=" << (abs_out / "slurm-collect-%j.out").string() << "\n";
  for (const auto& [k, v] : spec.slurm)
    if (k != "time") c << "#SBATCH --" << k << "=" << v << "\n";
  c << "#SBATCH --time=00:10:00\n"
    << "set -euo pipefail\n"
    << "IMPACTSPH=${IMPACTSPH:-" << shell_quote(exe) << "}\n"
    << "exec \"$IMPACTSPH\" sweep " << shell_quote(fs::absolute(spec.file).lexically_normal().string()) << " --out "
    << shell_quote(abs_out.string()) << " --collect\n";
  write_text_atomic(out / "collect.slurm", c.str());

  std::ostringstream sub;
  sub << "#!/bin/bash\n"
      << "# Submits the run array, then the collect step to run after it whatever the runs' outcome.\n"
      << "set -euo pipefail\n"
      << "cd " << shell_quote(abs_out.string()) << "\n"
      << "array=$(sbatch --parsable sweep.slurm)\n"
      << "collect=$(sbatch --parsable --dependency=afterany:${array%%;*} collect.slurm)\n"
      << "echo \"submitted array $array (" << spec.runs.size() << " runs) and collect step $collect\"\n";
  write_text_atomic(out / "submit.sh", sub.str());
  fs::permissions(out / "submit.sh", fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add);
}

}  // namespace

int sweep_command(const SweepOptions& opt) {
  if (!fs::is_regular_file(opt.sweep_file))
    throw std::runtime_error("sweep file " + opt.sweep_file + " not found");
  if (!opt.emit.empty() && opt.emit != "slurm")
    throw std::runtime_error("--emit " + opt.emit + ": the only script this writes is slurm (--emit slurm)");
  if (opt.threads_per_run < 1) throw std::runtime_error("--threads-per-run must be at least 1");
  const SweepSpec spec = load_sweep_file(opt.sweep_file);
  const fs::path out = opt.out.empty() ? fs::path("runs") / spec.name : fs::path(opt.out);
  fs::create_directories(out);
  const std::string exe = opt.executable.empty() ? this_executable() : opt.executable;

  if (opt.emit == "slurm") {
    emit_slurm(spec, opt, out, exe);
    std::printf("sweep %s: %zu runs; wrote %s (job array), %s and %s\nsubmit with: %s\n", spec.name.c_str(),
                spec.runs.size(), (out / "sweep.slurm").string().c_str(), (out / "collect.slurm").string().c_str(),
                (out / "submit.sh").string().c_str(), (out / "submit.sh").string().c_str());
    return 0;
  }
  if (opt.collect) {
    const std::vector<TableRow> rows = collect_rows(spec, out);
    std::printf("%s", write_table(spec, out, rows).c_str());
    int done = 0;
    for (const TableRow& r : rows) done += r.status == "done";
    std::printf("%d of %zu runs complete; table in %s and %s\n", done, rows.size(), (out / "sweep.csv").string().c_str(),
                (out / "sweep.md").string().c_str());
    return done == static_cast<int>(rows.size()) ? 0 : 3;
  }

  const int cores = std::max(1, omp_get_num_procs());
  const int threads = opt.threads_per_run;
  const int jobs = opt.jobs > 0 ? opt.jobs : std::max(1, cores / threads);
  if (jobs * threads > cores)
    std::fprintf(stderr, "warning: %d runs x %d threads is more than the %d cores; runs will share cores\n", jobs,
                 threads, cores);

  struct Todo {
    const SweepRun* run;
    bool restart;
  };
  std::vector<Todo> todo;
  int skipped = 0, skipped_failed = 0;
  for (const SweepRun& r : spec.runs) {
    const fs::path dir = out / r.name;
    const FolderState f = folder_state(r, dir);
    if (f.state == RunState::Complete) {
      ++skipped;
      continue;
    }
    if (f.state == RunState::Failed && !opt.retry_failed) {
      ++skipped_failed;
      continue;
    }
    todo.push_back({&r, f.state == RunState::Stopped});
  }
  std::printf("sweep %s: %zu runs of %s; %d complete already, %zu to run (%d continued from a checkpoint); %d at a "
              "time, %d thread%s each; results in %s\n",
              spec.name.c_str(), spec.runs.size(), spec.case_file.c_str(), skipped, todo.size(),
              static_cast<int>(std::count_if(todo.begin(), todo.end(), [](const Todo& t) { return t.restart; })), jobs,
              threads, threads > 1 ? "s" : "", out.string().c_str());
  if (skipped_failed > 0)
    std::printf("  %d run%s failed in an earlier sweep and %s skipped; --retry-failed runs them again\n", skipped_failed,
                skipped_failed > 1 ? "s" : "", skipped_failed > 1 ? "are" : "is");
  std::fflush(stdout);

  g_signals.store(0);
  const ScopedSignals signals(on_sweep_signal);
  struct Running {
    const SweepRun* run;
    pid_t pid;
    std::chrono::steady_clock::time_point start;
  };
  std::vector<Running> running;
  std::size_t next = 0;
  int failed = 0, interrupted = 0, finished = 0;
  bool told_stop = false, killed = false;
  // Once told to stop, no new run starts: the loop ends when the runs in flight have stopped, with runs
  // still to do left for the next call.
  while ((next < todo.size() && !told_stop) || !running.empty()) {
    const int sig = g_signals.load();
    if (sig >= 1 && !told_stop) {
      told_stop = true;
      std::fprintf(stderr, "\nstopping: the %zu run%s in flight write their checkpoints and stop; run the same command "
                           "again to continue (a second Ctrl-C kills them)\n",
                   running.size(), running.size() == 1 ? "" : "s");
      for (const Running& x : running) kill(-x.pid, SIGTERM);
    }
    if (sig >= 2 && !killed) {
      killed = true;
      for (const Running& x : running) kill(-x.pid, SIGKILL);
    }
    while (sig == 0 && next < todo.size() && static_cast<int>(running.size()) < jobs) {
      const Todo& t = todo[next++];
      const fs::path dir = out / t.run->name;
      fs::create_directories(dir);
      std::vector<std::string> args;
      if (t.restart) {
        args = restart_arguments(*t.run, dir, threads);
      } else {
        std::error_code ec;
        for (const char* f : {"summary.json", "checkpoint.bin", "run.json"}) fs::remove(dir / f, ec);
        args = run_arguments(spec, *t.run, dir, threads);
      }
      write_record(*t.run, dir, "started", "", args);
      running.push_back({t.run, spawn(exe, args, dir / "log.txt"), std::chrono::steady_clock::now()});
      std::printf("  start  %s%s\n", t.run->name.c_str(), t.restart ? " (from its checkpoint)" : "");
      std::fflush(stdout);
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, WNOHANG);
    if (pid <= 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      continue;
    }
    const auto it = std::find_if(running.begin(), running.end(), [&](const Running& x) { return x.pid == pid; });
    if (it == running.end()) continue;
    const SweepRun& r = *it->run;
    const fs::path dir = out / r.name;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - it->start).count();
    running.erase(it);
    const nlohmann::json record = read_json_or_null(dir / "sweep_run.json");
    const std::vector<std::string> args = record.value("arguments", std::vector<std::string>{});
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const FolderState f = folder_state(r, dir);
    if (code == 0 && f.state == RunState::Complete) {
      ++finished;
      write_record(r, dir, "done", "", args);
      std::printf("  done   %s  %.1f s\n", r.name.c_str(), wall);
    } else if (code == 130 || (WIFSIGNALED(status) && told_stop) || (told_stop && code != 3 && code != 2)) {
      ++interrupted;
      write_record(r, dir, "stopped", "", args);
      std::printf("  stopped %s after %.1f s%s\n", r.name.c_str(), wall,
                  fs::exists(dir / "checkpoint.bin") ? " (checkpoint written)" : " (no checkpoint yet: it starts afresh)");
    } else {
      ++failed;
      const std::string why = "exit status " + std::to_string(code) + ": " + last_lines(dir / "log.txt", 3);
      write_record(r, dir, "failed", why, args);
      std::printf("  FAILED %s (%s); its log is %s\n", r.name.c_str(), why.c_str(), (dir / "log.txt").string().c_str());
    }
    std::fflush(stdout);
  }

  const std::vector<TableRow> rows = collect_rows(spec, out);
  write_table(spec, out, rows);
  int done = 0;
  for (const TableRow& x : rows) done += x.status == "done";
  std::printf("sweep %s: %d of %zu runs complete (%d run now, %d skipped as complete), %d stopped, %d failed; table "
              "in %s and %s\n",
              spec.name.c_str(), done, rows.size(), finished, skipped, interrupted, failed + skipped_failed,
              (out / "sweep.csv").string().c_str(), (out / "sweep.md").string().c_str());
  if (told_stop) {
    std::printf("stopped: run the same command again to continue the sweep\n");
    return 130;
  }
  return failed + skipped_failed > 0 ? 3 : 0;
}

}  // namespace impactsph
