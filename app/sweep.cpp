// impactsph sweep: the sweep file, the runs as child processes, resume, the table, the Slurm script.
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
#include <toml++/toml.h>

#include "common/scoped_signals.hpp"
#include "app/run_args.hpp"
#include "common/case_file.hpp"
#include "common/errors.hpp"
#include "common/output.hpp"
#include "common/units.hpp"

namespace fs = std::filesystem;

namespace impactsph {

namespace {

// ---------------------------------------------------------------------------------------------------
// The sweep file

const std::vector<std::string> kSweepKeys{"name", "case", "set"};
const std::vector<std::string> kTopKeys{"sweep", "axes", "runs", "slurm"};
const std::vector<std::string> kSlurmKeys{"time", "partition", "account", "extra"};
const std::vector<std::string> kBackends{"reference", "gpu"};
const std::vector<std::string> kPrecisions{"double", "float"};
const char* kAxisHelp =
    "an axis is spacing, velocity (the impact speed of the case's [observables] projectile), backend, "
    "precision, or a case key as --set takes it (\"projectile.velocity\", \"numerics.cfl\", \"time.end\")";

int line_of(const toml::node* n) { return n ? static_cast<int>(n->source().begin.line) : 0; }

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// The text a value is given to `--set KEY=VALUE` as: strings as they are, numbers and booleans and
// arrays as TOML.
bool value_text(const toml::node& n, std::string& out) {
  if (const auto* s = n.as_string()) {
    out = s->get();
    return true;
  }
  if (n.is_integer() || n.is_floating_point() || n.is_boolean() || n.is_array()) {
    std::ostringstream ss;
    if (n.is_array()) ss << toml::toml_formatter{*n.as_array()};
    else if (n.is_integer()) ss << n.as_integer()->get();
    else if (n.is_boolean()) ss << (n.as_boolean()->get() ? "true" : "false");
    else {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.17g", n.as_floating_point()->get());
      ss << buf;
    }
    out = ss.str();
    return true;
  }
  return false;
}

// "0.5 mm" -> "0.5mm", "250 m/s" -> "250m_per_s", "[0, 0, -1]" -> "0,0,-1": a folder name a shell and
// Slurm take without quotes.
std::string name_part(const std::string& text) {
  std::string s;
  for (char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == ',') s += c;
    else if (c == '/') s += "_per_";
    else if (c == ' ' || c == '"' || c == '[' || c == ']' || c == '^') continue;
    else s += '_';
  }
  return s.empty() ? "empty" : s;
}

class SweepReader {
 public:
  explicit SweepReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const toml::node* at, const std::string& key, const std::string& message) const {
    throw CaseError(file_, line_of(at), key, message);
  }

