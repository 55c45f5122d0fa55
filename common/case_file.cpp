// Case file reader: parse TOML with toml++, apply overrides to the tree, then walk the tree once,
// checking every key against the schema of docs/case-files.md and filling a CaseSpec in SI units.
// Tables are read through View, which knows the full key of what it reads so every CaseError names it.
#include "common/case_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <toml++/toml.h>

#include "common/errors.hpp"
#include "common/mesh_solid.hpp"
#include "common/units.hpp"

namespace impactsph {
namespace {

using Keys = std::vector<std::string>;

int line_of(const toml::node* n) { return n ? static_cast<int>(n->source().begin.line) : 0; }

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

std::string join(const Keys& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string join_quoted(const Keys& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "\"" : ", \"") + x + "\"";
  return s;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

// " did you mean "density"?" when one valid word is an obvious typo away (a third of its letters).
std::string did_you_mean(const std::string& word, const Keys& valid) {
  auto lower = [](std::string x) {
    for (char& c : x) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return x;
  };
  for (const std::string& v : valid)
    if (lower(v) == lower(word)) return " did you mean \"" + v + "\"?";
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const std::string& v : valid) {
    const std::size_t d = edit_distance(word, v);
    if (d < best_d) best_d = d, best = v;
  }
  if (best.empty() || best_d > std::max<std::size_t>(1, std::max(word.size(), best.size()) / 3)) return "";
  return " did you mean \"" + best + "\"?";
}

// Entries of a table in the order they are written in the file (toml::table is ordered by key).
// Entries without a source (created by an override) come last, by name.
std::vector<std::pair<std::string, const toml::node*>> in_file_order(const toml::table& t) {
  struct Entry {
    unsigned line, column;
    std::string key;
    const toml::node* node;
  };
  std::vector<Entry> entries;
  for (auto&& [k, v] : t) {
    const toml::source_position p = k.source().begin;
    entries.push_back({p.line == 0 ? ~0u : p.line, p.column, std::string(k.str()), &v});
  }
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  std::vector<std::pair<std::string, const toml::node*>> out;
  for (const Entry& e : entries) out.emplace_back(e.key, e.node);
  return out;
}

// Builds CaseErrors: knows the file and which nodes came from overrides, so a message about an overridden
// value says where it came from (its line is 0).
class Reporter {
 public:
  explicit Reporter(std::string file) : file_(std::move(file)) {}
  [[noreturn]] void fail(const toml::node* at, const std::string& key, const std::string& message) const {
    std::string m = message;
    if (at) {
      const auto it = origin_.find(at);
      if (it != origin_.end()) m += " (set by " + it->second + ")";
    }
    // A value read from a material file (materials.NAME.file) names that file.
    const std::string file = at && at->source().path && !at->source().path->empty() ? *at->source().path : file_;
    throw CaseError(file, line_of(at), key, m);
  }
  void mark(const toml::node* n, const std::string& origin) { origin_[n] = origin; }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::map<const toml::node*, std::string> origin_;
};

// Reading of single values, given the node and its full key.
class Values {
 public:
  explicit Values(const Reporter& r) : r_(r) {}

  double quantity(const toml::node& n, const std::string& key, Dimension d) const {
    if (const auto* s = n.as_string()) {
      try {
        return parse_quantity(s->get(), d);
      } catch (const std::invalid_argument& e) {
        r_.fail(&n, key, e.what());
      }
    }
    if (n.is_integer() || n.is_floating_point()) {
      const double v = n.value<double>().value_or(0.0);
      if (!std::isfinite(v)) r_.fail(&n, key, "must be a finite number");
      return v;
    }
    if (d == Dimension::Dimensionless)
      r_.fail(&n, key, "expected a number such as " + dimension_example(d) + ", not " + type_name(n));
    r_.fail(&n, key,
            "expected a " + dimension_name(d) + " such as \"" + dimension_example(d) +
                "\" (a string with a unit, or a bare number in SI), not " + type_name(n));
  }

  Vec3d vec3(const toml::node& n, const std::string& key, Dimension d) const {
    const std::string ex = d == Dimension::Dimensionless
                               ? "[0, 0, -1]"
                               : "[\"0 " + unit_of(d) + "\", \"0 " + unit_of(d) + "\", \"1 " + unit_of(d) + "\"]";
    const auto* a = n.as_array();
    if (!a) r_.fail(&n, key, "expected an array of 3 " + plural(d) + " (x, y, z) such as " + ex + ", not " + type_name(n));
    if (a->size() != 3)
      r_.fail(&n, key, "has " + std::to_string(a->size()) + " entries; expected 3 " + plural(d) + " (x, y, z) such as " + ex);
    Vec3d v{0, 0, 0};
    for (int i = 0; i < 3; ++i) v[i] = quantity(*a->get(i), key + "[" + std::to_string(i) + "]", d);
    return v;
  }

  std::string string(const toml::node& n, const std::string& key, const std::string& example) const {
    if (const auto* s = n.as_string()) return s->get();
    r_.fail(&n, key, "expected a string such as " + example + ", not " + type_name(n));
  }

  bool boolean(const toml::node& n, const std::string& key) const {
    if (const auto* b = n.as_boolean()) return b->get();
    r_.fail(&n, key, "expected true or false, not " + type_name(n));
  }

  const Reporter& reporter() const { return r_; }

 private:
  static std::string unit_of(Dimension d) {
    const std::string ex = dimension_example(d);
    return ex.substr(ex.find(' ') + 1);
  }
  static std::string plural(Dimension d) {
    switch (d) {
      case Dimension::Dimensionless: return "numbers";
      case Dimension::Velocity: return "velocities";
      default: return dimension_name(d) + "s";
    }
  }
  const Reporter& r_;
};

// A table being read: its full key (`materials.steel.eos`), what it is for messages ("the EOS of a
// material") and typed accessors whose errors name the full key of the entry.
class View {
 public:
  View(const Reporter& r, const toml::table& t, std::string path, std::string what)
      : r_(r), v_(r), t_(t), path_(std::move(path)), what_(std::move(what)) {}

  const toml::table& table() const { return t_; }
  std::string key(const std::string& k) const { return path_.empty() ? k : path_ + "." + k; }
  const toml::node* find(const std::string& k) const { return t_.get(k); }
  bool has(const std::string& k) const { return find(k) != nullptr; }

  [[noreturn]] void fail(const std::string& k, const std::string& message) const {
    const toml::node* n = find(k);
    r_.fail(n ? n : &t_, key(k), message);
  }
  [[noreturn]] void fail_here(const std::string& message) const { r_.fail(&t_, path_, message); }
  // Reported at the line of the table that lacks the key; the root table has no line of its own.
  [[noreturn]] void missing(const std::string& k, const std::string& hint) const {
    r_.fail(path_.empty() ? nullptr : &t_, key(k), "missing in " + what_ + "; " + hint);
  }

  // Every key of the table must be one of `valid`.
  void allow(const Keys& valid) const {
    for (const auto& [k, n] : in_file_order(t_)) {
      if (std::find(valid.begin(), valid.end(), k) != valid.end()) continue;
      r_.fail(n, key(k), "unknown key \"" + k + "\" in " + what_ + ";" + did_you_mean(k, valid) +
                             " valid keys: " + join(valid));
    }
  }

  double quantity(const std::string& k, Dimension d) const {
    const toml::node* n = find(k);
    if (!n) missing(k, "expected a " + dimension_name(d) + " such as \"" + dimension_example(d) + "\"");
    return v_.quantity(*n, key(k), d);
  }
  double quantity_or(const std::string& k, Dimension d, double fallback) const {
    const toml::node* n = find(k);
    return n ? v_.quantity(*n, key(k), d) : fallback;
  }
  double number(const std::string& k) const { return quantity(k, Dimension::Dimensionless); }
  double number_or(const std::string& k, double fallback) const {
    return quantity_or(k, Dimension::Dimensionless, fallback);
  }

  Vec3d vec3(const std::string& k, Dimension d) const {
    const toml::node* n = find(k);
    if (!n) missing(k, "expected an array of 3 values (x, y, z) such as [\"0 mm\", \"0 mm\", \"8 mm\"]");
    return v_.vec3(*n, key(k), d);
  }

  std::string string(const std::string& k, const std::string& example) const {
    const toml::node* n = find(k);
    if (!n) missing(k, "expected a string such as " + example);
    return v_.string(*n, key(k), example);
  }
  std::string string_or(const std::string& k, const std::string& fallback) const {
    const toml::node* n = find(k);
    return n ? v_.string(*n, key(k), "\"" + fallback + "\"") : fallback;
  }
  bool boolean_or(const std::string& k, bool fallback) const {
    const toml::node* n = find(k);
    return n ? v_.boolean(*n, key(k)) : fallback;
  }

