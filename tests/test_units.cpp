// Quantity parsing (common/units.hpp): every unit the case files use, prefixes, the micro sign in both
// encodings, unit expressions, and the messages for wrong or unknown units.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "common/units.hpp"

using impactsph::Dimension;
using impactsph::parse_quantity;

namespace {

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

std::string error_of(const std::string& text, Dimension d) {
  try {
    parse_quantity(text, d);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "\"" << text << "\" was accepted";
  return "";
}

void expect_si(const std::string& text, Dimension d, double si) {
  EXPECT_NEAR(parse_quantity(text, d), si, 1e-12 * std::abs(si)) << text;
}

}  // namespace

TEST(Units, Lengths) {
  expect_si("8 mm", Dimension::Length, 8e-3);
  expect_si("0.5mm", Dimension::Length, 0.5e-3);
  expect_si("-3 mm", Dimension::Length, -3e-3);
  expect_si("2 m", Dimension::Length, 2);
  expect_si("1.5 cm", Dimension::Length, 1.5e-2);
  expect_si("40 um", Dimension::Length, 40e-6);
  expect_si("3 km", Dimension::Length, 3e3);
  expect_si("12 nm", Dimension::Length, 12e-9);
  expect_si("0.002", Dimension::Length, 0.002);
  expect_si("  +4.5e-1 mm  ", Dimension::Length, 0.45e-3);
  expect_si(".5 mm", Dimension::Length, 0.5e-3);
}

TEST(Units, VelocitiesAndTimes) {
  expect_si("298 m/s", Dimension::Velocity, 298);
  expect_si("1.2 km/s", Dimension::Velocity, 1200);
  expect_si("2 mm/us", Dimension::Velocity, 2000);
  expect_si("20 us", Dimension::Time, 20e-6);
  expect_si("20 \xC2\xB5s", Dimension::Time, 20e-6);  // U+00B5 MICRO SIGN
  expect_si("20 \xCE\xBCs", Dimension::Time, 20e-6);  // U+03BC GREEK SMALL LETTER MU
  expect_si("1.5e-6 s", Dimension::Time, 1.5e-6);
  expect_si("3 ms", Dimension::Time, 3e-3);
  expect_si("100 ns", Dimension::Time, 100e-9);
}

TEST(Units, PressuresDensitiesMasses) {
  expect_si("200 GPa", Dimension::Pressure, 200e9);
  expect_si("490 MPa", Dimension::Pressure, 490e6);
  expect_si("101.325 kPa", Dimension::Pressure, 101325);
  expect_si("5 Pa", Dimension::Pressure, 5);
  expect_si("2 bar", Dimension::Pressure, 2e5);
  expect_si("1 Mbar", Dimension::Pressure, 1e11);
  expect_si("7850 kg/m^3", Dimension::Density, 7850);
  expect_si("7850 kg/m3", Dimension::Density, 7850);
  expect_si("7.85 g/cm^3", Dimension::Density, 7850);
  expect_si("197 g", Dimension::Mass, 0.197);
  expect_si("0.197 kg", Dimension::Mass, 0.197);
  expect_si("1 N/m^2", Dimension::Pressure, 1);
}

TEST(Units, ThermalQuantities) {
  expect_si("452 J/(kg K)", Dimension::SpecificHeat, 452);
  expect_si("452 J/kg/K", Dimension::SpecificHeat, 452);
  expect_si("452 J/(kg*K)", Dimension::SpecificHeat, 452);
  expect_si("452 J/kg K", Dimension::SpecificHeat, 452);  // products bind tighter than '/'
  expect_si("0.452 kJ/(kg K)", Dimension::SpecificHeat, 452);
  expect_si("293 K", Dimension::Temperature, 293);
  expect_si("1e5 J/kg", Dimension::SpecificEnergy, 1e5);
  expect_si("2 MJ/kg", Dimension::SpecificEnergy, 2e6);
  expect_si("150 kJ/m^2", Dimension::FractureEnergy, 1.5e5);
  expect_si("150 N/mm", Dimension::FractureEnergy, 1.5e5);
  expect_si("20 J/m^2", Dimension::FractureEnergy, 20);
  expect_si("0.3", Dimension::Dimensionless, 0.3);
}

TEST(Units, StrainRates) {
  expect_si("1 /s", Dimension::StrainRate, 1);
  expect_si("1/s", Dimension::StrainRate, 1);
  expect_si("5e-4 /s", Dimension::StrainRate, 5e-4);
  expect_si("5e-4/s", Dimension::StrainRate, 5e-4);
  expect_si("0.001 1/s", Dimension::StrainRate, 1e-3);
  expect_si("2 s^-1", Dimension::StrainRate, 2);
  expect_si("2 1/ms", Dimension::StrainRate, 2e3);
  expect_si("3 /us", Dimension::StrainRate, 3e6);
  expect_si("4 1/(ms)", Dimension::StrainRate, 4e3);
  expect_si("0.5", Dimension::StrainRate, 0.5);  // bare: 1/s
  EXPECT_EQ(impactsph::dimension_name(Dimension::StrainRate), "strain rate");
  EXPECT_TRUE(Contains(impactsph::dimension_units(Dimension::StrainRate), "s^-1"));
  EXPECT_EQ(impactsph::format_quantity(5e-4, Dimension::StrainRate), "0.0005 /s");

  EXPECT_TRUE(Contains(error_of("1 m/s", Dimension::StrainRate), "is a velocity; expected a strain rate such as \"1 /s\""));
  EXPECT_TRUE(Contains(error_of("1 s", Dimension::StrainRate), "is a time"));
  EXPECT_TRUE(Contains(error_of("3 /s", Dimension::Velocity), "is a rate (1/s)"));
  EXPECT_TRUE(Contains(error_of("5 1 mm", Dimension::Length), "must be followed by \"/\""));
  EXPECT_TRUE(Contains(error_of("5 /", Dimension::StrainRate), "cannot read the unit"));
  EXPECT_TRUE(Contains(error_of("5 12/s", Dimension::StrainRate), "cannot read the unit"));
  // The numerator 1 is not a number in the middle of a product.
  EXPECT_TRUE(Contains(error_of("5 m 1/s", Dimension::Velocity), "cannot read the unit"));
}

TEST(Units, EveryExampleParsesAsItsDimension) {
  for (Dimension d : {Dimension::Dimensionless, Dimension::Length, Dimension::Velocity, Dimension::Time,
                      Dimension::Pressure, Dimension::Density, Dimension::Mass, Dimension::SpecificHeat,
                      Dimension::Temperature, Dimension::SpecificEnergy, Dimension::StrainRate,
                      Dimension::FractureEnergy}) {
    EXPECT_NO_THROW(parse_quantity(impactsph::dimension_example(d), d)) << impactsph::dimension_name(d);
    EXPECT_FALSE(impactsph::dimension_name(d).empty());
  }
}

TEST(Units, WrongDimensionNamesBoth) {
  const std::string m = error_of("200 m/s", Dimension::Pressure);
  EXPECT_TRUE(Contains(m, "\"200 m/s\" is a velocity"));
  EXPECT_TRUE(Contains(m, "expected a pressure such as \"200 GPa\""));
  EXPECT_TRUE(Contains(m, "MPa"));
  EXPECT_TRUE(Contains(error_of("7850 kg", Dimension::Density), "is a mass"));
  EXPECT_TRUE(Contains(error_of("3 mm", Dimension::Dimensionless), "is a length"));
  EXPECT_TRUE(Contains(error_of("3 m^2/s", Dimension::Length), "in units of m^2 s^-1"));
}

TEST(Units, UnknownUnitsAndBadSyntax) {
  EXPECT_TRUE(Contains(error_of("5 mn", Dimension::Length), "unknown unit \"mn\""));
  EXPECT_TRUE(Contains(error_of("5 mpa", Dimension::Pressure), "did you mean \"MPa\""));
  EXPECT_TRUE(Contains(error_of("5 Gm", Dimension::Length), "unknown unit \"Gm\""));  // prefix not in use for m
  EXPECT_TRUE(Contains(error_of("20 C", Dimension::Temperature), "absolute, in K"));
  EXPECT_TRUE(Contains(error_of("mm", Dimension::Length), "does not start with a number"));
  EXPECT_TRUE(Contains(error_of("", Dimension::Length), "empty"));
  EXPECT_TRUE(Contains(error_of("5 m^", Dimension::Length), "cannot read the unit"));
  EXPECT_TRUE(Contains(error_of("5 (m", Dimension::Length), "missing \")\""));
  EXPECT_TRUE(Contains(error_of("5 m/", Dimension::Length), "cannot read the unit"));
  EXPECT_TRUE(Contains(error_of("1e999 m", Dimension::Length), "out of range"));
  EXPECT_TRUE(Contains(error_of("5 m % 2", Dimension::Length), "unexpected \"%\""));
}

TEST(Units, FormatQuantity) {
  EXPECT_EQ(impactsph::format_quantity(8e-3, Dimension::Length), "8 mm");
  EXPECT_EQ(impactsph::format_quantity(490e6, Dimension::Pressure), "490 MPa");
  EXPECT_EQ(impactsph::format_quantity(20e-6, Dimension::Time), "20 us");
  EXPECT_EQ(impactsph::format_quantity(7850, Dimension::Density), "7850 kg/m^3");
  EXPECT_EQ(impactsph::format_quantity(0.3, Dimension::Dimensionless), "0.3");
}