  SweepSpec read() {
    toml::table root;
    try {
      root = toml::parse_file(file_);
    } catch (const toml::parse_error& e) {
      throw CaseError(file_, static_cast<int>(e.source().begin.line), "",
                      std::string("not valid TOML: ") + std::string(e.description()));
    } catch (const std::exception& e) {
      throw CaseError(file_, 0, "", std::string("cannot read the sweep file: ") + e.what());
    }
    for (auto&& [k, v] : root)
      if (std::find(kTopKeys.begin(), kTopKeys.end(), std::string(k.str())) == kTopKeys.end())
        throw CaseError(file_, static_cast<int>(k.source().begin.line), std::string(k.str()),
                        "unknown table; a sweep file has [sweep], [axes] (a cartesian product) or [[runs]] (a "
                        "list), and [slurm]");
    SweepSpec spec;
    spec.file = file_;
    const toml::table* sweep = root["sweep"].as_table();
    if (!sweep) fail(nullptr, "sweep", "missing: a sweep file starts with [sweep] and case = \"path/to/case.toml\"");
    for (auto&& [k, v] : *sweep)
      if (std::find(kSweepKeys.begin(), kSweepKeys.end(), std::string(k.str())) == kSweepKeys.end())
        fail(&v, "sweep." + std::string(k.str()), "unknown key; valid keys of [sweep]: " + join(kSweepKeys));
    spec.name = fs::path(file_).stem().string();
    if (const toml::node* n = sweep->get("name")) {
      if (!n->is_string() || n->as_string()->get().empty())
        fail(n, "sweep.name", "must be a non-empty string, e.g. name = \"hugoniot-spacing\"");
      spec.name = n->as_string()->get();
    }
    const toml::node* c = sweep->get("case");
    if (!c || !c->is_string())
      fail(c, "sweep.case", "needs the case file as a string, relative to the sweep file: case = \"../hugoniot-4340/case.toml\"");
    fs::path case_path = c->as_string()->get();
    if (case_path.is_relative()) case_path = fs::path(file_).parent_path() / case_path;
    if (!fs::is_regular_file(case_path))
      fail(c, "sweep.case", "no such file: " + case_path.string() + " (paths are relative to the sweep file)");
    spec.case_file = fs::absolute(case_path).lexically_normal().string();
    // The case itself must be valid before any override is tried on it.
    const CaseSpec base = load_case_file(spec.case_file);
    projectile_ = base.observables.projectile;

    std::vector<std::string> common_sets;
    if (const toml::node* s = sweep->get("set")) {
      const toml::array* a = s->as_array();
      if (!a) fail(s, "sweep.set", "must be an array of \"KEY=VALUE\" strings, e.g. set = [\"output.vtu=false\"]");
      for (std::size_t i = 0; i < a->size(); ++i) {
        const toml::node* e = a->get(i);
        const std::string key = "sweep.set[" + std::to_string(i) + "]";
        if (!e->is_string() || e->as_string()->get().find('=') == std::string::npos)
          fail(e, key, "must be a string KEY=VALUE, e.g. \"numerics.cfl=0.1\"");
        common_sets.push_back(e->as_string()->get());
      }
    }

    const toml::node* axes = root.get("axes");
    const toml::node* runs = root.get("runs");
    if (axes && runs)
      fail(runs, "runs", "a sweep has either [axes] (every combination of the values) or [[runs]] (a list), not both");
    if (!axes && !runs)
      fail(nullptr, "axes", "missing: give [axes] with arrays of values (spacing = [\"1 mm\", \"0.5 mm\"]) or a list of "
                            "[[runs]]");
    std::vector<std::vector<Param>> combos;
    if (axes) {
      if (!axes->is_table()) fail(axes, "axes", "must be a table: [axes] with one array of values per axis");
      std::vector<std::pair<std::string, std::vector<Param>>> values;
      for (auto& [name, node] : flatten(*axes->as_table(), "")) {
        const std::string key = "axes." + name;
        const toml::array* a = node->as_array();
        if (!a || a->empty())
          fail(node, key, "must be a non-empty array of values, e.g. " + name + " = [" + example(name) + "]");
        std::vector<Param> vs;
        std::set<std::string> seen;
        for (std::size_t i = 0; i < a->size(); ++i) {
          Param p = param(name, *a->get(i), key + "[" + std::to_string(i) + "]");
          if (!seen.insert(p.value).second) fail(a->get(i), key + "[" + std::to_string(i) + "]", "repeats " + p.value);
          vs.push_back(p);
        }
        spec.axis_names.push_back(name);
        values.emplace_back(name, vs);
      }
      if (values.empty()) fail(axes, "axes", "has no axis; " + std::string(kAxisHelp));
      combos.emplace_back();
      for (const auto& [name, vs] : values) {
        std::vector<std::vector<Param>> next;
        for (const std::vector<Param>& c0 : combos)
          for (const Param& p : vs) {
            next.push_back(c0);
            next.back().push_back(p);
          }
        combos = std::move(next);
      }
    } else {
      const toml::array* a = runs->as_array();
      if (!a || a->empty() || !a->is_array_of_tables())
        fail(runs, "runs", "must be a list of tables: [[runs]] then spacing = \"1 mm\", ... for each run");
      for (std::size_t i = 0; i < a->size(); ++i) {
        std::vector<Param> ps;
        for (auto& [name, node] : flatten(*a->get(i)->as_table(), "")) {
          ps.push_back(param(name, *node, "runs[" + std::to_string(i) + "]." + name));
          if (std::find(spec.axis_names.begin(), spec.axis_names.end(), name) == spec.axis_names.end())
            spec.axis_names.push_back(name);
        }
        combos.push_back(ps);
      }
    }

    std::map<std::string, std::string> names;
    for (const std::vector<Param>& combo : combos) {
      SweepRun r;
      r.sets = common_sets;
      std::string name;
      for (const Param& p : combo) {
        r.parameters.emplace_back(p.axis, p.value);
        name += (name.empty() ? "" : "__") + name_part(p.axis) + "-" + name_part(p.value);
        if (p.axis == "spacing") r.spacing = p.value;
        else if (p.axis == "backend") r.backend = p.value;
        else if (p.axis == "precision") r.precision = p.value;
        else if (p.axis == "velocity") r.sets.push_back(projectile_ + ".velocity=" + p.value);
        else r.sets.push_back(p.axis + "=" + p.value);
      }
      r.name = name.empty() ? "case-as-written" : name;
      // Checked exactly as `impactsph run` would check it, before any run starts.
      try {
        load_case_file(spec.case_file, r.sets, r.spacing);
      } catch (const CaseError& e) {
        const Param* culprit = combo.empty() ? nullptr : &combo.back();
        for (const Param& p : combo)
          if (e.key() == p.axis || e.key().find(p.axis) != std::string::npos ||
              (p.axis == "spacing" && e.key() == "numerics.spacing") ||
              (p.axis == "velocity" && e.key().find("velocity") != std::string::npos))
            culprit = &p;
        fail(culprit ? culprit->node : nullptr, culprit ? culprit->where : "sweep.set",
             "the run " + r.name + " is not a valid case: " + e.what());
      }
      const auto [it, fresh] = names.emplace(r.name, r.name);
      if (!fresh) fail(runs ? runs : axes, runs ? "runs" : "axes", "two runs have the same parameters: " + r.name);
      r.fingerprint = run_fingerprint(spec.case_file, r.spacing, r.sets);
      spec.runs.push_back(r);
    }

    if (const toml::node* s = root.get("slurm")) {
      if (!s->is_table()) fail(s, "slurm", "must be a table: [slurm] time = \"02:00:00\", partition = \"...\"");
      for (auto&& [k, v] : *s->as_table()) {
        const std::string key = std::string(k.str());
        if (std::find(kSlurmKeys.begin(), kSlurmKeys.end(), key) == kSlurmKeys.end())
          fail(&v, "slurm." + key, "unknown key; valid keys of [slurm]: " + join(kSlurmKeys));
        if (key == "extra") {
          const toml::array* a = v.as_array();
          if (!a) fail(&v, "slurm.extra", "must be an array of sbatch options, e.g. [\"--mem=4G\"]");
          for (std::size_t i = 0; i < a->size(); ++i) {
            const toml::node* e = a->get(i);
            if (!e->is_string() || e->as_string()->get().rfind("--", 0) != 0)
              fail(e, "slurm.extra[" + std::to_string(i) + "]", "must be an sbatch option string, e.g. \"--mem=4G\"");
            spec.slurm_extra.push_back(e->as_string()->get());
          }
        } else {
          if (!v.is_string() || v.as_string()->get().empty())
            fail(&v, "slurm." + key, "must be a non-empty string, e.g. time = \"02:00:00\"");
          spec.slurm[key] = v.as_string()->get();
        }
      }
    }
    return spec;
  }