  // A string that must be one of `valid`; `fallback` empty means the key is required.
  std::string choice(const std::string& k, const Keys& valid, const std::string& fallback = "") const {
    const toml::node* n = find(k);
    if (!n && !fallback.empty()) return fallback;
    if (!n) missing(k, "expected one of " + join_quoted(valid));
    const std::string s = v_.string(*n, key(k), join_quoted(valid));
    if (std::find(valid.begin(), valid.end(), s) == valid.end())
      fail(k, "unknown " + k + " \"" + s + "\";" + did_you_mean(s, valid) + " valid: " + join_quoted(valid));
    return s;
  }

  int axis(const std::string& k) const {
    const std::string a = choice(k, {"x", "y", "z"});
    return a[0] - 'x';
  }

  View sub(const std::string& k, const std::string& what, const std::string& example) const {
    const toml::node* n = find(k);
    if (!n) missing(k, "expected a table such as " + example);
    if (!n->is_table()) fail(k, "expected a table such as " + example + ", not " + type_name(*n));
    return View(r_, *n->as_table(), key(k), what);
  }

  // Range checks; `d` formats the bounds and the value in messages.
  void positive(const std::string& k, double v, Dimension d) const {
    if (!(v > 0)) fail(k, "must be greater than zero (got " + format_quantity(v, d) + ")");
  }
  void non_negative(const std::string& k, double v, Dimension d) const {
    if (!(v >= 0)) fail(k, "must not be negative (got " + format_quantity(v, d) + ")");
  }
  // lo < v <= hi (open_lo) or lo <= v <= hi; open_hi makes the upper bound exclusive.
  void range(const std::string& k, double v, double lo, double hi, Dimension d, bool open_lo = false,
             bool open_hi = false, const std::string& why = "") const {
    const bool ok = (open_lo ? v > lo : v >= lo) && (open_hi ? v < hi : v <= hi);
    if (ok) return;
    fail(k, std::string("must be ") + (open_lo ? "greater than " : "at least ") + format_quantity(lo, d) + " and " +
                (open_hi ? "less than " : "at most ") + format_quantity(hi, d) + " (got " + format_quantity(v, d) + ")" +
                (why.empty() ? "" : "; " + why));
  }

  const Values& values() const { return v_; }

