// Physical quantities with units, as case files write them ("8 mm", "298 m/s", "7.85 g/cm^3",
// "452 J/(kg K)"), turned into SI numbers (design.md, "Units": SI inside, a bare number is SI).
// Host only: errors are std::invalid_argument with a message a user can act on; case_file.cpp adds the
// file, line and key.
//
// A unit expression is parsed, not looked up: products (space, '*' or the middle dot) bind tighter than
// '/', so "J/kg K" and "J/(kg K)" and "J/kg/K" all mean J kg^-1 K^-1; exponents are written "^3" or "3"
// ("kg/m3"). Base units carry the prefixes that are in use for them (mm and um but not Gm; MPa but not
// mPa; "µ" and "u" both mean micro). The dimension of the whole expression is checked against the one
// the caller expects, so "200 m/s" where a pressure is wanted names what it is instead.
#pragma once
#include <string>

namespace impactsph {

enum class Dimension {
  Dimensionless,
  Length,          // m
  Velocity,        // m/s
  Time,            // s
  Pressure,        // Pa (also stress, moduli)
  Density,         // kg/m^3
  Mass,            // kg
  SpecificHeat,    // J/(kg K)
  Temperature,     // K (absolute only: no degrees Celsius, whose zero is offset)
  SpecificEnergy,  // J/kg
  FractureEnergy,  // J/m^2 (energy per unit crack area; also N/m)
  StrainRate       // 1/s (written "1/s", "/s" or "s^-1": "1e-3 /s", "1 1/s", "1 s^-1")
};

// s without its leading and trailing white space.
std::string trim(const std::string& s);

// "length", "velocity", ... as used in messages ("expected a length").
std::string dimension_name(Dimension d);
// A typical quantity of that dimension as a case file would write it, e.g. "8 mm" or "200 GPa".
std::string dimension_example(Dimension d);
// The units accepted for a dimension, for messages: "m, mm, cm, um, km (a bare number is m)".
std::string dimension_units(Dimension d);

// Parses "8 mm", "0.5mm", "-3 mm", "1.5e-6 s", "20 µs", "0.002" (bare: SI) into the SI value.
// Throws std::invalid_argument saying what is wrong and what would be valid for `expected`.
double parse_quantity(const std::string& text, Dimension expected);

// A value in SI written with a readable unit of its dimension ("8 mm", "490 MPa", "7850 kg/m^3"), for
// messages and logs; 6 significant digits.
std::string format_quantity(double value, Dimension d);

}  // namespace impactsph