 private:
  struct Param {
    std::string axis, value, where;
    const toml::node* node;
  };

  std::string example(const std::string& name) const {
    if (name == "spacing") return "\"1 mm\", \"0.5 mm\"";
    if (name == "velocity" || name.find("velocity") != std::string::npos) return "\"200 m/s\", \"300 m/s\"";
    if (name == "backend") return "\"reference\", \"gpu\"";
    if (name == "precision") return "\"double\", \"float\"";
    return "0.1, 0.2";
  }

  // Nested tables become dotted names: [axes] projectile.velocity = [...] is the axis "projectile.velocity".
  std::vector<std::pair<std::string, const toml::node*>> flatten(const toml::table& t, const std::string& prefix) {
    std::vector<std::pair<std::string, const toml::node*>> out;
    std::vector<std::pair<int, std::pair<std::string, const toml::node*>>> ordered;
    for (auto&& [k, v] : t) {
      const std::string name = prefix + std::string(k.str());
      if (v.is_table()) {
        for (auto& e : flatten(*v.as_table(), name + ".")) ordered.push_back({line_of(e.second), e});
      } else {
        ordered.push_back({line_of(&v), {name, &v}});
      }
    }
    std::stable_sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& e : ordered) out.push_back(e.second);
    return out;
  }

  Param param(const std::string& axis, const toml::node& n, const std::string& where) const {
    Param p{axis, "", where, &n};
    if (axis.find('.') == std::string::npos && axis != "spacing" && axis != "velocity" && axis != "backend" &&
        axis != "precision")
      fail(&n, where, "unknown axis '" + axis + "'; " + kAxisHelp);
    if (!value_text(n, p.value) || p.value.empty())
      fail(&n, where, "must be a value (a string with a unit, a number, a boolean or an array), e.g. " + example(axis));
    auto choice = [&](const std::vector<std::string>& valid) {
      if (std::find(valid.begin(), valid.end(), p.value) == valid.end())
        fail(&n, where, "'" + p.value + "' is not one of " + join(valid));
    };
    auto with_unit = [&](Dimension d, const char* eg) {
      // A bare number is SI in a case file, but 0.5 for a spacing is half a metre: a sweep axis of
      // lengths or speeds must say its unit.
      bool has_unit = false;
      for (char c : p.value) has_unit |= std::isalpha(static_cast<unsigned char>(c)) && c != 'e' && c != 'E';
      if (!n.is_string() || !has_unit)
        fail(&n, where, p.value + " has no unit; write it with one, e.g. \"" + eg + "\"");
      try {
        parse_quantity(p.value, d);
      } catch (const std::invalid_argument& e) {
        fail(&n, where, p.value + ": " + e.what());
      }
    };
    if (axis == "backend") choice(kBackends);
    else if (axis == "precision") choice(kPrecisions);
    else if (axis == "spacing") with_unit(Dimension::Length, "0.5 mm");
    else if (axis == "velocity") {
      if (projectile_.empty())
        fail(&n, where, "the case has no [observables] projectile, so 'velocity' names no body; use BODY.velocity "
                        "(e.g. \"flyer.velocity\") as the axis");
      with_unit(Dimension::Velocity, "300 m/s");
    }
    return p;
  }

  std::string file_;
  std::string projectile_;
};