 private:
  const Reporter& r_;
  Values v_;
  const toml::table& t_;
  std::string path_, what_;
};

constexpr double GPa = 1e9;
constexpr double kMaxModulus = 2000 * GPa;  // above every solid's modulus (diamond: ~1100 GPa)
// Below the shear modulus of soft rubber (~0.3 MPa) and any yield stress of a metal: catches a bare number
// meant in GPa or MPa but read in Pa.
constexpr double kMinModulus = 0.1e6;
const char* const kModulusHint = "a bare number is in Pa, write units as in \"200 GPa\"";

// Names are used by overrides as NAME.key, so they must not hold the override syntax.
void check_name(const Reporter& r, const toml::node* at, const std::string& key, const std::string& name) {
  if (name.empty()) r.fail(at, key, "must not be empty");
  for (const char c : name)
    if (c == '.' || c == '=' || c == '[' || c == ']' || c == '"' || std::isspace(static_cast<unsigned char>(c)))
      r.fail(at, key,
             "\"" + name + "\" may not contain '.', '=', brackets, quotes or spaces (overrides address it as " +
                 "NAME.key); use letters, digits, '-' and '_'");
}

// ---------------------------------------------------------------------------------------------------
// Materials

const Keys kEosKinds{"linear", "polynomial", "mie-gruneisen", "gruneisen-cubic"};
const Keys kStrengthKinds{"hydrodynamic", "elastic", "perfectly-plastic", "johnson-cook", "johnson-holmquist-2"};
// What the pairs of a failed particle carry (DamageParams::compressive_crack_faces).
const Keys kCrackFaces{"scaled", "compression"};
const Keys kDamageKinds{"none", "critical-plastic-strain", "fracture-energy", "johnson-cook", "johnson-holmquist-2"};

void read_eos(const View& e, EosParams<double>& p, bool& needs_bulk_modulus) {
  const std::string kind = e.choice("kind", kEosKinds);
  needs_bulk_modulus = false;
  if (e.has("min_pressure")) {
    p.min_pressure = e.quantity("min_pressure", Dimension::Pressure);
    e.range("min_pressure", p.min_pressure, -kMaxModulus, 0, Dimension::Pressure, false, false,
            "the pressure cutoff is the largest tension the material carries, a negative pressure such as "
            "\"-1.2 GPa\" (0: no tension)");
  }
  auto modulus = [&](const std::string& k) {
    const double v = e.quantity(k, Dimension::Pressure);
    e.range(k, v, kMinModulus, kMaxModulus, Dimension::Pressure, false, false, kModulusHint);
    return v;
  };
  auto coefficient = [&](const std::string& k) {
    const double v = e.quantity_or(k, Dimension::Pressure, 0.0);
    e.range(k, v, -kMaxModulus, kMaxModulus, Dimension::Pressure);
    return v;
  };
  auto c0 = [&]() {
    const double v = e.quantity("c0", Dimension::Velocity);
    e.range("c0", v, 0, 20000, Dimension::Velocity, true, false, "c0 is the bulk sound speed");
    return v;
  };
  auto gamma0 = [&]() {
    const double v = e.number("gamma0");
    e.range("gamma0", v, 0, 5, Dimension::Dimensionless);
    return v;
  };
  auto slope = [&](const std::string& k) {
    const double v = e.number(k);
    e.range(k, v, 0.5, 5, Dimension::Dimensionless, false, false, "the slope of the linear Us-up Hugoniot");
    return v;
  };
  if (kind == "linear") {
    e.allow({"kind", "bulk_modulus", "min_pressure"});
    p.kind = EosKind::Linear;
    if (e.has("bulk_modulus")) p.k1 = modulus("bulk_modulus");
    else needs_bulk_modulus = true;  // may come from youngs_modulus + poisson_ratio in the strength table
  } else if (kind == "polynomial") {
    e.allow({"kind", "k1", "k2", "k3", "min_pressure"});
    p.kind = EosKind::Polynomial;
    p.k1 = modulus("k1");
    p.k2 = coefficient("k2");
    p.k3 = coefficient("k3");
  } else if (kind == "mie-gruneisen") {
    e.allow({"kind", "c0", "s", "gamma0", "min_pressure"});
    p.kind = EosKind::MieGruneisen;
    p.c0 = c0();
    p.s1 = slope("s");
    p.gamma0 = gamma0();
  } else {
    e.allow({"kind", "c0", "s1", "s2", "s3", "gamma0", "a", "min_pressure"});
    p.kind = EosKind::GruneisenCubic;
    p.c0 = c0();
    p.s1 = slope("s1");
    p.s2 = e.number_or("s2", 0.0);
    e.range("s2", p.s2, -20, 20, Dimension::Dimensionless);
    p.s3 = e.number_or("s3", 0.0);
    e.range("s3", p.s3, -20, 20, Dimension::Dimensionless);
    p.gamma0 = gamma0();
    p.a = e.number_or("a", 0.0);
    e.range("a", p.a, -5, 5, Dimension::Dimensionless);
  }
}

// A stress that must be between kMinModulus and kMaxModulus (a bare number is in Pa).
double stress(const View& s, const std::string& k, const std::string& extra_hint = "") {
  const double v = s.quantity(k, Dimension::Pressure);
  s.range(k, v, kMinModulus, kMaxModulus, Dimension::Pressure, false, false, kModulusHint + extra_hint);
  return v;
}

// The Johnson-Cook flow stress constants (F 3.12-3.13) of a strength table of kind "johnson-cook".
void read_johnson_cook(const View& s, StrengthParams<double>& p) {
  p.jc_a = stress(s, "a", "; A is the yield stress at zero plastic strain");
  p.jc_b = s.quantity("b", Dimension::Pressure);
  if (p.jc_b != 0)  // B = 0 (no hardening) is valid; a small non-zero B is a bare number meant in MPa
    s.range("b", p.jc_b, kMinModulus, kMaxModulus, Dimension::Pressure, false, false,
            std::string(kModulusHint) + "; b = 0 means no strain hardening");
  p.jc_n = p.jc_b > 0 ? s.number("n") : s.number_or("n", 1.0);  // n is needed only with hardening
  s.range("n", p.jc_n, 0, 2, Dimension::Dimensionless, true);
  p.jc_c = s.number_or("c", 0.0);
  s.range("c", p.jc_c, 0, 1, Dimension::Dimensionless);
  p.jc_m = s.number_or("m", 1.0);
  s.range("m", p.jc_m, 0, 5, Dimension::Dimensionless, true);
  p.reference_strain_rate = s.quantity_or("reference_strain_rate", Dimension::StrainRate, 1.0);
  s.positive("reference_strain_rate", p.reference_strain_rate, Dimension::StrainRate);
  p.melt_temperature = 0;  // 0: no thermal softening; checked against room_temperature by read_material
  if (s.has("melt_temperature")) {
    p.melt_temperature = s.quantity("melt_temperature", Dimension::Temperature);
    s.positive("melt_temperature", p.melt_temperature, Dimension::Temperature);
  }
  p.taylor_quinney = s.number_or("taylor_quinney", 0.9);
  s.range("taylor_quinney", p.taylor_quinney, 0, 1, Dimension::Dimensionless, false, false,
          "the fraction of plastic work that heats the material");
}

// The JH-2 strength constants (X eqs 22-24, Table 1) of a strength table of kind "johnson-holmquist-2".
void read_jh2_strength(const View& s, StrengthParams<double>& p) {
  const std::string norm = "a normalised JH-2 constant (dimensionless; X Table 1)";
  p.jh_a = s.number("a");
  s.range("a", p.jh_a, 0, 5, Dimension::Dimensionless, true, false, norm);
  p.jh_b = s.number("b");
  s.range("b", p.jh_b, 0, 5, Dimension::Dimensionless, false, false, norm);
  p.jh_n = s.number("n");
  s.range("n", p.jh_n, 0, 2, Dimension::Dimensionless, true, false, norm);
  p.jh_m = s.number("m");
  s.range("m", p.jh_m, 0, 2, Dimension::Dimensionless, true, false, norm);
  p.jh_c = s.number_or("c", 0.0);
  s.range("c", p.jh_c, 0, 1, Dimension::Dimensionless, false, false, norm);
  p.hel = stress(s, "hel", "; the Hugoniot elastic limit, e.g. \"2.79 GPa\"");
  p.p_hel = stress(s, "p_hel", "; the pressure at the HEL, e.g. \"1.46 GPa\"");
  if (!(p.p_hel < p.hel))
    s.fail("p_hel", "must be less than hel = " + format_quantity(p.hel, Dimension::Pressure) + " (got " +
                        format_quantity(p.p_hel, Dimension::Pressure) + "): HEL = P_HEL + 2/3 sigma_HEL with sigma_HEL > 0");
  p.tensile_pressure = stress(s, "tensile_strength", "; T, the largest hydrostatic tension, e.g. \"0.2 GPa\"");
  p.sfmax = s.number_or("sfmax", 1e30);
  s.range("sfmax", p.sfmax, 0, 1e30, Dimension::Dimensionless, true, false,
          "the cap of the normalised fractured strength; leave it out for no cap");
  p.reference_strain_rate = s.quantity_or("reference_strain_rate", Dimension::StrainRate, 1.0);
  s.positive("reference_strain_rate", p.reference_strain_rate, Dimension::StrainRate);
}

// Returns the bulk modulus E/(3(1-2nu)) when the elastic constants were given as E and nu, else 0.
double read_strength(const View& s, StrengthParams<double>& p) {
  const std::string kind = s.choice("kind", kStrengthKinds);
  if (kind == "hydrodynamic") {
    s.allow({"kind"});
    p.kind = StrengthKind::Hydrodynamic;
    return 0;
  }
  if (kind == "elastic") {
    s.allow({"kind", "shear_modulus", "youngs_modulus", "poisson_ratio"});
    p.kind = StrengthKind::Elastic;
  } else if (kind == "perfectly-plastic") {
    s.allow({"kind", "shear_modulus", "youngs_modulus", "poisson_ratio", "yield_stress"});
    p.kind = StrengthKind::PerfectlyPlastic;
    p.yield_stress = stress(s, "yield_stress", "; a material without strength is kind = \"hydrodynamic\"");
  } else if (kind == "johnson-cook") {
    s.allow({"kind", "shear_modulus", "youngs_modulus", "poisson_ratio", "a", "b", "n", "c", "m",
             "reference_strain_rate", "melt_temperature", "taylor_quinney"});
    p.kind = StrengthKind::JohnsonCook;
  } else {
    s.allow({"kind", "shear_modulus", "youngs_modulus", "poisson_ratio", "a", "b", "c", "m", "n", "hel", "p_hel",
             "tensile_strength", "sfmax", "reference_strain_rate"});
    p.kind = StrengthKind::JohnsonHolmquist2;
  }
  const bool has_g = s.has("shear_modulus"), has_e = s.has("youngs_modulus"), has_nu = s.has("poisson_ratio");
  if (has_g && (has_e || has_nu))
    s.fail(has_e ? "youngs_modulus" : "poisson_ratio",
           "give either shear_modulus or youngs_modulus + poisson_ratio, not both");
  double derived_k = 0;
  if (has_g) {
    p.shear_modulus = stress(s, "shear_modulus");
  } else {
    if (!has_e && !has_nu)
      s.missing("shear_modulus", "expected shear_modulus = \"80 GPa\", or youngs_modulus = \"200 GPa\" with "
                                 "poisson_ratio = 0.3");
    if (!has_e) s.missing("youngs_modulus", "poisson_ratio needs youngs_modulus, e.g. \"200 GPa\"");
    if (!has_nu) s.missing("poisson_ratio", "youngs_modulus needs poisson_ratio, e.g. 0.3");
    const double E = stress(s, "youngs_modulus");
    const double nu = s.number("poisson_ratio");
    s.range("poisson_ratio", nu, -1, 0.5, Dimension::Dimensionless, true, true);
    p.shear_modulus = E / (2 * (1 + nu));
    derived_k = E / (3 * (1 - 2 * nu));
  }
  if (p.kind == StrengthKind::JohnsonCook) read_johnson_cook(s, p);
  if (p.kind == StrengthKind::JohnsonHolmquist2) read_jh2_strength(s, p);
  return derived_k;
}

// The damage table; `strength` is the strength table, named when damage needs plasticity it lacks.
void read_damage(const View& d, const StrengthParams<double>& strength, DamageParams<double>& p) {
  const std::string kind = d.choice("kind", kDamageKinds);
  if (kind == "none") {
    d.allow({"kind"});
    p.kind = DamageKind::None;
    return;
  }
  if (kind == "johnson-holmquist-2") {
    if (strength.kind != StrengthKind::JohnsonHolmquist2)
      d.fail("kind", "damage kind \"johnson-holmquist-2\" needs strength kind \"johnson-holmquist-2\" (its "
                     "failure strain uses the strength's p_hel and tensile_strength, X eq 26)");
    d.allow({"kind", "d1", "d2", "min_failure_strain", "bulking", "pair_factor"});
    p.kind = DamageKind::JohnsonHolmquist2;
    p.d1 = d.number("d1");
    d.range("d1", p.d1, 0, 1, Dimension::Dimensionless, true, false, "D1 of eps_f = D1 (P* + T*)^D2 (X eq 26)");
    p.d2 = d.number("d2");
    d.range("d2", p.d2, 0, 5, Dimension::Dimensionless, false, false, "D2 of eps_f = D1 (P* + T*)^D2 (X eq 26)");
    p.min_failure_strain = d.number_or("min_failure_strain", 0.0);
    d.range("min_failure_strain", p.min_failure_strain, 0, 10, Dimension::Dimensionless);
    p.bulking = d.number_or("bulking", 0.0);
    d.range("bulking", p.bulking, 0, 1, Dimension::Dimensionless, false, false,
            "beta, the fraction of lost elastic energy converted to pressure (X eq 28)");
    p.scale_pairs = d.boolean_or("pair_factor", false);  // JH-2 carries damage in its strength (X eq 22)
    return;
  }
  if (strength.kind != StrengthKind::JohnsonCook && strength.kind != StrengthKind::PerfectlyPlastic)
    d.fail("kind", "damage kind \"" + kind + "\" accumulates plastic strain, but the strength kind \"" +
                       (strength.kind == StrengthKind::Elastic ? "elastic" : strength.kind == StrengthKind::Hydrodynamic
                                                                              ? "hydrodynamic"
                                                                              : "johnson-holmquist-2") +
                       "\" has no plasticity of that kind; use strength kind \"johnson-cook\" or \"perfectly-plastic\", "
                       "or damage kind \"none\"");
  p.scale_pairs = d.boolean_or("pair_factor", true);
  p.compressive_crack_faces = d.choice("crack_faces", kCrackFaces, "scaled") == "compression";
  if (p.compressive_crack_faces && !p.scale_pairs)
    d.fail("crack_faces", "crack_faces = \"compression\" acts on the pairs of failed particles, which "
                          "pair_factor = false leaves unscaled and unfailed; set pair_factor = true or drop crack_faces");
  if (kind == "critical-plastic-strain") {
    d.allow({"kind", "critical_plastic_strain", "pair_factor", "crack_faces"});
    p.kind = DamageKind::CriticalPlasticStrain;
    p.critical_plastic_strain = d.number("critical_plastic_strain");
    d.range("critical_plastic_strain", p.critical_plastic_strain, 0, 10, Dimension::Dimensionless, true);
    return;
  }
  if (kind == "fracture-energy") {
    d.allow({"kind", "fracture_energy", "band_width_factor", "pair_factor", "crack_faces"});
    p.kind = DamageKind::FractureEnergy;
    p.fracture_energy = d.quantity("fracture_energy", Dimension::FractureEnergy);
    d.range("fracture_energy", p.fracture_energy, 0, 1e8, Dimension::FractureEnergy, true, false,
            "Gamma, the plastic work per unit crack area at failure (damage.hpp)");
    p.band_width_factor = d.number("band_width_factor");
    d.range("band_width_factor", p.band_width_factor, 0.5, 20, Dimension::Dimensionless, false, false,
            "the width of the failing band in initial smoothing lengths h0 = h_factor x spacing");
    return;
  }
  d.allow({"kind", "d1", "d2", "d3", "d4", "d5", "min_failure_strain", "pair_factor", "crack_faces"});
  p.kind = DamageKind::JohnsonCook;
  const std::string why = "the Johnson-Cook failure constants are at most 20 in magnitude";
  p.d1 = d.number("d1");
  d.range("d1", p.d1, -1, 20, Dimension::Dimensionless, false, false, why);
  p.d2 = d.number("d2");
  d.range("d2", p.d2, 0, 20, Dimension::Dimensionless, false, false, why);
  p.d3 = d.number("d3");
  d.range("d3", p.d3, -20, 20, Dimension::Dimensionless, false, false, why);
  p.d4 = d.number_or("d4", 0.0);
  d.range("d4", p.d4, -20, 20, Dimension::Dimensionless, false, false, why);
  p.d5 = d.number_or("d5", 0.0);
  d.range("d5", p.d5, -20, 20, Dimension::Dimensionless, false, false, why);
  p.min_failure_strain = d.number_or("min_failure_strain", 0.0);
  d.range("min_failure_strain", p.min_failure_strain, 0, 10, Dimension::Dimensionless);
}

MaterialSpec read_material(const View& m, const std::string& name) {
  m.allow({"density", "eos", "strength", "damage", "specific_heat", "room_temperature"});
  MaterialSpec out;
  out.name = name;
  out.line = line_of(&m.table());
  MaterialParams<double>& p = out.params;
  p.eos.rho0 = m.quantity("density", Dimension::Density);
  m.range("density", p.eos.rho0, 1, 30000, Dimension::Density);

  bool needs_bulk_modulus = false;
  const View eos = m.sub("eos", "the EOS of a material", "{ kind = \"linear\", bulk_modulus = \"160 GPa\" }");
  read_eos(eos, p.eos, needs_bulk_modulus);
  const View strength =
      m.sub("strength", "the strength model of a material", "{ kind = \"elastic\", shear_modulus = \"80 GPa\" }");
  const double derived_k = read_strength(strength, p.strength);
  if (needs_bulk_modulus) {
    if (derived_k <= 0)
      eos.missing("bulk_modulus", "a linear EOS needs bulk_modulus = \"160 GPa\" (or youngs_modulus and "
                                    "poisson_ratio in the strength table, from which K = E/(3(1-2nu)))");
    p.eos.k1 = derived_k;
    if (p.eos.k1 > kMaxModulus)
      strength.fail("poisson_ratio", "gives a bulk modulus E/(3(1-2nu)) of " + format_quantity(p.eos.k1, Dimension::Pressure) +
                                         ", above " + format_quantity(kMaxModulus, Dimension::Pressure) + "; give bulk_modulus");
  }

  if (m.has("damage")) {
    const View d = m.sub("damage", "the damage model of a material", "{ kind = \"none\" }");
    read_damage(d, p.strength, p.damage);
  }
  if (m.has("specific_heat")) {
    p.specific_heat = m.quantity("specific_heat", Dimension::SpecificHeat);
    m.range("specific_heat", p.specific_heat, 0, 1e5, Dimension::SpecificHeat, true);
  }
  p.room_temperature = m.quantity_or("room_temperature", Dimension::Temperature, 293.0);
  m.range("room_temperature", p.room_temperature, 0, 5000, Dimension::Temperature, true);
  if (p.strength.melt_temperature > 0) {
    if (!(p.strength.melt_temperature > p.room_temperature))
      strength.fail("melt_temperature", "must be above room_temperature = " +
                                            format_quantity(p.room_temperature, Dimension::Temperature) + " (got " +
                                            format_quantity(p.strength.melt_temperature, Dimension::Temperature) + ")");
    if (!(p.specific_heat > 0))
      m.missing("specific_heat", "Johnson-Cook thermal softening (strength.melt_temperature) needs the temperature, "
                                 "which plastic work raises by way of specific_heat = \"452 J/(kg K)\"; give it, or "
                                 "leave out melt_temperature to turn thermal softening off");
  }
  return out;
}

std::vector<MaterialSpec> read_materials(const View& root) {
  const std::string example = "[materials.steel] with density, eos and strength";
  const toml::node* n = root.find("materials");
  if (!n) root.missing("materials", "expected one table per material, such as " + example);
  if (!n->is_table())
    root.fail("materials", "expected one table per material, such as " + example + ", not " + type_name(*n));
  const View all(root.values().reporter(), *n->as_table(), "materials", "materials");
  std::vector<MaterialSpec> out;
  for (const auto& [name, node] : in_file_order(all.table())) {
    check_name(root.values().reporter(), node, all.key(name), name);
    if (!node->is_table())
      all.fail(name, "expected a table of material constants such as " + example + ", not " + type_name(*node));
    out.push_back(read_material(View(root.values().reporter(), *node->as_table(), all.key(name), "a material"), name));
  }
  if (out.empty()) all.fail_here("no material is defined; expected " + example);
  return out;
}

// ---------------------------------------------------------------------------------------------------
// Bodies and boundaries

const Keys kShapes{"box", "cylinder", "disk", "plate", "sphere", "mesh"};
const Keys kBoxKeys{"min", "max"};
const Keys kCylinderKeys{"base", "axis", "radius", "length", "nose"};
const Keys kNoseKinds{"flat", "hemispherical", "conical", "ogival"};
const Keys kSphereKeys{"center", "radius"};
const Keys kMeshKeys{"file", "mesh_unit", "origin"};
// Units a mesh file's coordinates may be in, and metres per unit.
const std::vector<std::pair<std::string, double>> kMeshUnits{
    {"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}, {"um", 1e-6}, {"in", 0.0254}};

void read_box(const View& v, Vec3d& lo, Vec3d& hi) {
  lo = v.vec3("min", Dimension::Length);
  hi = v.vec3("max", Dimension::Length);
  for (int i = 0; i < 3; ++i)
    if (!(hi[i] > lo[i]))
      v.fail("max", "max[" + std::to_string(i) + "] = " + format_quantity(hi[i], Dimension::Length) +
                        " must be greater than min[" + std::to_string(i) + "] = " + format_quantity(lo[i], Dimension::Length));
}

// A cylinder's nose (BodySpec::nose): { kind = "conical", length = "17.3 mm", at = "base" }; `at` is the end
// the nose replaces, "base" (the face at `base`) or "top" (base + length along the axis). The nose is part
// of the cylinder's length.
void read_nose(const View& n, BodySpec& body) {
  const std::string kind = n.choice("kind", kNoseKinds);
  if (kind == "flat") {
    n.allow({"kind"});
    return;
  }
  const std::string at = n.choice("at", {"base", "top"});
  body.nose_at_base = at == "base";
  const double r = body.radius;
  if (kind == "hemispherical") {
    n.allow({"kind", "at"});
    body.nose = Nose::Hemispherical;
    body.nose_length = r;
  } else if (kind == "conical") {
    n.allow({"kind", "at", "length"});
    body.nose = Nose::Conical;
    body.nose_length = n.quantity("length", Dimension::Length);
    n.positive("length", body.nose_length, Dimension::Length);
  } else {
    n.allow({"kind", "at", "crh"});
    body.nose = Nose::Ogival;
    body.nose_crh = n.number("crh");
    // crh = 0.5 is the hemisphere; below it the tangent ogive does not close.
    n.range("crh", body.nose_crh, 0.5, 100, Dimension::Dimensionless, false, false,
            "the calibre-radius-head of a tangent ogive, its radius over the diameter (0.5: a hemisphere; "
            "projectiles use 1.5 to 6)");
    body.nose_length = r * std::sqrt(4 * body.nose_crh - 1);
  }
  if (!(body.nose_length <= body.length))
    n.fail(kind == "conical" ? "length" : "kind",
           "the " + kind + " nose is " + format_quantity(body.nose_length, Dimension::Length) +
               " long, longer than the cylinder (length = " + format_quantity(body.length, Dimension::Length) +
               "), which includes its nose; lengthen the cylinder or shorten the nose");
}

// A body from a closed surface mesh: file = "nose.stl" (relative to the case file's folder), mesh_unit =
// the unit of its coordinates (required: a CAD export carries none), origin = where the file's origin
// lies in the case (default the case's origin). The file is read and checked here, so that `check` finds a
// bad mesh and the message names the key.
void read_mesh(const View& b, BodySpec& body) {
  body.mesh_file = b.string("file", "\"nose.stl\"");
  Keys unit_names;
  for (const auto& [name, metres] : kMeshUnits) unit_names.push_back(name);
  if (!b.has("mesh_unit"))
    b.missing("mesh_unit", "a mesh file's coordinates carry no unit; give mesh_unit = one of " + join_quoted(unit_names));
  const std::string unit = b.choice("mesh_unit", unit_names);
  double metres = 1;
  for (const auto& [name, m] : kMeshUnits)
    if (name == unit) metres = m;
  const Vec3d origin = b.has("origin") ? b.vec3("origin", Dimension::Length) : Vec3d{0, 0, 0};
  namespace fs = std::filesystem;
  fs::path path(body.mesh_file);
  if (path.is_relative()) path = fs::path(b.values().reporter().file()).parent_path() / path;
  try {
    body.mesh = MeshSolid::read(path.string(), metres, origin);
  } catch (const MeshError& e) {
    b.fail("file", std::string(e.what()) + (body.mesh_file != path.string() ? " (a relative file is read from the case "
                                                                              "file's folder)" : ""));
  }
}

void read_velocity(const View& b, BodySpec& body) {
  const toml::node* v = b.find("velocity");
  const toml::node* dir = b.find("direction");
  if (!v) {
    if (dir) b.fail("direction", "direction needs velocity = a speed such as \"298 m/s\"");
    return;
  }
  if (v->is_array()) {
    if (dir) b.fail("direction", "give velocity as a 3-vector, or as a speed with a direction, not both");
    body.velocity = b.vec3("velocity", Dimension::Velocity);
    return;
  }
  const double speed = b.quantity("velocity", Dimension::Velocity);
  if (speed < 0) b.fail("velocity", "a speed must not be negative (got " + format_quantity(speed, Dimension::Velocity) +
                                        "); reverse the direction instead");
  if (!dir)
    b.missing("direction", "velocity given as a speed needs direction = [0, 0, -1] (or give velocity as a vector "
                           "such as [\"0 m/s\", \"0 m/s\", \"-298 m/s\"])");
  const Vec3d d = b.vec3("direction", Dimension::Dimensionless);
  const double len = norm(d);
  if (!(len > 0)) b.fail("direction", "must not be the zero vector");
  body.velocity = (speed / len) * d;
}

BodySpec read_body(const View& b, const std::vector<MaterialSpec>& materials) {
  BodySpec body;
  const Reporter& r = b.values().reporter();
  body.name = b.string("name", "\"projectile\"");
  check_name(r, b.find("name"), b.key("name"), body.name);
  const std::string shape = b.choice("shape", kShapes);
  const Keys common{"name", "material", "shape", "velocity", "direction", "variable_h", "h_min", "h_max"};
  const bool is_box = shape == "box", is_sphere = shape == "sphere", is_mesh = shape == "mesh";
  const Keys& own = is_box ? kBoxKeys : (is_sphere ? kSphereKeys : (is_mesh ? kMeshKeys : kCylinderKeys));
  Keys valid = common;
  valid.insert(valid.end(), own.begin(), own.end());
  // A key of another shape (a sphere given an axis, a box given a radius) is named as such, before the
  // generic unknown-key message of allow(), so the fix is plain.
  const char* const own_name = is_box ? "box" : (is_sphere ? "sphere" : (is_mesh ? "mesh" : "cylinder"));
  for (const auto& [k, n] : in_file_order(b.table())) {
    if (std::find(valid.begin(), valid.end(), k) != valid.end()) continue;
    std::string owners;
    for (const auto& [other, keys] : {std::pair<const char*, const Keys*>{"box", &kBoxKeys},
                                      {"cylinder", &kCylinderKeys}, {"sphere", &kSphereKeys},
                                      {"mesh", &kMeshKeys}})
      if (std::find(keys->begin(), keys->end(), k) != keys->end())
        owners += std::string(owners.empty() ? "a " : " or a ") + other;
    if (!owners.empty())
      r.fail(n, b.key(k), "\"" + k + "\" is a key of " + owners + ", not of a " + own_name + " (shape = \"" + shape +
                             "\"); valid keys: " + join(valid));
  }
  b.allow(valid);

  Keys names;
  for (const MaterialSpec& m : materials) names.push_back(m.name);
  body.material = b.string("material", names.empty() ? "\"steel\"" : "\"" + names[0] + "\"");
  const auto it = std::find(names.begin(), names.end(), body.material);
  if (it == names.end())
    b.fail("material", "no material named \"" + body.material + "\";" + did_you_mean(body.material, names) +
                           " defined materials: " + join_quoted(names));
  body.material_index = static_cast<int>(it - names.begin());

  if (is_box) {
    body.shape = Shape::Box;
    read_box(b, body.box_min, body.box_max);
  } else if (is_mesh) {
    body.shape = Shape::Mesh;
    read_mesh(b, body);
  } else if (is_sphere) {
    body.shape = Shape::Sphere;
    body.center = b.vec3("center", Dimension::Length);
    body.radius = b.quantity("radius", Dimension::Length);
    b.positive("radius", body.radius, Dimension::Length);
  } else {
    body.shape = Shape::Cylinder;
    body.base = b.vec3("base", Dimension::Length);
    body.axis = b.axis("axis");
    body.radius = b.quantity("radius", Dimension::Length);
    b.positive("radius", body.radius, Dimension::Length);
    body.length = b.quantity("length", Dimension::Length);
    b.positive("length", body.length, Dimension::Length);
    if (b.has("nose"))
      read_nose(b.sub("nose", "the nose of a cylinder", "{ kind = \"hemispherical\", at = \"base\" }"), body);
  }
  read_velocity(b, body);
  // Variable smoothing length (X eqs 9-10): bounds as factors of the initial h (X: HMIN 0.2, HMAX 2.0).
  body.variable_h = b.boolean_or("variable_h", false);
  for (const char* k : {"h_min", "h_max"})
    if (!body.variable_h && b.has(k))
      b.fail(k, std::string(k) + " bounds a variable smoothing length; it needs variable_h = true");
  body.h_min_factor = b.number_or("h_min", 0.2);
  b.range("h_min", body.h_min_factor, 0, 1, Dimension::Dimensionless, true, false,
          "HMIN of X eq 10, a factor of the initial smoothing length");
  body.h_max_factor = b.number_or("h_max", 2.0);
  b.range("h_max", body.h_max_factor, 1, 10, Dimension::Dimensionless, false, false,
          "HMAX of X eq 10, a factor of the initial smoothing length");
  return body;
}

const toml::array* array_of_tables(const View& parent, const std::string& k, const std::string& example) {
  const toml::node* n = parent.find(k);
  if (!n) return nullptr;
  const toml::array* a = n->as_array();
  if (a && a->empty()) return a;
  if (!a || !a->is_array_of_tables())
    parent.fail(k, "expected an array of tables, written [[" + parent.key(k) + "]] with " + example + ", not " + type_name(*n));
  return a;
}

std::vector<BodySpec> read_bodies(const View& root, const std::vector<MaterialSpec>& materials) {
  const std::string example = "name, material and shape";
  const toml::array* a = array_of_tables(root, "bodies", example);
  if (!a) root.missing("bodies", "expected at least one [[bodies]] table with " + example);
  if (a->empty()) root.fail("bodies", "is empty; expected at least one [[bodies]] table with " + example);
  std::vector<BodySpec> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const View b(root.values().reporter(), *a->get(i)->as_table(), "bodies[" + std::to_string(i) + "]", "a body");
    BodySpec body = read_body(b, materials);
    body.line = line_of(a->get(i));
    for (std::size_t j = 0; j < out.size(); ++j)
      if (out[j].name == body.name)
        b.fail("name", "duplicate body name \"" + body.name + "\" (also bodies[" + std::to_string(j) +
                           "]); body names must be unique");
    out.push_back(std::move(body));
  }
  return out;
}

void read_boundaries(const View& root, CaseSpec& spec) {
  const toml::node* n = root.find("boundaries");
  if (!n) return;
  if (!n->is_table())
    root.fail("boundaries", "expected a table holding [[boundaries.fixed]], [[boundaries.symmetry]] and "
                            "[[boundaries.wall]], not " + type_name(*n));
  const Reporter& r = root.values().reporter();
  const View bnd(r, *n->as_table(), "boundaries", "boundaries");
  bnd.allow({"fixed", "symmetry", "wall"});

  Keys body_names;
  for (const BodySpec& b : spec.bodies) body_names.push_back(b.name);

  if (const toml::array* a = array_of_tables(bnd, "fixed", "region = \"box\", min and max")) {
    for (std::size_t i = 0; i < a->size(); ++i) {
      const View f(r, *a->get(i)->as_table(), "boundaries.fixed[" + std::to_string(i) + "]", "a fixed region");
      FixedRegionSpec reg;
      reg.line = line_of(a->get(i));
      const std::string region = f.choice("region", {"box", "outside-cylinder"});
      if (region == "box") {
        f.allow({"region", "body", "min", "max"});
        reg.kind = FixedRegionSpec::Kind::Box;
        read_box(f, reg.box_min, reg.box_max);
      } else {
        f.allow({"region", "body", "axis", "axis_point", "radius"});
        reg.kind = FixedRegionSpec::Kind::OutsideCylinder;
        reg.axis = f.axis("axis");
        reg.axis_point = f.vec3("axis_point", Dimension::Length);
        reg.radius = f.quantity("radius", Dimension::Length);
        f.positive("radius", reg.radius, Dimension::Length);
      }
      if (f.has("body")) {
        reg.body = f.string("body", "\"plate\"");
        if (std::find(body_names.begin(), body_names.end(), reg.body) == body_names.end())
          f.fail("body", "no body named \"" + reg.body + "\";" + did_you_mean(reg.body, body_names) +
                             " bodies: " + join_quoted(body_names));
      }
      spec.fixed.push_back(reg);
    }
  }
  // Symmetry planes, then walls (mirror planes that push but do not pull), into one list of planes.
  for (const char* kind : {"symmetry", "wall"}) {
    const bool wall = std::string(kind) == "wall";
    const toml::array* a = array_of_tables(bnd, kind, "axis and position");
    if (!a) continue;
    for (std::size_t i = 0; i < a->size(); ++i) {
      SymmetryPlaneSpec plane;
      plane.wall = wall;
      plane.key = "boundaries." + std::string(kind) + "[" + std::to_string(i) + "]";
      const View s(r, *a->get(i)->as_table(), plane.key, wall ? "a rigid wall" : "a symmetry plane");
      s.allow({"axis", "position"});
      plane.line = line_of(a->get(i));
      plane.axis = s.axis("axis");
      plane.position = s.quantity_or("position", Dimension::Length, 0.0);
      for (const SymmetryPlaneSpec& other : spec.symmetry)
        if (other.axis == plane.axis && other.position == plane.position)
          s.fail(s.has("position") ? "position" : "axis",
                 "the same plane as " + other.key + "; each plane is given once");
      spec.symmetry.push_back(plane);
    }
  }
  // Both solvers keep a plane's images in a bit mask, and the gpu port holds its planes in a fixed array.
  if (spec.symmetry.size() > 6)
    root.fail(spec.symmetry.back().key, "too many planes: at most 6, symmetry planes and walls together "
                                        "(the faces of a box), and this case gives " +
                                            std::to_string(spec.symmetry.size()));
}

// Contact pairs: [[contacts]] with bodies = ["a", "b"], kind, penalty_scale, contact_distance.
void read_contacts(const View& root, CaseSpec& spec) {
  const toml::array* a = array_of_tables(root, "contacts", "bodies = [\"projectile\", \"plate\"] and kind = \"penalty\"");
  if (!a) return;
  const Reporter& r = root.values().reporter();
  Keys body_names;
  for (const BodySpec& b : spec.bodies) body_names.push_back(b.name);
  for (std::size_t i = 0; i < a->size(); ++i) {
    const View c(r, *a->get(i)->as_table(), "contacts[" + std::to_string(i) + "]", "a contact");
    ContactSpec contact;
    contact.line = line_of(a->get(i));
    const std::string kind = c.choice("kind", {"penalty", "shared"}, "penalty");
    if (kind == "penalty") c.allow({"bodies", "kind", "penalty_scale", "contact_distance", "srad"});
    else c.allow({"bodies", "kind"});
    contact.kind = kind == "penalty" ? ContactSpec::Kind::Penalty : ContactSpec::Kind::Shared;

    const std::string example = "[\"projectile\", \"plate\"]";
    const toml::node* n = c.find("bodies");
    if (!n) c.missing("bodies", "expected the names of two bodies such as " + example);
    const toml::array* pair = n->as_array();
    if (!pair) c.fail("bodies", "expected an array of two body names such as " + example + ", not " + type_name(*n));
    if (pair->size() != 2)
      c.fail("bodies", "has " + std::to_string(pair->size()) + " entries; expected two body names such as " + example);
    int index[2];
    std::string name[2];
    for (std::size_t j = 0; j < 2; ++j) {
      const std::string key = c.key("bodies") + "[" + std::to_string(j) + "]";
      name[j] = c.values().string(*pair->get(j), key, example);
      const auto it = std::find(body_names.begin(), body_names.end(), name[j]);
      if (it == body_names.end())
        r.fail(pair->get(j), key, "no body named \"" + name[j] + "\";" + did_you_mean(name[j], body_names) +
                                      " bodies: " + join_quoted(body_names));
      index[j] = static_cast<int>(it - body_names.begin());
    }
    if (index[0] == index[1])
      c.fail("bodies", "names \"" + name[0] + "\" twice; a contact is between two different bodies");
    contact.body_a = name[0];
    contact.body_b = name[1];
    contact.index_a = index[0];
    contact.index_b = index[1];
    for (std::size_t j = 0; j < spec.contacts.size(); ++j) {
      const ContactSpec& o = spec.contacts[j];
      if ((o.index_a == index[0] && o.index_b == index[1]) || (o.index_a == index[1] && o.index_b == index[0]))
        c.fail("bodies", "the pair \"" + name[0] + "\", \"" + name[1] + "\" is already listed in contacts[" +
                             std::to_string(j) + "]; each pair is given once");
    }
    if (contact.kind == ContactSpec::Kind::Penalty) {
      contact.penalty_scale = c.number_or("penalty_scale", 0.3);
      c.range("penalty_scale", contact.penalty_scale, 0, 10, Dimension::Dimensionless, true, false,
              "K_p scales the penalty force (F Table 3: 0.3)");
      contact.contact_distance = c.number_or("contact_distance", 1.0);
      c.range("contact_distance", contact.contact_distance, 0.5, 3, Dimension::Dimensionless, false, false,
              "in particle spacings");
      if (c.has("srad")) {
        if (c.has("contact_distance"))
          c.fail("srad", "give either srad (in smoothing lengths, X eq 18) or contact_distance (in spacings), not both");
        contact.srad = c.number("srad");
        c.range("srad", contact.srad, 0.5, 3, Dimension::Dimensionless, false, false,
                "SRAD of X eqs 18 and 20: particles touch at srad (h_i + h_j)/2");
      }
    }
    spec.contacts.push_back(contact);
  }
}

// ---------------------------------------------------------------------------------------------------
// Case, numerics, time, output

// output.picture_field, in the order of enum PictureField.
const Keys kPictureFields{"plastic_strain", "damage", "speed", "pressure"};

void read_numerics(const View& root, NumericsSpec& num) {
  const View n = root.sub("numerics", "[numerics]", "[numerics] with spacing = \"0.5 mm\"");
  n.allow({"spacing", "kernel", "h_factor", "viscosity_linear", "viscosity_quadratic", "viscosity_balsara",
           "viscosity_limiter", "viscosity_limiter_close_approach",
           "bulk_viscosity_linear", "bulk_viscosity_quadratic", "artificial_stress", "artificial_stress_exponent", "artificial_stress_of",
           "delta",
           "cfl", "correction_max_condition"});
  num.spacing = n.quantity("spacing", Dimension::Length);
  num.spacing_line = line_of(n.find("spacing"));
  n.positive("spacing", num.spacing, Dimension::Length);
  const std::string kernel = n.choice("kernel", {"wendland-c2", "cubic-spline"}, "wendland-c2");
  num.kernel = kernel == "wendland-c2" ? KernelKind::WendlandC2 : KernelKind::CubicSpline;
  num.h_factor = n.number_or("h_factor", 1.2);
  n.range("h_factor", num.h_factor, 1.0, 2.0, Dimension::Dimensionless);
  num.viscosity.linear = n.number_or("viscosity_linear", 1.0);
  n.non_negative("viscosity_linear", num.viscosity.linear, Dimension::Dimensionless);
  num.viscosity.quadratic = n.number_or("viscosity_quadratic", 1.0);
  n.non_negative("viscosity_quadratic", num.viscosity.quadratic, Dimension::Dimensionless);
  num.viscosity_balsara = n.boolean_or("viscosity_balsara", false);
  const bool limited = n.choice("viscosity_limiter", {"none", "van-leer"}, "none") == "van-leer";
  const double close = n.number_or("viscosity_limiter_close_approach", kViscosityCloseApproachSpacings);
  n.range("viscosity_limiter_close_approach", close, 0, 1, Dimension::Dimensionless);
  if (!limited && n.has("viscosity_limiter_close_approach"))
    n.fail("viscosity_limiter_close_approach", "only acts with viscosity_limiter = \"van-leer\"; set that, or remove this key");
  num.viscosity = limited_viscosity_params(num.viscosity.linear, num.viscosity.quadratic, limited, num.h_factor, close);
  num.bulk_viscosity.linear = n.number_or("bulk_viscosity_linear", 0.0);
  n.range("bulk_viscosity_linear", num.bulk_viscosity.linear, 0, 5, Dimension::Dimensionless);
  num.bulk_viscosity.quadratic = n.number_or("bulk_viscosity_quadratic", 0.0);
  n.range("bulk_viscosity_quadratic", num.bulk_viscosity.quadratic, 0, 5, Dimension::Dimensionless);
  num.artificial_stress = n.number_or("artificial_stress", 0.0);
  n.range("artificial_stress", num.artificial_stress, 0, 1, Dimension::Dimensionless);
  const double exponent = n.number_or("artificial_stress_exponent", 4.0);
  n.range("artificial_stress_exponent", exponent, 1, 8, Dimension::Dimensionless);
  if (exponent != std::floor(exponent))
    n.fail("artificial_stress_exponent", "must be a whole number such as 4 (Gray, Monaghan and Swift 2001), got " +
                                             format_quantity(exponent, Dimension::Dimensionless));
  num.artificial_stress_exponent = static_cast<int>(exponent);
  num.artificial_stress_deviatoric = n.choice("artificial_stress_of", {"deviatoric", "total"}, "deviatoric") == "deviatoric";
  num.delta = n.number_or("delta", 0.1);
  n.range("delta", num.delta, 0, 1, Dimension::Dimensionless);
  num.cfl = n.number_or("cfl", 0.2);
  n.range("cfl", num.cfl, 0, 1, Dimension::Dimensionless, true);
  num.correction.max_condition = n.number_or("correction_max_condition", 1e3);
  if (!(num.correction.max_condition > 3))
    n.fail("correction_max_condition", "must be greater than 3, the condition number of the identity (got " +
                                           format_quantity(num.correction.max_condition, Dimension::Dimensionless) + ")");
}

void read_time(const View& root, TimeSpec& time) {
  const View t = root.sub("time", "[time]", "[time] with end = \"20 us\" and output_interval = \"1 us\"");
  t.allow({"end", "output_interval", "frame_interval", "checkpoint_interval"});
  time.end = t.quantity("end", Dimension::Time);
  t.positive("end", time.end, Dimension::Time);
  auto interval = [&](const std::string& k, double v) {
    if (v > time.end)
      t.fail(k, "is longer than time.end = " + format_quantity(time.end, Dimension::Time) + " (got " +
                    format_quantity(v, Dimension::Time) + "); an interval must be at most the end time");
  };
  time.output_interval = t.quantity("output_interval", Dimension::Time);
  t.positive("output_interval", time.output_interval, Dimension::Time);
  interval("output_interval", time.output_interval);
  time.frame_interval = t.quantity_or("frame_interval", Dimension::Time, time.output_interval);
  t.positive("frame_interval", time.frame_interval, Dimension::Time);
  interval("frame_interval", time.frame_interval);
  time.checkpoint_interval = t.quantity_or("checkpoint_interval", Dimension::Time, 0.0);
  t.non_negative("checkpoint_interval", time.checkpoint_interval, Dimension::Time);
  interval("checkpoint_interval", time.checkpoint_interval);
}

void read_observables(const Reporter& r, const View& root, CaseSpec& spec) {
  const toml::node* n = root.find("observables");
  if (!n) return;
  if (!n->is_table())
    root.fail("observables", "expected a table such as [observables] with projectile = \"projectile\", not " + type_name(*n));
  const View o(r, *n->as_table(), "observables", "[observables]");
  o.allow({"taylor_bar", "projectile", "target", "stop_when_settled", "settle_window", "settle_tolerance"});
  ObservablesSpec& obs = spec.observables;
  auto body = [&](const std::string& k, std::string& name, int& index) {
    if (!o.has(k)) return;
    name = o.string(k, "\"projectile\"");
    Keys names;
    for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
      names.push_back(spec.bodies[b].name);
      if (spec.bodies[b].name == name) index = static_cast<int>(b);
    }
    if (index < 0) o.fail(k, "names no body: \"" + name + "\"; the bodies are " + join_quoted(names));
  };
  body("taylor_bar", obs.taylor_bar, obs.taylor_bar_index);
  if (obs.taylor_bar_index >= 0 && spec.bodies[static_cast<std::size_t>(obs.taylor_bar_index)].shape == Shape::Sphere)
    o.fail("taylor_bar", "\"" + obs.taylor_bar + "\" is a sphere; the Taylor-bar observables (final length, impact-face "
                         "diameter) measure a bar: a cylinder, or a box along z");
  body("projectile", obs.projectile, obs.projectile_index);
  body("target", obs.target, obs.target_index);
  if (obs.target_index >= 0 && obs.projectile_index < 0)
    o.fail("target", "needs projectile = \"...\" too: the plug is the part of the target that leaves with the projectile");
  obs.stop_when_settled = o.boolean_or("stop_when_settled", false);
  if (obs.stop_when_settled && obs.projectile_index < 0)
    o.fail("stop_when_settled", "needs projectile = \"...\": the run settles when the projectile's velocity is steady");
  obs.settle_window = o.quantity_or("settle_window", Dimension::Time, obs.settle_window);
  o.positive("settle_window", obs.settle_window, Dimension::Time);
  obs.settle_tolerance = o.quantity_or("settle_tolerance", Dimension::Velocity, obs.settle_tolerance);
  o.positive("settle_tolerance", obs.settle_tolerance, Dimension::Velocity);
}

CaseSpec read_case(const toml::table& tree, const Reporter& r) {
  const View root(r, tree, "", "the case file");
  root.allow({"case", "materials", "bodies", "boundaries", "contacts", "numerics", "time", "observables", "output"});
  CaseSpec spec;
  spec.source_file = r.file();

  const View c = root.sub("case", "[case]", "[case] with name = \"elastic-wave\"");
  c.allow({"name", "description"});
  spec.name = c.string("name", "\"elastic-wave\"");
  if (spec.name.empty()) c.fail("name", "must not be empty");
  spec.description = c.string_or("description", "");

  spec.materials = read_materials(root);
  spec.bodies = read_bodies(root, spec.materials);
  read_boundaries(root, spec);
  read_contacts(root, spec);
  read_numerics(root, spec.numerics);
  read_time(root, spec.time);
  read_observables(r, root, spec);
  if (const toml::node* n = root.find("output")) {
    if (!n->is_table()) root.fail("output", "expected a table such as [output] with vtu = true, not " + type_name(*n));
    const View o(r, *n->as_table(), "output", "[output]");
    o.allow({"vtu", "csv", "picture", "picture_field"});
    spec.output.vtu = o.boolean_or("vtu", true);
    spec.output.csv = o.boolean_or("csv", true);
    spec.output.picture = o.boolean_or("picture", true);
    const std::string field = o.choice("picture_field", kPictureFields, "plastic_strain");
    spec.output.picture_field = static_cast<PictureField>(
        std::find(kPictureFields.begin(), kPictureFields.end(), field) - kPictureFields.begin());
    if (spec.output.picture_field == PictureField::Damage &&
        std::none_of(spec.materials.begin(), spec.materials.end(),
                     [](const MaterialSpec& m) { return m.params.damage.kind != DamageKind::None; }))
      o.fail("picture_field", "\"damage\" needs a material with a damage model ([materials.NAME] damage = { kind = "
                              "... }) and no material of this case has one; valid here: \"plastic_strain\", "
                              "\"speed\", \"pressure\"");
  }
  return spec;
}

// ---------------------------------------------------------------------------------------------------
// Overrides

// The value of an override as a TOML node: `0.1`, `true`, `"298 m/s"`, `[0, 0, -1]` are TOML; anything
// that does not parse as one TOML value (`298 m/s`, `40us`) is taken as a string.
toml::table value_holder(const std::string& value) {
  if (value.find('\n') == std::string::npos) {
    try {
      toml::table t = toml::parse("v = " + value);
      if (t.size() == 1 && t.contains("v")) return t;
    } catch (const toml::parse_error&) {
      // Not a TOML value: fall through to a plain string.
    }
  }
  toml::table t;
  t.insert("v", value);
  return t;
}

// Puts a copy of the value held by `holder` under `key` in `t` and returns the new node. A copy, not a
// move: toml++ copies drop the source region, so the node reports line 0 instead of line 1 of "v = ...".
const toml::node* put(toml::table& t, const std::string& key, const toml::table& holder) {
  const toml::node* out = nullptr;
  holder.get("v")->visit([&](const auto& v) { out = &t.insert_or_assign(key, v).first->second; });
  return out;
}

// A body's velocity given as a vector in the file and overridden by a speed keeps its direction: the
// direction of the old vector is written as `direction`, unless the body already has one.
void keep_direction(toml::table& body, Reporter& r, const std::string& origin) {
  if (body.contains("direction")) return;
  const toml::array* old = body.get_as<toml::array>("velocity");
  if (!old || old->size() != 3) return;
  Vec3d v{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const toml::node* c = old->get(i);
    if (const auto* s = c->as_string()) {
      try {
        v[i] = parse_quantity(s->get(), Dimension::Velocity);
      } catch (const std::invalid_argument&) {
        return;  // the vector was invalid anyway; validation reports the missing direction
      }
    } else if (c->is_number()) {
      v[i] = c->value<double>().value_or(0.0);
    } else {
      return;
    }
  }
  const double len = norm(v);
  if (!(len > 0)) return;
  toml::array dir{v.x / len, v.y / len, v.z / len};
  r.mark(&body.insert_or_assign("direction", std::move(dir)).first->second, origin + ", keeping the file's direction");
}

void apply_override(toml::table& root, const std::string& text, Reporter& r) {
  const std::string file = r.file();
  const auto eq = text.find('=');
  if (eq == std::string::npos)
    throw CaseError(file, 0, text, "an override is KEY=VALUE, such as projectile.velocity=298 m/s or numerics.cfl=0.1");
  const std::string path = trim(text.substr(0, eq));
  const std::string value = trim(text.substr(eq + 1));
  Keys parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(trim(p));
  if (!path.empty() && path.back() == '.') parts.push_back("");
  if (parts.size() < 2 || std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); }))
    throw CaseError(file, 0, text, "the key of an override is TABLE.key, BODY.key or MATERIAL.key, such as "
                                   "numerics.cfl, projectile.velocity or steel.eos.c0");
  if (value.empty()) throw CaseError(file, 0, text, "the override has no value after '='");

  // Names that exist in the file, for resolving the first component and for the error listing them.
  std::map<std::string, toml::table*> bodies, materials;
  if (toml::array* a = root.get_as<toml::array>("bodies"))
    for (toml::node& b : *a)
      if (toml::table* t = b.as_table())
        if (const auto* name = t->get_as<std::string>("name")) bodies.emplace(name->get(), t);
  if (toml::table* m = root.get_as<toml::table>("materials"))
    for (auto&& [k, v] : *m)
      if (toml::table* t = v.as_table()) materials.emplace(std::string(k.str()), t);

  const Keys tables{"case", "numerics", "time", "observables", "output"};
  toml::table* target = nullptr;
  std::size_t first_key = 1;
  const std::string& head = parts[0];
  auto named = [&](const std::map<std::string, toml::table*>& from, const std::string& what) -> toml::table* {
    const auto it = from.find(parts[1]);
    if (it != from.end()) return it->second;
    Keys names;
    for (const auto& [k, v] : from) names.push_back(k);
    throw CaseError(file, 0, text, "no " + what + " named \"" + parts[1] + "\";" + did_you_mean(parts[1], names) +
                                       " defined: " + (names.empty() ? std::string("none") : join_quoted(names)));
  };
  if (std::find(tables.begin(), tables.end(), head) != tables.end()) {
    toml::node* n = root.get(head);
    if (!n) n = &root.insert_or_assign(head, toml::table{}).first->second;
    target = n->as_table();
    if (!target) throw CaseError(file, 0, text, "\"" + head + "\" in the case file is not a table");
  } else if ((head == "bodies" || head == "materials") && parts.size() >= 3) {
    target = named(head == "bodies" ? bodies : materials, head == "bodies" ? "body" : "material");
    first_key = 2;
  } else {
    const bool is_body = bodies.count(head) > 0, is_material = materials.count(head) > 0;
    if (is_body && is_material)
      throw CaseError(file, 0, text, "\"" + head + "\" names both a body and a material; write bodies." + head +
                                         "." + parts[1] + " or materials." + head + "." + parts[1]);
    if (!is_body && !is_material) {
      Keys all = tables;
      std::string listing = "tables: " + join_quoted(tables);
      Keys names;
      for (const auto& [k, v] : bodies) names.push_back(k), all.push_back(k);
      listing += "; bodies: " + (names.empty() ? std::string("none") : join_quoted(names));
      names.clear();
      for (const auto& [k, v] : materials) names.push_back(k), all.push_back(k);
      listing += "; materials: " + (names.empty() ? std::string("none") : join_quoted(names));
      throw CaseError(file, 0, text, "no table, body or material named \"" + head + "\";" + did_you_mean(head, all) +
                                         " valid: " + listing);
    }
    target = is_body ? bodies[head] : materials[head];
  }

  const std::string origin = "override \"" + text + "\"";
  for (std::size_t i = first_key; i + 1 < parts.size(); ++i) {
    toml::node* n = target->get(parts[i]);
    if (!n) {
      n = &target->insert_or_assign(parts[i], toml::table{}).first->second;
      r.mark(n, origin);
    }
    if (!n->is_table())
      throw CaseError(file, line_of(n), text, "\"" + parts[i] + "\" is " + type_name(*n) + ", not a table");
    target = n->as_table();
  }
  toml::table holder = value_holder(value);
  const std::string& leaf = parts.back();
  const bool is_body_table = std::any_of(bodies.begin(), bodies.end(), [&](const auto& b) { return b.second == target; });
  if (is_body_table && leaf == "velocity" && !holder.get("v")->is_array()) keep_direction(*target, r, origin);
  r.mark(put(*target, leaf, holder), origin);
}

