// The reading of a case file's TOML tree (common/case_file.cpp and the readers beside it, host only):
// Reporter builds the CaseErrors, Values reads single values, View reads a table and knows the full key of
// what it reads, so that every CaseError names the file, the line and the key. Internal to the case-file
// reader: case_file.hpp is the interface.
#pragma once
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "common/case_spec.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"

namespace impactsph::case_reading {

using Keys = std::vector<std::string>;

inline int line_of(const toml::node* n) { return n ? static_cast<int>(n->source().begin.line) : 0; }

inline std::string type_name(const toml::node& n) {
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

inline std::string join(const Keys& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

inline std::string join_quoted(const Keys& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "\"" : ", \"") + x + "\"";
  return s;
}

inline std::size_t edit_distance(const std::string& a, const std::string& b) {
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
inline std::string did_you_mean(const std::string& word, const Keys& valid) {
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
inline std::vector<std::pair<std::string, const toml::node*>> in_file_order(const toml::table& t) {
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

constexpr double GPa = 1e9;
constexpr double kMaxModulus = 2000 * GPa;  // above every solid's modulus (diamond: ~1100 GPa)
// Below the shear modulus of soft rubber (~0.3 MPa) and any yield stress of a metal: catches a bare number
// meant in GPa or MPa but read in Pa.
constexpr double kMinModulus = 0.1e6;
inline const char* const kModulusHint = "a bare number is in Pa, write units as in \"200 GPa\"";

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

  // A stress or modulus, required, between kMinModulus and kMaxModulus (a bare number is in Pa);
  // `extra_hint` follows the unit hint in the message.
  double stress(const std::string& k, const std::string& extra_hint = "") const {
    const double v = quantity(k, Dimension::Pressure);
    range(k, v, kMinModulus, kMaxModulus, Dimension::Pressure, false, false, kModulusHint + extra_hint);
    return v;
  }
  // The same, but 0 is valid too (a small non-zero value is a bare number meant in MPa or GPa).
  double stress_or_zero(const std::string& k, const std::string& extra_hint = "") const {
    const double v = quantity(k, Dimension::Pressure);
    if (v != 0) range(k, v, kMinModulus, kMaxModulus, Dimension::Pressure, false, false, kModulusHint + extra_hint);
    return v;
  }

  const Values& values() const { return v_; }

 private:
  const Reporter& r_;
  Values v_;
  const toml::table& t_;
  std::string path_, what_;
};


// Names are used by overrides as NAME.key, so they must not hold the override syntax.
inline void check_name(const Reporter& r, const toml::node* at, const std::string& key, const std::string& name) {
  if (name.empty()) r.fail(at, key, "must not be empty");
  for (const char c : name)
    if (c == '.' || c == '=' || c == '[' || c == ']' || c == '"' || std::isspace(static_cast<unsigned char>(c)))
      r.fail(at, key,
             "\"" + name + "\" may not contain '.', '=', brackets, quotes or spaces (overrides address it as " +
                 "NAME.key); use letters, digits, '-' and '_'");
}


// The sections of the case file, each read in its own file: the materials (case_materials.cpp), the bodies,
// boundaries and contacts (case_geometry.cpp).
std::vector<MaterialSpec> read_materials(const View& root);
std::vector<BodySpec> read_bodies(const View& root, const std::vector<MaterialSpec>& materials);
void read_boundaries(const View& root, CaseSpec& spec);
void read_contacts(const View& root, CaseSpec& spec);

}  // namespace impactsph::case_reading
