// The base case and the assertions shared by the case-file tests (test_case_file*.cpp).
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "common/case_file.hpp"
#include "common/errors.hpp"

namespace impactsph::case_file_test {

using impactsph::CaseError;
using impactsph::CaseSpec;
using impactsph::parse_case_string;


// Two materials written in non-alphabetical order (file order must win), a box and a cylinder.
inline const std::string kBase = R"toml(# test case
[case]
name = "test"
description = "a plate and a projectile"

[materials.steel]
density = "7850 kg/m^3"
eos = { kind = "linear", bulk_modulus = "160 GPa" }
strength = { kind = "elastic", shear_modulus = "80 GPa" }

[materials.copper]
density = "8.93 g/cm^3"
eos = { kind = "mie-gruneisen", c0 = "3940 m/s", s = 1.489, gamma0 = 2.02 }
strength = { kind = "perfectly-plastic", youngs_modulus = "124 GPa", poisson_ratio = 0.34, yield_stress = "90 MPa" }
specific_heat = "383 J/(kg K)"

[[bodies]]
name = "plate"
material = "steel"
shape = "box"
min = ["0 mm", "0 mm", "0 mm"]
max = ["10 mm", "10 mm", "2 mm"]

[[bodies]]
name = "projectile"
material = "copper"
shape = "cylinder"
base = ["5 mm", "5 mm", "2 mm"]
axis = "z"
radius = "2 mm"
length = "5 mm"
velocity = "298 m/s"
direction = [0, 0, -1]

[numerics]
spacing = "0.5 mm"

[time]
end = "20 us"
output_interval = "1 us"
)toml";

// kBase with `from` replaced by `to` (which must be there, so a test cannot silently test nothing).
inline std::string with(const std::string& from, const std::string& to, const std::string& base = kBase) {
  const auto at = base.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: \"" << from << "\" is not in the case";
  if (at == std::string::npos) return base;
  std::string s = base;
  s.replace(at, from.size(), to);
  return s;
}

// 1-based line of the first line of `text` holding `part`.
inline int line_of(const std::string& text, const std::string& part) {
  const auto at = text.find(part);
  EXPECT_NE(at, std::string::npos);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

inline ::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

inline CaseError error_of(const std::string& toml, const std::vector<std::string>& overrides = {},
                   const std::string& spacing = "") {
  try {
    parse_case_string(toml, "case.toml", overrides, spacing);
  } catch (const CaseError& e) {
    EXPECT_EQ(e.file(), "case.toml");
    return e;
  }
  ADD_FAILURE() << "the case was accepted";
  return CaseError("", 0, "", "");
}

// The common assertion: the key, a hint in the message, and the line (-1: do not check).
inline void expect_error(const std::string& toml, const std::string& key, const std::string& hint, int line) {
  const CaseError e = error_of(toml);
  EXPECT_EQ(e.key(), key) << e.what();
  EXPECT_TRUE(Contains(e.what(), hint));
  if (line >= 0) {
    EXPECT_EQ(e.line(), line) << e.what();
  }
}

}  // namespace impactsph::case_file_test
