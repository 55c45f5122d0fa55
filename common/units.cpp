// Quantity parsing: a number, then a unit expression parsed by recursive descent into an SI factor and a
// dimension (exponents of kg, m, s, K), checked against the dimension the caller expects. See units.hpp.
#include "common/units.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace impactsph {
namespace {

// Exponents of the SI base units kg, m, s, K.
struct Dim {
  int kg = 0, m = 0, s = 0, K = 0;
  bool operator==(const Dim& o) const { return kg == o.kg && m == o.m && s == o.s && K == o.K; }
  bool operator!=(const Dim& o) const { return !(*this == o); }
};
Dim operator*(Dim a, Dim b) { return {a.kg + b.kg, a.m + b.m, a.s + b.s, a.K + b.K}; }
Dim operator/(Dim a, Dim b) { return {a.kg - b.kg, a.m - b.m, a.s - b.s, a.K - b.K}; }
Dim pow(Dim a, int n) { return {a.kg * n, a.m * n, a.s * n, a.K * n}; }

constexpr Dim kNone{0, 0, 0, 0};
constexpr Dim kLength{0, 1, 0, 0};
constexpr Dim kVelocity{0, 1, -1, 0};
constexpr Dim kTime{0, 0, 1, 0};
constexpr Dim kPressure{1, -1, -2, 0};
constexpr Dim kDensity{1, -3, 0, 0};
constexpr Dim kMass{1, 0, 0, 0};
constexpr Dim kSpecificHeat{0, 2, -2, -1};
constexpr Dim kTemperature{0, 0, 0, 1};
constexpr Dim kSpecificEnergy{0, 2, -2, 0};
constexpr Dim kEnergy{1, 2, -2, 0};
constexpr Dim kForce{1, 1, -2, 0};
constexpr Dim kStrainRate{0, 0, -1, 0};
constexpr Dim kFractureEnergy{1, 0, -2, 0};

Dim dim_of(Dimension d) {
  switch (d) {
    case Dimension::Dimensionless: return kNone;
    case Dimension::Length: return kLength;
    case Dimension::Velocity: return kVelocity;
    case Dimension::Time: return kTime;
    case Dimension::Pressure: return kPressure;
    case Dimension::Density: return kDensity;
    case Dimension::Mass: return kMass;
    case Dimension::SpecificHeat: return kSpecificHeat;
    case Dimension::Temperature: return kTemperature;
    case Dimension::SpecificEnergy: return kSpecificEnergy;
    case Dimension::StrainRate: return kStrainRate;
    case Dimension::FractureEnergy: return kFractureEnergy;
  }
  return kNone;
}

struct Prefix {
  char symbol;  // 'u' stands for micro; "µ" is rewritten to it before parsing
  double factor;
};
constexpr std::array<Prefix, 7> kPrefixes{{{'n', 1e-9}, {'u', 1e-6}, {'m', 1e-3}, {'c', 1e-2}, {'k', 1e3},
                                          {'M', 1e6}, {'G', 1e9}}};

struct BaseUnit {
  const char* symbol;
  double factor;  // SI value of one unit
  Dim dim;
  const char* prefixes;  // the prefixes in use with this unit (no Gm, no mPa, no cs)
};
const std::array<BaseUnit, 8> kUnits{{
    {"m", 1.0, kLength, "numck"},
    {"s", 1.0, kTime, "num"},
    {"g", 1e-3, kMass, "mk"},
    {"Pa", 1.0, kPressure, "kMG"},
    {"bar", 1e5, kPressure, "mkM"},
    {"J", 1.0, kEnergy, "kM"},
    {"N", 1.0, kForce, "kM"},
    {"K", 1.0, kTemperature, ""},
}};

double prefix_factor(char p) {
  for (const Prefix& x : kPrefixes)
    if (x.symbol == p) return x.factor;
  return 0;
}

// Every accepted unit symbol, prefixed or not, for "did you mean" hints on a wrong letter case.
std::vector<std::string> all_symbols() {
  std::vector<std::string> out;
  for (const BaseUnit& u : kUnits) {
    out.emplace_back(u.symbol);
    for (const char* p = u.prefixes; *p; ++p) out.push_back(std::string(1, *p) + u.symbol);
  }
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Names of dimensions a user might write by mistake, for "\"200 m/s\" is a velocity".
std::string describe(Dim d) {
  struct Named {
    Dim dim;
    const char* name;
  };
  static const Named kNamed[] = {
      {kLength, "a length"},          {kVelocity, "a velocity"},
      {kTime, "a time"},              {kPressure, "a pressure"},
      {kDensity, "a density"},        {kMass, "a mass"},
      {kSpecificHeat, "a specific heat"}, {kTemperature, "a temperature"},
      {kSpecificEnergy, "a specific energy"}, {kEnergy, "an energy"},
      {kForce, "a force"},            {{0, 2, 0, 0}, "an area"},
      {{0, 3, 0, 0}, "a volume"},     {{0, 1, -2, 0}, "an acceleration"},
      {kStrainRate, "a rate (1/s)"}, {kFractureEnergy, "an energy per unit area (J/m^2)"},
      {kNone, "a bare number"},
  };
  for (const Named& n : kNamed)
    if (n.dim == d) return n.name;
  std::string s;
  const std::pair<int, const char*> parts[] = {{d.kg, "kg"}, {d.m, "m"}, {d.s, "s"}, {d.K, "K"}};
  for (const auto& [e, sym] : parts) {
    if (e == 0) continue;
    if (!s.empty()) s += " ";
    s += sym;
    if (e != 1) s += "^" + std::to_string(e);
  }
  return "in units of " + s;
}

std::string expectation(Dimension d) {
  if (d == Dimension::Dimensionless) return "expected a bare number such as " + dimension_example(d);
  const std::string name = dimension_name(d);
  const bool vowel = std::string("aeiou").find(name[0]) != std::string::npos;
  return std::string("expected ") + (vowel ? "an " : "a ") + name + " such as \"" + dimension_example(d) +
         "\" (units: " + dimension_units(d) + ")";
}

// Replaces the two code points that people type for micro (U+00B5 MICRO SIGN, U+03BC GREEK SMALL LETTER
// MU) by 'u', and the middle dot (U+00B7) by '*', so the parser below sees ASCII only.
std::string normalise(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (i + 1 < s.size()) {
      const unsigned char n = static_cast<unsigned char>(s[i + 1]);
      if ((c == 0xC2 && n == 0xB5) || (c == 0xCE && n == 0xBC)) { out += 'u'; ++i; continue; }
      if (c == 0xC2 && n == 0xB7) { out += '*'; ++i; continue; }
    }
    out += s[i];
  }
  return out;
}

struct UnitValue {
  double factor = 1;
  Dim dim{};
};

// Recursive descent over the unit text:
//   expr    := (product | '1' | ) ('/' product)*   (a missing numerator is 1: "/s", "1/s")
//   product := power (['*'] power)*        (a space between two factors multiplies)
//   power   := atom ['^' signed-int | int]
//   atom    := identifier | '(' expr ')'
// Products bind tighter than '/', so "J/kg K" is J/(kg K), the reading people intend.
class UnitParser {
 public:
  UnitParser(const std::string& unit, const std::string& whole, Dimension expected)
      : s_(unit), whole_(whole), expected_(expected) {}