// ---------------------------------------------------------------------------------------------------
// Run folders and their state

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
enum class RunState { NotRun, Complete, Stopped, Failed, Stale };

struct FolderState {
  RunState state = RunState::NotRun;
  nlohmann::json summary;  // summary.json when it belongs to this run
  std::string error;       // why it failed (sweep_run.json)
};

// Complete: summary.json says completed with this run's fingerprint and solver flags. Stopped: a
// checkpoint of this run is there. Failed: the sweep recorded a failure of this very run. Stale: the
// folder holds another run (the case or an override changed). The solver flags are compared through the
// command line summary.json records, since the fingerprint covers the case and overrides only.
FolderState folder_state(const SweepRun& r, const fs::path& dir) {
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
// The table

std::string number(double v, int digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string json_cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_number()) return number(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

struct TableRow {
  const SweepRun* run;
  std::string status;
  nlohmann::json summary;  // null when the run has none of its own
};

// Observables in SI: the unit of each, for the column heads.
std::string observable_unit(const std::string& key) {
  if (key.find("velocity") != std::string::npos) return "m/s";
  if (key.find("mass") != std::string::npos) return "kg";
  if (key.find("time") != std::string::npos) return "s";
  if (key == "final_length" || key.rfind("impact_face_diameter", 0) == 0) return "m";
  return "";
}

// Writes OUT/sweep.csv and OUT/sweep.md; returns the Markdown table.
std::string write_table(const SweepSpec& spec, const fs::path& out, const std::vector<TableRow>& rows) {
  std::vector<std::string> observables;
  for (const TableRow& r : rows)
    if (r.summary.is_object() && r.summary.contains("observables"))
      for (auto& [k, v] : r.summary["observables"].items())
        if (std::find(observables.begin(), observables.end(), k) == observables.end()) observables.push_back(k);

  std::vector<std::string> head{"run"};
  for (const std::string& a : spec.axis_names) head.push_back(a);
  head.insert(head.end(), {"status", "particles", "steps", "wall_time_s", "particle_steps_per_s", "mean_neighbours",
                           "energy_drift", "correction_fallbacks"});
  for (const std::string& o : observables) {
    const std::string unit = observable_unit(o);
    head.push_back(unit.empty() ? o : o + "_" + name_part(unit));
  }
  std::vector<std::vector<std::string>> cells;
  for (const TableRow& r : rows) {
    std::vector<std::string> c{r.run->name};
    for (const std::string& a : spec.axis_names) {
      std::string v;
      for (const auto& [k, x] : r.run->parameters)
        if (k == a) v = x;
      c.push_back(v);
    }
    c.push_back(r.status);
    const nlohmann::json& s = r.summary;
    if (s.is_object()) {
      const double particles = s.value("particles", 0.0), steps = s.value("steps", 0.0), wall = s.value("wall_time_s", 0.0);
      c.push_back(json_cell(s.value("particles", nlohmann::json())));
      c.push_back(json_cell(s.value("steps", nlohmann::json())));
      c.push_back(number(wall, 4));
      // Over the whole run, restarts included: particles x steps / the wall time of all its segments.
      c.push_back(wall > 0 ? number(particles * steps / wall, 4) : "");
      c.push_back(number(s.value("mean_neighbours", 0.0), 4));
      c.push_back(s.contains("totals") ? number(s["totals"].value("energy_drift_relative", 0.0), 3) : "");
      c.push_back(s.contains("correction_fallbacks") ? json_cell(s["correction_fallbacks"].value("particle_steps", nlohmann::json()))
                                                     : "");
      for (const std::string& o : observables)
        c.push_back(s.contains("observables") ? json_cell(s["observables"].value(o, nlohmann::json())) : "");
    } else {
      c.resize(head.size());
    }
    cells.push_back(c);
  }
  std::string csv;
  for (std::size_t k = 0; k < head.size(); ++k) csv += (k ? "," : "") + csv_field(head[k]);
  csv += "\n";
  for (const auto& c : cells) {
    for (std::size_t k = 0; k < c.size(); ++k) csv += (k ? "," : "") + csv_field(c[k]);
    csv += "\n";
  }
  write_text_atomic(out / "sweep.csv", csv);

  std::string md = "|";
  for (const std::string& h : head) md += " " + h + " |";
  md += "\n|";
  for (std::size_t k = 0; k < head.size(); ++k) md += "---|";
  md += "\n";
  for (const auto& c : cells) {
    md += "|";
    for (const std::string& x : c) md += " " + x + " |";
    md += "\n";
  }
  std::string doc = "# Sweep " + spec.name + "\n\nSweep file `" + report_path(spec.file) + "`, case `" + report_path(spec.case_file) +
                    "`, " + std::to_string(rows.size()) + " runs. Written by `impactsph sweep`; the same table is in "
                    "sweep.csv. Observables in SI units; particle_steps_per_s is particles x steps / wall time of "
                    "the whole run (restarts included).\n\n" + md;
  write_text_atomic(out / "sweep.md", doc);
  return md;
}

std::string status_text(RunState s) {
  switch (s) {
    case RunState::Complete: return "done";
    case RunState::Stopped: return "stopped";
    case RunState::Failed: return "failed";
    case RunState::Stale: return "stale";
    default: return "not run";
  }
}

std::vector<TableRow> collect_rows(const SweepSpec& spec, const fs::path& out) {
  std::vector<TableRow> rows;
  for (const SweepRun& r : spec.runs) {
    const FolderState f = folder_state(r, out / r.name);
    rows.push_back({&r, status_text(f.state), f.summary});
  }
  return rows;
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

SweepSpec load_sweep_file(const std::string& path) { return SweepReader(path).read(); }

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