// Material files: a material given as `[materials.NAME]` with the single key `file = "PATH"` (PATH relative
// to the case file's folder) takes its constants from that TOML file, whose top level holds the keys of
// a material table (density, eos, strength, ...). Read before the overrides, so NAME.key overrides work on
// the file's values; errors in the file name the file and its line (the nodes keep their source).
void resolve_material_files(toml::table& tree, const Reporter& r) {
  toml::table* materials = tree.get_as<toml::table>("materials");
  if (!materials) return;
  const std::filesystem::path base = std::filesystem::path(r.file()).parent_path();
  for (auto&& [k, v] : *materials) {
    toml::table* m = v.as_table();
    if (!m || !m->contains("file")) continue;
    const std::string key = "materials." + std::string(k.str()) + ".file";
    const toml::node* f = m->get("file");
    const auto* path = f->as_string();
    if (!path) r.fail(f, key, "expected the path of a material file such as \"../materials/alumina-ad995.toml\", not " + type_name(*f));
    for (auto&& [other, node] : *m)
      if (other.str() != "file")
        r.fail(&node, "materials." + std::string(k.str()) + "." + std::string(other.str()),
               "a material read from a file takes all its constants from the file; give only file = \"...\" here "
               "(change a constant with an override, NAME.key=VALUE)");
    const std::filesystem::path full = base / path->get();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(full, ec))
      r.fail(f, key, "no material file \"" + full.string() + "\" (the path is relative to the case file's folder)");
    std::ifstream in(full, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    toml::table loaded;
    try {
      loaded = toml::parse(text.str(), full.string());
    } catch (const toml::parse_error& e) {
      throw CaseError(full.string(), static_cast<int>(e.source().begin.line), "", "not valid TOML: " + std::string(e.description()));
    }
    *m = std::move(loaded);
  }
}