  UnitValue parse() {
    UnitValue v = expr();
    skip_space();
    if (pos_ < s_.size()) fail_syntax("unexpected \"" + s_.substr(pos_, 1) + "\"");
    return v;
  }

 private:
  void skip_space() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  char peek() {
    skip_space();
    return pos_ < s_.size() ? s_[pos_] : '\0';
  }

  UnitValue expr() {
    UnitValue v;  // a numerator of 1, written "1" or left out, as in "1/s" and "/s"
    if (peek() == '1' && (pos_ + 1 >= s_.size() || !std::isdigit(static_cast<unsigned char>(s_[pos_ + 1])))) {
      ++pos_;
      if (peek() != '/') fail_syntax("a \"1\" must be followed by \"/\", as in \"1/s\"");
    } else if (peek() != '/') {
      v = product();
    }
    while (peek() == '/') {
      ++pos_;
      const UnitValue d = product();
      v.factor /= d.factor;
      v.dim = v.dim / d.dim;
    }
    return v;
  }

  UnitValue product() {
    UnitValue v = power();
    for (;;) {
      const char c = peek();
      if (c == '*') {
        ++pos_;
      } else if (!(std::isalpha(static_cast<unsigned char>(c)) || c == '(')) {
        break;
      }
      const UnitValue f = power();
      v.factor *= f.factor;
      v.dim = v.dim * f.dim;
    }
    return v;
  }

