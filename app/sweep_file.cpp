// impactsph sweep, the sweep file: [sweep], [axes] and [[runs]] into a SweepSpec, every key checked with a
// message that names the file, the line and what would be valid (docs/sweeps-and-verification.md).
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <toml++/toml.h>

#include "app/run_args.hpp"
#include "app/sweep_parts.hpp"
#include "common/case_file.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"

namespace fs = std::filesystem;

namespace impactsph {
namespace sweep_detail {

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

}  // namespace sweep_detail

namespace {

using sweep_detail::name_part;

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

}  // namespace

SweepSpec load_sweep_file(const std::string& path) { return SweepReader(path).read(); }

}  // namespace impactsph