CaseSpec parse_tree(toml::table& tree, Reporter& r, const std::vector<std::string>& set_overrides,
                    const std::string& spacing_override) {
  resolve_material_files(tree, r);
  for (const std::string& o : set_overrides) apply_override(tree, o, r);
  if (!spacing_override.empty()) {
    toml::node* n = tree.get("numerics");
    if (!n) n = &tree.insert_or_assign("numerics", toml::table{}).first->second;
    toml::table* numerics = n->as_table();
    if (!numerics) throw CaseError(r.file(), line_of(n), "numerics", "expected a table [numerics], not " + type_name(*n));
    toml::table holder = value_holder(trim(spacing_override));
    r.mark(put(*numerics, "spacing", holder), "the spacing override \"" + spacing_override + "\"");
  }
  return read_case(tree, r);
}

}  // namespace

CaseSpec parse_case_string(const std::string& toml_text, const std::string& display_name,
                           const std::vector<std::string>& set_overrides, const std::string& spacing_override) {
  Reporter r(display_name);
  toml::table tree;
  try {
    tree = toml::parse(toml_text, display_name);
  } catch (const toml::parse_error& e) {
    throw CaseError(display_name, static_cast<int>(e.source().begin.line), "",
                    "not valid TOML: " + std::string(e.description()));
  }
  return parse_tree(tree, r, set_overrides, spacing_override);
}