  UnitValue power() {
    UnitValue v = atom();
    // No skip_space before an exponent written as bare digits: "m3" is m^3, "m 3" is not a unit.
    int n = 1;
    bool has_exponent = false;
    if (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) {
      n = integer();
      has_exponent = true;
    } else if (peek() == '^') {
      ++pos_;
      skip_space();
      n = integer();
      has_exponent = true;
    }
    if (has_exponent) {
      v.factor = std::pow(v.factor, n);
      v.dim = pow(v.dim, n);
    }
    return v;
  }

  int integer() {
    const std::size_t start = pos_;
    if (start >= s_.size()) fail_syntax("it ends where an exponent is expected");
    if (pos_ < s_.size() && (s_[pos_] == '-' || s_[pos_] == '+')) ++pos_;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    int n = 0;
    const char* first = s_.data() + start + (s_[start] == '+' ? 1 : 0);
    const auto r = std::from_chars(first, s_.data() + pos_, n);
    if (r.ec != std::errc() || r.ptr != s_.data() + pos_ || n == 0 || n > 9 || n < -9)
      fail_syntax("an exponent must be a small non-zero integer, as in \"m^3\"");
    return n;
  }

  UnitValue atom() {
    const char c = peek();
    if (c == '(') {
      ++pos_;
      UnitValue v = expr();
      if (peek() != ')') fail_syntax("missing \")\"");
      ++pos_;
      return v;
    }
    const std::size_t start = pos_;
    while (pos_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    if (pos_ == start) {
      if (pos_ >= s_.size()) fail_syntax("it ends where a unit is expected");
      fail_syntax("unexpected \"" + s_.substr(pos_, 1) + "\"");
    }
    return lookup(s_.substr(start, pos_ - start));
  }

  UnitValue lookup(const std::string& id) const {
    for (const BaseUnit& u : kUnits)
      if (id == u.symbol) return {u.factor, u.dim};
    if (id.size() > 1) {
      const std::string rest = id.substr(1);
      for (const BaseUnit& u : kUnits) {
        if (rest != u.symbol) continue;
        for (const char* p = u.prefixes; *p; ++p)
          if (*p == id[0]) return {prefix_factor(id[0]) * u.factor, u.dim};
      }
    }
    std::string hint;
    for (const std::string& sym : all_symbols())
      if (lower(sym) == lower(id)) hint = " (did you mean \"" + sym + "\"? unit symbols are case-sensitive)";
    if (hint.empty() && (id == "C" || id == "degC" || id == "F" || id == "degF"))
      hint = " (temperatures are absolute, in K)";
    throw std::invalid_argument("unknown unit \"" + id + "\" in \"" + whole_ + "\"" + hint + "; " +
                                expectation(expected_));
  }

  [[noreturn]] void fail_syntax(const std::string& why) const {
    throw std::invalid_argument("cannot read the unit \"" + s_ + "\" in \"" + whole_ + "\": " + why + "; " +
                                expectation(expected_));
  }

  const std::string& s_;
  const std::string& whole_;
  Dimension expected_;
  std::size_t pos_ = 0;
};

// Length of the leading decimal number of s (sign, digits, point, exponent), 0 if there is none. The
// exponent is only taken when digits follow, so "2 em" would not eat the "e".
std::size_t number_length(const std::string& s) {
  std::size_t i = 0, digits = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
  }
  if (digits == 0) return 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    if (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) {
      while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
      i = j;
    }
  }
  return i;
}

}  // namespace

std::string trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

std::string dimension_name(Dimension d) {
  switch (d) {
    case Dimension::Dimensionless: return "dimensionless number";
    case Dimension::Length: return "length";
    case Dimension::Velocity: return "velocity";
    case Dimension::Time: return "time";
    case Dimension::Pressure: return "pressure";
    case Dimension::Density: return "density";
    case Dimension::Mass: return "mass";
    case Dimension::SpecificHeat: return "specific heat";
    case Dimension::Temperature: return "temperature";
    case Dimension::SpecificEnergy: return "specific energy";
    case Dimension::StrainRate: return "strain rate";
    case Dimension::FractureEnergy: return "fracture energy";
  }
  return "quantity";
}

std::string dimension_example(Dimension d) {
  switch (d) {
    case Dimension::Dimensionless: return "0.3";
    case Dimension::Length: return "8 mm";
    case Dimension::Velocity: return "298 m/s";
    case Dimension::Time: return "20 us";
    case Dimension::Pressure: return "200 GPa";
    case Dimension::Density: return "7850 kg/m^3";
    case Dimension::Mass: return "197 g";
    case Dimension::SpecificHeat: return "452 J/(kg K)";
    case Dimension::Temperature: return "293 K";
    case Dimension::SpecificEnergy: return "1e5 J/kg";
    case Dimension::StrainRate: return "1 /s";
    case Dimension::FractureEnergy: return "200 kJ/m^2";
  }
  return "";
}