std::vector<std::string> case_material_files(const std::string& path) {
  std::vector<std::string> files;
  toml::table tree;
  try {
    tree = toml::parse_file(path);
  } catch (const toml::parse_error&) {
    return files;
  }
  const toml::table* materials = tree.get_as<toml::table>("materials");
  if (!materials) return files;
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  for (auto&& [k, v] : *materials) {
    const toml::table* m = v.as_table();
    const toml::node* f = m ? m->get("file") : nullptr;
    if (f && f->as_string()) files.push_back((base / f->as_string()->get()).string());
  }
  return files;
}

std::string toml_file_content(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::ostringstream text;
  text << in.rdbuf();
  try {
    const toml::table tree = toml::parse(text.str(), path);
    std::ostringstream out;
    out << toml::toml_formatter(tree);  // keys in order, no comments: the same tree prints the same text
    return out.str();
  } catch (const toml::parse_error&) {
    return text.str();
  }
}

CaseSpec load_case_file(const std::string& path, const std::vector<std::string>& set_overrides,
                        const std::string& spacing_override) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw CaseError(path, 0, "", "no such case file");
  if (std::filesystem::is_directory(path, ec))
    throw CaseError(path, 0, "", "is a directory; expected a case file such as " + path + "/case.toml");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(path, 0, "", "cannot open the case file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_case_string(text.str(), path, set_overrides, spacing_override);
}

}  // namespace impactsph