std::string dimension_units(Dimension d) {
  switch (d) {
    case Dimension::Dimensionless: return "none";
    case Dimension::Length: return "m, mm, cm, um, nm, km; a bare number is m";
    case Dimension::Velocity: return "m/s, km/s, mm/us; a bare number is m/s";
    case Dimension::Time: return "s, ms, us, ns; a bare number is s";
    case Dimension::Pressure: return "Pa, kPa, MPa, GPa, bar, kbar, Mbar; a bare number is Pa";
    case Dimension::Density: return "kg/m^3, g/cm^3; a bare number is kg/m^3";
    case Dimension::Mass: return "kg, g, mg; a bare number is kg";
    case Dimension::SpecificHeat: return "J/(kg K), J/kg/K, kJ/(kg K); a bare number is J/(kg K)";
    case Dimension::Temperature: return "K, absolute; a bare number is K";
    case Dimension::SpecificEnergy: return "J/kg, kJ/kg, MJ/kg; a bare number is J/kg";
    case Dimension::StrainRate: return "1/s, /s, s^-1, 1/ms, 1/us; a bare number is 1/s";
    case Dimension::FractureEnergy: return "J/m^2, kJ/m^2, MJ/m^2, N/m, N/mm; a bare number is J/m^2";
  }
  return "";
}

double parse_quantity(const std::string& text, Dimension expected) {
  const std::string t = trim(normalise(text));
  if (t.empty()) throw std::invalid_argument("empty value; " + expectation(expected));
  const std::size_t n = number_length(t);
  if (n == 0)
    throw std::invalid_argument("\"" + text + "\" does not start with a number; " + expectation(expected));
  double value = 0;
  const char* first = t.data() + (t[0] == '+' ? 1 : 0);
  const auto r = std::from_chars(first, t.data() + n, value);
  if (r.ec != std::errc() || r.ptr != t.data() + n || !std::isfinite(value))
    throw std::invalid_argument("\"" + text + "\": the number is out of range; " + expectation(expected));
  const std::string unit = trim(t.substr(n));
  if (unit.empty()) return value;  // a bare number is SI, whatever the dimension (design.md, "Units")
  const UnitValue u = UnitParser(unit, text, expected).parse();
  if (u.dim != dim_of(expected))
    throw std::invalid_argument("\"" + text + "\" is " + describe(u.dim) + "; " + expectation(expected));
  const double si = value * u.factor;
  if (!std::isfinite(si))
    throw std::invalid_argument("\"" + text + "\": the value is out of range; " + expectation(expected));
  return si;
}

std::string format_quantity(double v, Dimension d) {
  const double a = std::fabs(v);
  double scale = 1;
  const char* unit = "";
  switch (d) {
    case Dimension::Dimensionless: break;
    case Dimension::Length:
      if (a >= 1) unit = "m";
      else if (a >= 1e-4 || a == 0) scale = 1e-3, unit = "mm";
      else scale = 1e-6, unit = "um";
      break;
    case Dimension::Velocity: unit = "m/s"; break;
    case Dimension::Time:
      if (a == 0 || a >= 1) unit = "s";
      else if (a >= 1e-3) scale = 1e-3, unit = "ms";
      else if (a >= 1e-6) scale = 1e-6, unit = "us";
      else scale = 1e-9, unit = "ns";
      break;
    case Dimension::Pressure:
      if (a >= 1e9) scale = 1e9, unit = "GPa";
      else if (a >= 1e6) scale = 1e6, unit = "MPa";
      else if (a >= 1e3) scale = 1e3, unit = "kPa";
      else unit = "Pa";
      break;
    case Dimension::Density: unit = "kg/m^3"; break;
    case Dimension::Mass:
      if (a == 0 || a >= 1) unit = "kg";
      else scale = 1e-3, unit = "g";
      break;
    case Dimension::SpecificHeat: unit = "J/(kg K)"; break;
    case Dimension::Temperature: unit = "K"; break;
    case Dimension::SpecificEnergy: unit = "J/kg"; break;
    case Dimension::StrainRate: unit = "/s"; break;
    case Dimension::FractureEnergy:
      if (a >= 1e3) scale = 1e3, unit = "kJ/m^2";
      else unit = "J/m^2";
      break;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v / scale);
  std::string s = buf;
  if (*unit) s += std::string(" ") + unit;
  return s;
}

}  // namespace impactsph
