// Case files (common/case_file.hpp): the schema of docs/case-files.md read into a CaseSpec, one test per
// class of bad input (each asserting the key, a useful hint and the line), and override semantics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "common/case_file.hpp"
#include "common/errors.hpp"
#include "common/scene.hpp"

using impactsph::CaseError;
using impactsph::CaseSpec;
using impactsph::parse_case_string;
using impactsph::Nose;

namespace {

// Two materials written in non-alphabetical order (file order must win), a box and a cylinder.
const std::string kBase = R"toml(# test case
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
std::string with(const std::string& from, const std::string& to, const std::string& base = kBase) {
  const auto at = base.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: \"" << from << "\" is not in the case";
  if (at == std::string::npos) return base;
  std::string s = base;
  s.replace(at, from.size(), to);
  return s;
}

// 1-based line of the first line of `text` holding `part`.
int line_of(const std::string& text, const std::string& part) {
  const auto at = text.find(part);
  EXPECT_NE(at, std::string::npos);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

CaseError error_of(const std::string& toml, const std::vector<std::string>& overrides = {},
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
void expect_error(const std::string& toml, const std::string& key, const std::string& hint, int line) {
  const CaseError e = error_of(toml);
  EXPECT_EQ(e.key(), key) << e.what();
  EXPECT_TRUE(Contains(e.what(), hint));
  if (line >= 0) {
    EXPECT_EQ(e.line(), line) << e.what();
  }
}

}  // namespace

TEST(CaseFile, ReadsTheBaseCase) {
  const CaseSpec s = parse_case_string(kBase, "case.toml");
  EXPECT_EQ(s.source_file, "case.toml");
  EXPECT_EQ(s.name, "test");
  EXPECT_EQ(s.description, "a plate and a projectile");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "steel");  // file order, not the alphabetical order of toml::table
  EXPECT_EQ(s.materials[1].name, "copper");

  const auto& steel = s.materials[0].params;
  EXPECT_EQ(steel.eos.kind, impactsph::EosKind::Linear);
  EXPECT_DOUBLE_EQ(steel.eos.rho0, 7850);
  EXPECT_DOUBLE_EQ(steel.eos.k1, 160e9);
  EXPECT_EQ(steel.strength.kind, impactsph::StrengthKind::Elastic);
  EXPECT_DOUBLE_EQ(steel.strength.shear_modulus, 80e9);
  EXPECT_DOUBLE_EQ(steel.room_temperature, 293);
  EXPECT_DOUBLE_EQ(steel.specific_heat, 0);

  const auto& cu = s.materials[1].params;
  EXPECT_NEAR(cu.eos.rho0, 8930, 1e-9);
  EXPECT_EQ(cu.eos.kind, impactsph::EosKind::MieGruneisen);
  EXPECT_DOUBLE_EQ(cu.eos.c0, 3940);
  EXPECT_DOUBLE_EQ(cu.eos.s1, 1.489);
  EXPECT_DOUBLE_EQ(cu.eos.gamma0, 2.02);
  EXPECT_EQ(cu.strength.kind, impactsph::StrengthKind::PerfectlyPlastic);
  EXPECT_NEAR(cu.strength.shear_modulus, 124e9 / (2 * 1.34), 1);
  EXPECT_DOUBLE_EQ(cu.strength.yield_stress, 90e6);
  EXPECT_DOUBLE_EQ(cu.specific_heat, 383);

  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[0].shape, impactsph::Shape::Box);
  EXPECT_EQ(s.bodies[0].material_index, 0);
  EXPECT_DOUBLE_EQ(s.bodies[0].box_max.z, 2e-3);
  EXPECT_DOUBLE_EQ(s.bodies[0].velocity.z, 0);
  const auto& p = s.bodies[1];
  EXPECT_EQ(p.shape, impactsph::Shape::Cylinder);
  EXPECT_EQ(p.material, "copper");
  EXPECT_EQ(p.material_index, 1);
  EXPECT_EQ(p.axis, 2);
  EXPECT_DOUBLE_EQ(p.radius, 2e-3);
  EXPECT_DOUBLE_EQ(p.length, 5e-3);
  EXPECT_DOUBLE_EQ(p.base.x, 5e-3);
  EXPECT_DOUBLE_EQ(p.velocity.x, 0);
  EXPECT_DOUBLE_EQ(p.velocity.z, -298);

  EXPECT_DOUBLE_EQ(s.numerics.spacing, 0.5e-3);
  EXPECT_EQ(s.numerics.kernel, impactsph::KernelKind::WendlandC2);
  EXPECT_DOUBLE_EQ(s.numerics.h_factor, 1.2);
  EXPECT_DOUBLE_EQ(s.numerics.viscosity.linear, 1.0);
  EXPECT_DOUBLE_EQ(s.numerics.viscosity.quadratic, 1.0);
  EXPECT_DOUBLE_EQ(s.numerics.delta, 0.1);
  EXPECT_DOUBLE_EQ(s.numerics.cfl, 0.2);
  EXPECT_DOUBLE_EQ(s.numerics.correction.max_condition, 1e3);
  EXPECT_DOUBLE_EQ(s.time.end, 20e-6);
  EXPECT_DOUBLE_EQ(s.time.output_interval, 1e-6);
  EXPECT_DOUBLE_EQ(s.time.frame_interval, 1e-6);
  EXPECT_DOUBLE_EQ(s.time.checkpoint_interval, 0);
  EXPECT_TRUE(s.output.vtu);
  EXPECT_TRUE(s.output.csv);
  EXPECT_TRUE(s.fixed.empty());
  EXPECT_TRUE(s.symmetry.empty());
}

TEST(CaseFile, ReadsOptionalSections) {
  const std::string toml = kBase + R"(
[output]
vtu = false

[[boundaries.fixed]]
region = "outside-cylinder"
axis = "z"
axis_point = [0.005, 0.005, 0]
radius = "4 mm"
body = "plate"

[[boundaries.fixed]]
region = "box"
min = ["0 mm", "0 mm", "0 mm"]
max = ["1 mm", "10 mm", "2 mm"]

[[boundaries.symmetry]]
axis = "y"
)";
  const std::string t2 = with("spacing = \"0.5 mm\"",
                              "spacing = \"0.5 mm\"\nkernel = \"cubic-spline\"\nh_factor = 1.5\ncfl = 0.3\n"
                              "viscosity_linear = 0.5\nviscosity_quadratic = 2\ndelta = 0\ncorrection_max_condition = 50\n"
                              "bulk_viscosity_linear = 0.5\nbulk_viscosity_quadratic = 1\n"
                              "viscosity_limiter = \"van-leer\"\nviscosity_limiter_close_approach = 0.5\n"
                              "artificial_stress = 0.3\nartificial_stress_exponent = 6\nartificial_stress_of = \"total\"",
                              with("output_interval = \"1 us\"",
                                   "output_interval = \"1 us\"\nframe_interval = \"0.5 us\"\ncheckpoint_interval = \"10 us\"",
                                   toml));
  const CaseSpec s = parse_case_string(t2, "case.toml");
  EXPECT_DOUBLE_EQ(s.numerics.bulk_viscosity.linear, 0.5);
  EXPECT_DOUBLE_EQ(s.numerics.bulk_viscosity.quadratic, 1);
  EXPECT_DOUBLE_EQ(parse_case_string(toml, "case.toml").numerics.bulk_viscosity.linear, 0);  // off by default
  EXPECT_TRUE(s.numerics.viscosity.limited);
  EXPECT_DOUBLE_EQ(s.numerics.viscosity.close_eta, 0.5 / 1.5);  // spacings over h_factor
  EXPECT_DOUBLE_EQ(s.numerics.viscosity.close_fold, 0.2 / 1.5);
  EXPECT_FALSE(parse_case_string(toml, "case.toml").numerics.viscosity.limited);  // off by default
  EXPECT_DOUBLE_EQ(s.numerics.artificial_stress, 0.3);
  EXPECT_EQ(s.numerics.artificial_stress_exponent, 6);
  EXPECT_FALSE(s.numerics.artificial_stress_deviatoric);
  EXPECT_TRUE(parse_case_string(toml, "case.toml").numerics.artificial_stress_deviatoric);
  EXPECT_DOUBLE_EQ(parse_case_string(toml, "case.toml").numerics.artificial_stress, 0);  // off by default
  EXPECT_EQ(parse_case_string(toml, "case.toml").numerics.artificial_stress_exponent, 4);
  EXPECT_FALSE(s.output.vtu);
  EXPECT_TRUE(s.output.csv);
  ASSERT_EQ(s.fixed.size(), 2u);
  EXPECT_EQ(s.fixed[0].kind, impactsph::FixedRegionSpec::Kind::OutsideCylinder);
  EXPECT_EQ(s.fixed[0].body, "plate");
  EXPECT_DOUBLE_EQ(s.fixed[0].radius, 4e-3);
  EXPECT_DOUBLE_EQ(s.fixed[0].axis_point.y, 5e-3);
  EXPECT_EQ(s.fixed[1].kind, impactsph::FixedRegionSpec::Kind::Box);
  EXPECT_TRUE(s.fixed[1].body.empty());
  ASSERT_EQ(s.symmetry.size(), 1u);
  EXPECT_EQ(s.symmetry[0].axis, 1);
  EXPECT_DOUBLE_EQ(s.symmetry[0].position, 0);
  EXPECT_EQ(s.numerics.kernel, impactsph::KernelKind::CubicSpline);
  EXPECT_DOUBLE_EQ(s.numerics.h_factor, 1.5);
  EXPECT_DOUBLE_EQ(s.numerics.cfl, 0.3);
  EXPECT_DOUBLE_EQ(s.numerics.viscosity.linear, 0.5);
  EXPECT_DOUBLE_EQ(s.numerics.viscosity.quadratic, 2);
  EXPECT_DOUBLE_EQ(s.numerics.delta, 0);
  EXPECT_DOUBLE_EQ(s.numerics.correction.max_condition, 50);
  EXPECT_DOUBLE_EQ(s.time.frame_interval, 0.5e-6);  // shorter than output_interval is fine
  EXPECT_DOUBLE_EQ(s.time.checkpoint_interval, 10e-6);
}

TEST(CaseFile, OtherEosKindsAndDerivedBulkModulus) {
  std::string t = with("eos = { kind = \"linear\", bulk_modulus = \"160 GPa\" }\n"
                       "strength = { kind = \"elastic\", shear_modulus = \"80 GPa\" }",
                       "eos = { kind = \"linear\" }\nstrength = { kind = \"elastic\", youngs_modulus = \"200 GPa\", "
                       "poisson_ratio = 0.3 }\ndamage = { kind = \"none\" }\nroom_temperature = \"300 K\"");
  CaseSpec s = parse_case_string(t, "case.toml");
  EXPECT_NEAR(s.materials[0].params.eos.k1, 200e9 / (3 * 0.4), 1);
  EXPECT_NEAR(s.materials[0].params.strength.shear_modulus, 200e9 / 2.6, 1);
  EXPECT_DOUBLE_EQ(s.materials[0].params.room_temperature, 300);

  t = with("eos = { kind = \"linear\", bulk_modulus = \"160 GPa\" }",
           "eos = { kind = \"polynomial\", k1 = \"130.95 GPa\", k3 = \"-10 GPa\" }");
  s = parse_case_string(t, "case.toml");
  EXPECT_EQ(s.materials[0].params.eos.kind, impactsph::EosKind::Polynomial);
  EXPECT_DOUBLE_EQ(s.materials[0].params.eos.k1, 130.95e9);
  EXPECT_DOUBLE_EQ(s.materials[0].params.eos.k2, 0);
  EXPECT_DOUBLE_EQ(s.materials[0].params.eos.k3, -10e9);

  t = with("eos = { kind = \"linear\", bulk_modulus = \"160 GPa\" }\n"
           "strength = { kind = \"elastic\", shear_modulus = \"80 GPa\" }",
           "[materials.steel.eos]\nkind = \"gruneisen-cubic\"\nc0 = \"4029 m/s\"\ns1 = 1.23\ngamma0 = 1.54\na = 0.1\n"
           "[materials.steel.strength]\nkind = \"hydrodynamic\"");
  s = parse_case_string(t, "case.toml");
  const auto& e = s.materials[0].params.eos;
  EXPECT_EQ(e.kind, impactsph::EosKind::GruneisenCubic);
  EXPECT_DOUBLE_EQ(e.c0, 4029);
  EXPECT_DOUBLE_EQ(e.s1, 1.23);
  EXPECT_DOUBLE_EQ(e.s2, 0);
  EXPECT_DOUBLE_EQ(e.gamma0, 1.54);
  EXPECT_DOUBLE_EQ(e.a, 0.1);
  EXPECT_EQ(s.materials[0].params.strength.kind, impactsph::StrengthKind::Hydrodynamic);
}

TEST(CaseFile, EosPressureCutoff) {
  const std::string eos = "eos = { kind = \"mie-gruneisen\", c0 = \"3940 m/s\", s = 1.489, gamma0 = 2.02 }";
  auto copper = [](const CaseSpec& c) {
    for (const auto& m : c.materials)
      if (m.name == "copper") return m.params.eos;
    ADD_FAILURE() << "no material copper";
    return impactsph::EosParams<double>{};
  };
  CaseSpec s = parse_case_string(kBase, "case.toml");
  EXPECT_EQ(copper(s).min_pressure, -1e30);  // no cutoff unless asked for
  std::string t = with(eos, "eos = { kind = \"mie-gruneisen\", c0 = \"3940 m/s\", s = 1.489, gamma0 = 2.02, "
                            "min_pressure = \"-1.2 GPa\" }");
  s = parse_case_string(t, "case.toml");
  EXPECT_DOUBLE_EQ(copper(s).min_pressure, -1.2e9);
  t = with(eos, "eos = { kind = \"mie-gruneisen\", c0 = \"3940 m/s\", s = 1.489, gamma0 = 2.02, "
                "min_pressure = \"1.2 GPa\" }");
  expect_error(t, "materials.copper.eos.min_pressure", "at most 0 Pa (got 1.2 GPa); the pressure cutoff is the largest "
               "tension the material carries", line_of(t, "min_pressure"));
  t = with(eos, "eos = { kind = \"mie-gruneisen\", c0 = \"3940 m/s\", s = 1.489, gamma0 = 2.02, "
                "min_pressure = \"-1.2 mm\" }");
  expect_error(t, "materials.copper.eos.min_pressure", "is a length; expected a pressure", line_of(t, "min_pressure"));
}

TEST(CaseFile, VelocityForms) {
  std::string t = with("velocity = \"298 m/s\"\ndirection = [0, 0, -1]", "velocity = [\"0 m/s\", \"0.1 km/s\", -300]");
  CaseSpec s = parse_case_string(t, "case.toml");
  EXPECT_DOUBLE_EQ(s.bodies[1].velocity.y, 100);
  EXPECT_DOUBLE_EQ(s.bodies[1].velocity.z, -300);
  t = with("direction = [0, 0, -1]", "direction = [3, 0, -4]");  // normalised
  s = parse_case_string(t, "case.toml");
  EXPECT_NEAR(s.bodies[1].velocity.x, 298 * 0.6, 1e-12);
  EXPECT_NEAR(s.bodies[1].velocity.z, -298 * 0.8, 1e-12);
}

namespace {
// kBase with the cylindrical projectile replaced by a sphere.
std::string sphere_case() {
  return with("shape = \"cylinder\"\nbase = [\"5 mm\", \"5 mm\", \"2 mm\"]\naxis = \"z\"\nradius = \"2 mm\"\nlength = \"5 mm\"\n",
              "shape = \"sphere\"\ncenter = [\"5 mm\", \"5 mm\", \"4.5 mm\"]\nradius = \"2 mm\"\n");
}
}  // namespace

TEST(CaseFile, ReadsASphere) {
  const std::string kSphere = sphere_case();
  const CaseSpec s = parse_case_string(kSphere, "case.toml");
  ASSERT_EQ(s.bodies.size(), 2u);
  const auto& p = s.bodies[1];
  EXPECT_EQ(p.shape, impactsph::Shape::Sphere);
  EXPECT_DOUBLE_EQ(p.center.x, 5e-3);
  EXPECT_DOUBLE_EQ(p.center.y, 5e-3);
  EXPECT_DOUBLE_EQ(p.center.z, 4.5e-3);
  EXPECT_DOUBLE_EQ(p.radius, 2e-3);
  EXPECT_DOUBLE_EQ(p.velocity.z, -298);
  EXPECT_EQ(p.material_index, 1);
  // Bare numbers are metres, as for every length.
  const CaseSpec t = parse_case_string(with("radius = \"2 mm\"", "radius = 0.002", kSphere), "case.toml");
  EXPECT_DOUBLE_EQ(t.bodies[1].radius, 2e-3);
}

// ---- one test per class of bad input ----

TEST(CaseFileErrors, SphereKeys) {
  const std::string kSphere = sphere_case();
  const int body_line = line_of(kSphere, "name = \"projectile\"") - 1;  // its [[bodies]] header
  ASSERT_EQ(kSphere.substr(kSphere.find("[[bodies]]\nname = \"projectile\""), 10), "[[bodies]]");

  // Required keys, reported at the line of the body's table.
  std::string t = with("center = [\"5 mm\", \"5 mm\", \"4.5 mm\"]\n", "", kSphere);
  expect_error(t, "bodies[1].center", "missing in a body; expected an array of 3 values", body_line);
  t = with("radius = \"2 mm\"\n", "", kSphere);
  expect_error(t, "bodies[1].radius", "missing in a body; expected a length such as", body_line);

  // Values.
  t = with("radius = \"2 mm\"", "radius = \"0 mm\"", kSphere);
  expect_error(t, "bodies[1].radius", "must be greater than zero (got 0 mm)", line_of(t, "radius = "));
  t = with("radius = \"2 mm\"", "radius = \"-2 mm\"", kSphere);
  expect_error(t, "bodies[1].radius", "must be greater than zero (got -2 mm)", line_of(t, "radius = "));
  t = with("radius = \"2 mm\"", "radius = \"2 m/s\"", kSphere);
  expect_error(t, "bodies[1].radius", "\"2 m/s\" is a velocity; expected a length", line_of(t, "radius = "));
  t = with("center = [\"5 mm\", \"5 mm\", \"4.5 mm\"]", "center = [\"5 mm\", \"5 mm\"]", kSphere);
  expect_error(t, "bodies[1].center", "has 2 entries; expected 3 lengths (x, y, z)", line_of(t, "center = "));
  t = with("center = [\"5 mm\", \"5 mm\", \"4.5 mm\"]", "center = \"5 mm\"", kSphere);
  expect_error(t, "bodies[1].center", "expected an array of 3 lengths", line_of(t, "center = "));
  t = with("center = [\"5 mm\", \"5 mm\", \"4.5 mm\"]", "center = [\"5 mm\", \"5 GPa\", \"4.5 mm\"]", kSphere);
  expect_error(t, "bodies[1].center[1]", "is a pressure; expected a length", line_of(t, "center = "));

  // Keys of the other shapes, named as such, with the sphere's valid keys.
  const std::string valid = "valid keys: name, material, shape, velocity, direction, variable_h, h_min, h_max, center, radius";
  for (const std::string& extra : {"axis = \"z\"", "length = \"5 mm\"", "base = [\"5 mm\", \"5 mm\", \"2 mm\"]"}) {
    SCOPED_TRACE(extra);
    t = with("radius = \"2 mm\"\n", "radius = \"2 mm\"\n" + extra + "\n", kSphere);
    const std::string k = extra.substr(0, extra.find(' '));
    expect_error(t, "bodies[1]." + k, "\"" + k + "\" is a key of a cylinder, not of a sphere (shape = \"sphere\"); " + valid,
                 line_of(t, extra));
  }
  t = with("radius = \"2 mm\"\n", "radius = \"2 mm\"\nmax = [\"1 mm\", \"1 mm\", \"1 mm\"]\n", kSphere);
  expect_error(t, "bodies[1].max", "\"max\" is a key of a box, not of a sphere", line_of(t, "max = [\"1 mm\""));
  // A misspelt key is unknown, with a suggestion.
  t = with("center =", "centre =", kSphere);
  expect_error(t, "bodies[1].centre", "unknown key \"centre\" in a body; did you mean \"center\"? " + valid,
               line_of(t, "centre ="));

  // The other way round: a sphere's key on a cylinder or a box.
  t = with("length = \"5 mm\"\n", "length = \"5 mm\"\ncenter = [\"5 mm\", \"5 mm\", \"4.5 mm\"]\n");
  expect_error(t, "bodies[1].center", "\"center\" is a key of a sphere, not of a cylinder (shape = \"cylinder\")",
               line_of(t, "center = "));
  t = with("shape = \"cylinder\"", "shape = \"disk\"", t);
  expect_error(t, "bodies[1].center", "not of a cylinder (shape = \"disk\")", -1);
  t = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]", "max = [\"10 mm\", \"10 mm\", \"2 mm\"]\nradius = \"1 mm\"");
  expect_error(t, "bodies[0].radius", "\"radius\" is a key of a cylinder or a sphere, not of a box", -1);

  // A sphere is no Taylor bar (its observables measure a bar's length and impact face).
  t = kSphere + "\n[observables]\ntaylor_bar = \"projectile\"\n";
  expect_error(t, "observables.taylor_bar", "\"projectile\" is a sphere; the Taylor-bar observables", line_of(t, "taylor_bar ="));
  EXPECT_NO_THROW(parse_case_string(kSphere + "\n[observables]\nprojectile = \"projectile\"\ntarget = \"plate\"\n", "case.toml"));
}

TEST(CaseFileErrors, InvalidToml) {
  const std::string t = with("name = \"test\"", "name = \"test");
  const CaseError e = error_of(t);
  EXPECT_TRUE(Contains(e.what(), "not valid TOML"));
  EXPECT_EQ(e.line(), line_of(t, "name = \"test"));
}

TEST(CaseFileErrors, UnknownKeyListsValidKeysAndSuggests) {
  std::string t = with("density = \"7850 kg/m^3\"", "densty = \"7850 kg/m^3\"");
  expect_error(t, "materials.steel.densty", "did you mean \"density\"?", line_of(t, "densty"));
  expect_error(t, "materials.steel.densty", "valid keys: density, eos, strength", -1);

  t = with("spacing = \"0.5 mm\"", "spacing = \"0.5 mm\"\nspacng = 1");
  expect_error(t, "numerics.spacng", "did you mean \"spacing\"?", line_of(t, "spacng"));

  t = kBase + "\n[outputs]\nvtu = true\n";
  expect_error(t, "outputs", "did you mean \"output\"?", line_of(t, "[outputs]"));

  // A key of another shape is unknown for this one.
  t = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]", "max = [\"10 mm\", \"10 mm\", \"2 mm\"]\nradius = \"1 mm\"");
  expect_error(t, "bodies[0].radius", "valid keys: name, material, shape, velocity, direction, variable_h, h_min, h_max, min, max",
               line_of(t, "radius = \"1 mm\""));

  t = with("s = 1.489", "s1 = 1.489");
  expect_error(t, "materials.copper.eos.s1", "did you mean \"s\"?", line_of(t, "s1 = 1.489"));

  t = with("strength = { kind = \"elastic\", shear_modulus = \"80 GPa\" }",
           "strength = { kind = \"hydrodynamic\", shear_modulus = \"80 GPa\" }");
  expect_error(t, "materials.steel.strength.shear_modulus", "valid keys: kind", -1);
}

TEST(CaseFileErrors, MissingRequiredKeys) {
  std::string t = with("[time]\nend = \"20 us\"\noutput_interval = \"1 us\"\n", "");
  expect_error(t, "time", "missing in the case file", 0);

  t = with("end = \"20 us\"\n", "");
  expect_error(t, "time.end", "expected a time such as \"20 us\"", line_of(t, "[time]"));

  t = with("density = \"7850 kg/m^3\"\n", "");
  expect_error(t, "materials.steel.density", "missing in a material", line_of(t, "[materials.steel]"));

  t = with("name = \"test\"\n", "");
  expect_error(t, "case.name", "missing", line_of(t, "[case]"));

  t = with("shape = \"box\"\n", "");
  expect_error(t, "bodies[0].shape", "expected one of \"box\", \"cylinder\"", -1);

  t = with("radius = \"2 mm\"\n", "");
  expect_error(t, "bodies[1].radius", "expected a length", -1);

  t = with("eos = { kind = \"mie-gruneisen\", c0 = \"3940 m/s\", s = 1.489, gamma0 = 2.02 }",
           "eos = { kind = \"mie-gruneisen\", c0 = \"3940 m/s\", s = 1.489 }");
  expect_error(t, "materials.copper.eos.gamma0", "missing", -1);

  t = with("eos = { kind = \"linear\", bulk_modulus = \"160 GPa\" }", "eos = { kind = \"linear\" }");
  expect_error(t, "materials.steel.eos.bulk_modulus", "youngs_modulus and poisson_ratio", -1);

  t = with("velocity = \"298 m/s\"\ndirection = [0, 0, -1]", "velocity = \"298 m/s\"");
  expect_error(t, "bodies[1].direction", "needs direction", -1);
}

TEST(CaseFileErrors, WrongType) {
  std::string t = with("spacing = \"0.5 mm\"", "spacing = true");
  expect_error(t, "numerics.spacing", "not a boolean", line_of(t, "spacing = true"));

  t = with("min = [\"0 mm\", \"0 mm\", \"0 mm\"]", "min = [\"0 mm\", \"0 mm\"]");
  expect_error(t, "bodies[0].min", "has 2 entries; expected 3", line_of(t, "min = "));

  t = with("min = [\"0 mm\", \"0 mm\", \"0 mm\"]", "min = \"0 mm\"");
  expect_error(t, "bodies[0].min", "expected an array of 3 lengths", -1);

  t = with("eos = { kind = \"linear\", bulk_modulus = \"160 GPa\" }", "eos = \"linear\"");
  expect_error(t, "materials.steel.eos", "expected a table", line_of(t, "eos = \"linear\""));

  t = kBase + "\n[output]\nvtu = \"yes\"\n";
  expect_error(t, "output.vtu", "expected true or false", line_of(t, "vtu = \"yes\""));

  t = with("name = \"plate\"", "name = 3");
  expect_error(t, "bodies[0].name", "expected a string", -1);
}

TEST(CaseFileErrors, WrongUnits) {
  std::string t = with("radius = \"2 mm\"", "radius = \"2 m/s\"");
  expect_error(t, "bodies[1].radius", "\"2 m/s\" is a velocity; expected a length", line_of(t, "radius = "));

  t = with("min = [\"0 mm\", \"0 mm\", \"0 mm\"]", "min = [\"0 mm\", \"0 GPa\", \"0 mm\"]");
  expect_error(t, "bodies[0].min[1]", "is a pressure; expected a length", line_of(t, "min = "));

  t = with("bulk_modulus = \"160 GPa\"", "bulk_modulus = \"160\"");  // a bare number is SI: 160 Pa
  expect_error(t, "materials.steel.eos.bulk_modulus", "a bare number is in Pa", -1);

  t = with("end = \"20 us\"", "end = \"20 uss\"");
  expect_error(t, "time.end", "unknown unit \"uss\"", line_of(t, "end = "));

  t = with("gamma0 = 2.02", "gamma0 = \"2.02 K\"");
  expect_error(t, "materials.copper.eos.gamma0", "is a temperature", -1);
}

TEST(CaseFileErrors, NonPositiveSizes) {
  std::string t = with("spacing = \"0.5 mm\"", "spacing = \"0 mm\"");
  expect_error(t, "numerics.spacing", "must be greater than zero", line_of(t, "spacing = "));
  t = with("spacing = \"0.5 mm\"", "spacing = -0.001");
  expect_error(t, "numerics.spacing", "must be greater than zero (got -1 mm)", -1);
  t = with("axis = \"z\"", "axis = \"Z\"");
  expect_error(t, "bodies[1].axis", "did you mean \"z\"?", -1);
  t = with("radius = \"2 mm\"", "radius = \"-2 mm\"");
  expect_error(t, "bodies[1].radius", "must be greater than zero", -1);
  t = with("length = \"5 mm\"", "length = 0");
  expect_error(t, "bodies[1].length", "must be greater than zero", -1);
  t = with("density = \"7850 kg/m^3\"", "density = \"0 kg/m^3\"");
  expect_error(t, "materials.steel.density", "at least 1 kg/m^3", -1);
  t = with("bulk_modulus = \"160 GPa\"", "bulk_modulus = \"-160 GPa\"");
  expect_error(t, "materials.steel.eos.bulk_modulus", "at least 100 kPa", -1);
  t = with("shear_modulus = \"80 GPa\"", "shear_modulus = \"0 GPa\"");
  expect_error(t, "materials.steel.strength.shear_modulus", "at least 100 kPa", -1);
}

TEST(CaseFileErrors, BoxMinNotBelowMax) {
  const std::string t = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]", "max = [\"10 mm\", \"10 mm\", \"0 mm\"]");
  expect_error(t, "bodies[0].max", "max[2] = 0 mm must be greater than min[2] = 0 mm", line_of(t, "max = "));
}

TEST(CaseFileErrors, UnknownKindsListValidOnes) {
  std::string t = with("kind = \"mie-gruneisen\"", "kind = \"mie-grueneisen\"");
  expect_error(t, "materials.copper.eos.kind", "did you mean \"mie-gruneisen\"?", line_of(t, "mie-grueneisen"));
  expect_error(t, "materials.copper.eos.kind", "\"linear\", \"polynomial\", \"mie-gruneisen\", \"gruneisen-cubic\"", -1);
  t = with("kind = \"elastic\"", "kind = \"plastic\"");
  expect_error(t, "materials.steel.strength.kind",
               "\"hydrodynamic\", \"elastic\", \"perfectly-plastic\", \"johnson-cook\"", -1);
  t = with("shape = \"box\"", "shape = \"sphre\"");
  expect_error(t, "bodies[0].shape", "did you mean \"sphere\"? valid: \"box\", \"cylinder\", \"disk\", \"plate\", \"sphere\"",
               line_of(t, "sphre"));
  t = with("spacing = \"0.5 mm\"", "spacing = \"0.5 mm\"\nkernel = \"gaussian\"");
  expect_error(t, "numerics.kernel", "\"wendland-c2\", \"cubic-spline\"", -1);
  t = with("specific_heat", "damage = { kind = \"gurson\" }\nspecific_heat");
  expect_error(t, "materials.copper.damage.kind",
               "valid: \"none\", \"critical-plastic-strain\", \"fracture-energy\", \"johnson-cook\"", line_of(t, "gurson"));
  t = with("kind = \"elastic\"", "kind = \"johnson_cook\"");
  expect_error(t, "materials.steel.strength.kind", "did you mean \"johnson-cook\"?", -1);
  t = kBase + "\n[[contacts]]\nbodies = [\"plate\", \"projectile\"]\nkind = \"penality\"\n";
  expect_error(t, "contacts[0].kind", "did you mean \"penalty\"? valid: \"penalty\", \"shared\"",
               line_of(t, "penality"));
}

TEST(CaseFileErrors, BodyNamesUnknownMaterial) {
  const std::string t = with("material = \"copper\"", "material = \"coper\"");
  expect_error(t, "bodies[1].material", "did you mean \"copper\"?", line_of(t, "coper"));
  expect_error(t, "bodies[1].material", "defined materials: \"steel\", \"copper\"", -1);
}

TEST(CaseFileErrors, DuplicateBodyNames) {
  const std::string t = with("name = \"projectile\"", "name = \"plate\"");
  expect_error(t, "bodies[1].name", "duplicate body name \"plate\" (also bodies[0])", -1);
}

TEST(CaseFileErrors, BadNames) {
  std::string t = with("name = \"plate\"", "name = \"the plate\"");
  expect_error(t, "bodies[0].name", "may not contain", -1);
  t = with("[materials.steel]", "[materials.\"st.eel\"]");
  expect_error(t, "materials.st.eel", "may not contain", -1);
}

TEST(CaseFileErrors, MaterialConstantsOutOfRange) {
  struct Case {
    std::string from, to, key, hint;
  };
  const std::vector<Case> cases = {
      {"density = \"7850 kg/m^3\"", "density = \"78500 kg/m^3\"", "materials.steel.density", "at most 30000 kg/m^3"},
      {"poisson_ratio = 0.34", "poisson_ratio = 0.5", "materials.copper.strength.poisson_ratio", "less than 0.5"},
      {"poisson_ratio = 0.34", "poisson_ratio = -1", "materials.copper.strength.poisson_ratio", "greater than -1"},
      {"gamma0 = 2.02", "gamma0 = 6", "materials.copper.eos.gamma0", "at most 5"},
      {"s = 1.489", "s = 0.2", "materials.copper.eos.s", "at least 0.5"},
      {"c0 = \"3940 m/s\"", "c0 = \"30 km/s\"", "materials.copper.eos.c0", "at most 20000 m/s"},
      {"c0 = \"3940 m/s\"", "c0 = 0", "materials.copper.eos.c0", "greater than 0 m/s"},
      {"yield_stress = \"90 MPa\"", "yield_stress = \"-1 MPa\"", "materials.copper.strength.yield_stress",
       "at least 100 kPa"},
      {"yield_stress = \"90 MPa\"", "yield_stress = 490", "materials.copper.strength.yield_stress",
       "a bare number is in Pa"},
      {"shear_modulus = \"80 GPa\"", "shear_modulus = \"3000 GPa\"", "materials.steel.strength.shear_modulus",
       "at most 2000 GPa"},
      {"youngs_modulus = \"124 GPa\"", "youngs_modulus = \"2.5e12\"", "materials.copper.strength.youngs_modulus",
       "at most 2000 GPa"},
      {"specific_heat = \"383 J/(kg K)\"", "specific_heat = \"-1 J/kg/K\"", "materials.copper.specific_heat",
       "greater than 0"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.to);
    const std::string t = with(c.from, c.to);
    expect_error(t, c.key, c.hint, line_of(t, c.to));
  }
}

TEST(CaseFileErrors, ElasticConstantsGivenTwiceOrHalf) {
  std::string t = with("youngs_modulus = \"124 GPa\", poisson_ratio = 0.34",
                       "youngs_modulus = \"124 GPa\", poisson_ratio = 0.34, shear_modulus = \"46 GPa\"");
  expect_error(t, "materials.copper.strength.youngs_modulus", "not both", -1);
  t = with("youngs_modulus = \"124 GPa\", poisson_ratio = 0.34", "youngs_modulus = \"124 GPa\"");
  expect_error(t, "materials.copper.strength.poisson_ratio", "needs poisson_ratio", -1);
}

TEST(CaseFileErrors, NumericsOutOfRange) {
  struct Case {
    std::string to, key, hint;
  };
  const std::vector<Case> cases = {
      {"h_factor = 2.5", "numerics.h_factor", "at most 2"},
      {"h_factor = 0.9", "numerics.h_factor", "at least 1"},
      {"cfl = 0", "numerics.cfl", "greater than 0"},
      {"cfl = 1.5", "numerics.cfl", "at most 1"},
      {"delta = -0.1", "numerics.delta", "at least 0"},
      {"viscosity_linear = -1", "numerics.viscosity_linear", "must not be negative"},
      {"viscosity_quadratic = -1", "numerics.viscosity_quadratic", "must not be negative"},
      {"viscosity_limiter = \"minmod\"", "numerics.viscosity_limiter", "\"none\", \"van-leer\""},
      {"viscosity_limiter_close_approach = 0.5", "numerics.viscosity_limiter_close_approach", "viscosity_limiter = \"van-leer\""},
      {"viscosity_limiter_close_approach = 2\nviscosity_limiter = \"van-leer\"", "numerics.viscosity_limiter_close_approach", "at most 1"},
      {"bulk_viscosity_linear = -0.5", "numerics.bulk_viscosity_linear", "at least 0"},
      {"bulk_viscosity_quadratic = 6", "numerics.bulk_viscosity_quadratic", "at most 5"},
      {"artificial_stress = 1.5", "numerics.artificial_stress", "at most 1"},
      {"artificial_stress = -0.3", "numerics.artificial_stress", "at least 0"},
      {"artificial_stress_exponent = 0", "numerics.artificial_stress_exponent", "at least 1"},
      {"artificial_stress_exponent = 4.5", "numerics.artificial_stress_exponent", "whole number"},
      {"artificial_stress_of = \"mean\"", "numerics.artificial_stress_of", "\"deviatoric\", \"total\""},
      {"correction_max_condition = 2", "numerics.correction_max_condition", "greater than 3"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.to);
    const std::string t = with("spacing = \"0.5 mm\"", "spacing = \"0.5 mm\"\n" + c.to);
    expect_error(t, c.key, c.hint, line_of(t, c.to));
  }
}

TEST(CaseFileErrors, IntervalsLongerThanEnd) {
  std::string t = with("output_interval = \"1 us\"", "output_interval = \"1 ms\"");
  expect_error(t, "time.output_interval", "longer than time.end = 20 us", line_of(t, "output_interval"));
  t = with("output_interval = \"1 us\"", "output_interval = \"1 us\"\nframe_interval = \"30 us\"");
  expect_error(t, "time.frame_interval", "at most the end time", -1);
  t = with("output_interval = \"1 us\"", "output_interval = \"1 us\"\ncheckpoint_interval = \"30 us\"");
  expect_error(t, "time.checkpoint_interval", "longer than time.end", -1);
  t = with("end = \"20 us\"", "end = \"0 us\"");
  expect_error(t, "time.end", "greater than zero", -1);
}

TEST(CaseFileErrors, Boundaries) {
  std::string t = kBase + "\n[[boundaries.symmetry]]\naxis = \"w\"\nposition = \"0 mm\"\n";
  expect_error(t, "boundaries.symmetry[0].axis", "valid: \"x\", \"y\", \"z\"", line_of(t, "axis = \"w\""));
  t = kBase + "\n[[boundaries.symmetry]]\naxis = \"x\"\n[[boundaries.symmetry]]\naxis = \"x\"\nposition = 0\n";
  expect_error(t, "boundaries.symmetry[1].position", "the same plane as boundaries.symmetry[0]", -1);
  t = kBase + "\n[[boundaries.symmetry]]\naxis = \"x\"\n[[boundaries.symmetry]]\naxis = \"x\"\nposition = \"10 mm\"\n";
  EXPECT_EQ(parse_case_string(t, "case.toml").symmetry.size(), 2u);  // two planes on one axis: a channel
  // A wall joins the same list of planes, after the symmetry planes, and is named by its own table.
  t = kBase + "\n[[boundaries.wall]]\naxis = \"z\"\nposition = \"-5 mm\"\n[[boundaries.symmetry]]\naxis = \"x\"\n";
  {
    const CaseSpec w = parse_case_string(t, "case.toml");
    ASSERT_EQ(w.symmetry.size(), 2u);
    EXPECT_FALSE(w.symmetry[0].wall);
    EXPECT_EQ(w.symmetry[0].key, "boundaries.symmetry[0]");
    EXPECT_TRUE(w.symmetry[1].wall);
    EXPECT_EQ(w.symmetry[1].axis, 2);
    EXPECT_DOUBLE_EQ(w.symmetry[1].position, -5e-3);
    EXPECT_EQ(w.symmetry[1].key, "boundaries.wall[0]");
    EXPECT_EQ(w.symmetry[1].line, line_of(t, "[[boundaries.wall]]"));
  }
  t = kBase;
  for (int k = 0; k < 7; ++k) t += "\n[[boundaries.wall]]\naxis = \"x\"\nposition = \"" + std::to_string(k) + " mm\"\n";
  expect_error(t, "boundaries.wall[6]", "too many planes: at most 6, symmetry planes and walls together", -1);
  t = kBase + "\n[[boundaries.symmetry]]\naxis = \"z\"\n[[boundaries.wall]]\naxis = \"z\"\nposition = 0\n";
  expect_error(t, "boundaries.wall[0].position", "the same plane as boundaries.symmetry[0]", -1);
  t = kBase + "\n[[boundaries.wall]]\naxis = \"z\"\nfriction = 0.1\n";
  expect_error(t, "boundaries.wall[0].friction", "axis", -1);
  t = kBase + "\n[[boundaries.fixed]]\nregion = \"box\"\nbody = \"plat\"\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n";
  expect_error(t, "boundaries.fixed[0].body", "did you mean \"plate\"?", line_of(t, "body = \"plat\""));
  t = kBase + "\n[[boundaries.fixed]]\nregion = \"sphere\"\n";
  expect_error(t, "boundaries.fixed[0].region", "\"box\", \"outside-cylinder\"", -1);
  t = kBase + "\n[[boundaries.fixed]]\nregion = \"outside-cylinder\"\naxis = \"z\"\naxis_point = [0, 0, 0]\nradius = 0\n";
  expect_error(t, "boundaries.fixed[0].radius", "greater than zero", -1);
  t = kBase + "\n[boundaries]\nfixd = []\n";
  expect_error(t, "boundaries.fixd", "did you mean \"fixed\"?", -1);
}

TEST(CaseFileErrors, VelocityGivenTwoWays) {
  std::string t = with("velocity = \"298 m/s\"", "velocity = [0, 0, -298]");
  expect_error(t, "bodies[1].direction", "not both", -1);
  t = with("velocity = \"298 m/s\"", "velocity = \"-298 m/s\"");
  expect_error(t, "bodies[1].velocity", "reverse the direction", -1);
  t = with("direction = [0, 0, -1]", "direction = [0, 0, 0]");
  expect_error(t, "bodies[1].direction", "zero vector", -1);
}

// ---- overrides ----

TEST(CaseFileOverrides, ValuesAreParsedLikeTheFile) {
  const CaseSpec s = parse_case_string(kBase, "case.toml",
                                       {"projectile.velocity=400 m/s", "numerics.cfl=0.1", "time.end=40us",
                                        "steel.density=7800 kg/m^3", "copper.eos.c0 = \"4000 m/s\"",
                                        "case.name=renamed", "output.csv=false", "plate.max=[0.01, 0.01, 0.004]"});
  EXPECT_DOUBLE_EQ(s.bodies[1].velocity.z, -400);
  EXPECT_DOUBLE_EQ(s.numerics.cfl, 0.1);
  EXPECT_DOUBLE_EQ(s.time.end, 40e-6);
  EXPECT_DOUBLE_EQ(s.materials[0].params.eos.rho0, 7800);
  EXPECT_DOUBLE_EQ(s.materials[1].params.eos.c0, 4000);
  EXPECT_EQ(s.name, "renamed");
  EXPECT_FALSE(s.output.csv);
  EXPECT_DOUBLE_EQ(s.bodies[0].box_max.z, 4e-3);
}

TEST(CaseFileOverrides, QuotedAndExplicitForms) {
  const CaseSpec s = parse_case_string(kBase, "case.toml",
                                       {"bodies.projectile.velocity=\"350 m/s\"", "materials.steel.eos.bulk_modulus=170 GPa",
                                        "projectile.direction=[1, 0, 0]"});
  EXPECT_DOUBLE_EQ(s.bodies[1].velocity.x, 350);
  EXPECT_DOUBLE_EQ(s.bodies[1].velocity.z, 0);
  EXPECT_DOUBLE_EQ(s.materials[0].params.eos.k1, 170e9);
}

TEST(CaseFileOverrides, SpeedKeepsTheFilesDirection) {
  const std::string t = with("velocity = \"298 m/s\"\ndirection = [0, 0, -1]",
                             "velocity = [\"0 m/s\", \"-60 m/s\", \"-80 m/s\"]");
  const CaseSpec s = parse_case_string(t, "case.toml", {"projectile.velocity=200 m/s"});
  EXPECT_NEAR(s.bodies[1].velocity.x, 0, 1e-12);
  EXPECT_NEAR(s.bodies[1].velocity.y, -120, 1e-12);
  EXPECT_NEAR(s.bodies[1].velocity.z, -160, 1e-12);
}

TEST(CaseFileOverrides, NewKeysAreCreatedAndValidated) {
  const CaseSpec s = parse_case_string(kBase, "case.toml", {"numerics.h_factor=1.3", "output.vtu=false"});
  EXPECT_DOUBLE_EQ(s.numerics.h_factor, 1.3);
  EXPECT_FALSE(s.output.vtu);

  CaseError e = error_of(kBase, {"numerics.cfl=2"});
  EXPECT_EQ(e.key(), "numerics.cfl");
  EXPECT_EQ(e.line(), 0);
  EXPECT_TRUE(Contains(e.what(), "at most 1"));
  EXPECT_TRUE(Contains(e.what(), "set by override \"numerics.cfl=2\""));

  e = error_of(kBase, {"numerics.cfll=0.1"});
  EXPECT_EQ(e.key(), "numerics.cfll");
  EXPECT_TRUE(Contains(e.what(), "did you mean \"cfl\"?"));

  e = error_of(kBase, {"projectile.radius=3 m/s"});
  EXPECT_EQ(e.key(), "bodies[1].radius");
  EXPECT_TRUE(Contains(e.what(), "is a velocity"));
}

TEST(CaseFileOverrides, UnknownTargetsAreErrors) {
  CaseError e = error_of(kBase, {"projectle.velocity=1"});
  EXPECT_EQ(e.key(), "projectle.velocity=1");
  EXPECT_TRUE(Contains(e.what(), "did you mean \"projectile\"?"));
  EXPECT_TRUE(Contains(e.what(), "bodies: \"plate\", \"projectile\""));
  EXPECT_TRUE(Contains(e.what(), "materials: \"copper\", \"steel\""));

  e = error_of(kBase, {"bodies.rod.velocity=1"});
  EXPECT_TRUE(Contains(e.what(), "no body named \"rod\""));

  e = error_of(kBase, {"numerics.cfl"});
  EXPECT_EQ(e.key(), "numerics.cfl");
  EXPECT_TRUE(Contains(e.what(), "KEY=VALUE"));

  e = error_of(kBase, {"cfl=0.1"});
  EXPECT_TRUE(Contains(e.what(), "TABLE.key"));

  e = error_of(kBase, {"projectile.velocity.x=1"});
  EXPECT_TRUE(Contains(e.what(), "not a table"));

  const std::string t = with("name = \"plate\"", "name = \"steel\"");
  e = error_of(t, {"steel.density=1"});
  EXPECT_TRUE(Contains(e.what(), "names both a body and a material"));
}

TEST(CaseFileOverrides, SpacingOverride) {
  CaseSpec s = parse_case_string(kBase, "case.toml", {"numerics.spacing=1 mm"}, "0.25mm");
  EXPECT_DOUBLE_EQ(s.numerics.spacing, 0.25e-3);
  const CaseError e = error_of(kBase, {}, "0.25 m/s");
  EXPECT_EQ(e.key(), "numerics.spacing");
  EXPECT_TRUE(Contains(e.what(), "spacing override"));
}

// ---- files ----

TEST(CaseFileLoad, MissingFile) {
  try {
    impactsph::load_case_file(std::string(IMPACTSPH_TEST_DATA) + "/no-such-case.toml");
    FAIL() << "accepted";
  } catch (const CaseError& e) {
    EXPECT_TRUE(Contains(e.what(), "no such case file"));
  }
}

TEST(CaseFileLoad, FixturesNameFileLineAndKey) {
  struct Fixture {
    std::string file, key, hint;
    int line;
  };
  const std::vector<Fixture> fixtures = {
      {"bad_unknown_key.toml", "materials.steel.strength.yeild_stress", "did you mean \"yield_stress\"?", 12},
      {"bad_units.toml", "bodies[0].max[2]", "\"3 kg\" is a mass; expected a length", 17},
      {"bad_syntax.toml", "", "not valid TOML", 5},
      {"bad_material_ref.toml", "bodies[0].material", "no material named \"stel\"", 13},
  };
  for (const Fixture& f : fixtures) {
    SCOPED_TRACE(f.file);
    const std::string path = std::string(IMPACTSPH_TEST_DATA) + "/" + f.file;
    try {
      impactsph::load_case_file(path);
      ADD_FAILURE() << "accepted";
    } catch (const CaseError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_EQ(e.line(), f.line) << e.what();
      EXPECT_EQ(e.key(), f.key);
      EXPECT_TRUE(Contains(e.what(), f.hint));
      EXPECT_TRUE(Contains(e.what(), path + ":" + std::to_string(f.line) + ": "));
    }
  }
}

TEST(CaseFileLoad, DocumentedExampleLoads) {
  const CaseSpec s = impactsph::load_case_file(std::string(IMPACTSPH_TEST_DATA) + "/example_plate_impact.toml");
  EXPECT_EQ(s.name, "plate-impact-example");
  EXPECT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.fixed.size(), 1u);
  EXPECT_EQ(s.symmetry.size(), 2u);
  EXPECT_NEAR(s.bodies[1].velocity.z, -298, 1e-12);
  const auto& weldox = s.materials[0].params;
  EXPECT_EQ(weldox.strength.kind, impactsph::StrengthKind::JohnsonCook);
  EXPECT_DOUBLE_EQ(weldox.strength.jc_a, 490e6);
  EXPECT_DOUBLE_EQ(weldox.strength.jc_b, 807e6);
  EXPECT_DOUBLE_EQ(weldox.strength.reference_strain_rate, 5e-4);
  EXPECT_DOUBLE_EQ(weldox.strength.melt_temperature, 0);  // F neglects thermal effects
  EXPECT_EQ(weldox.damage.kind, impactsph::DamageKind::CriticalPlasticStrain);
  EXPECT_DOUBLE_EQ(weldox.damage.critical_plastic_strain, 0.3);
  ASSERT_EQ(s.contacts.size(), 1u);
  EXPECT_EQ(s.contacts[0].kind, impactsph::ContactSpec::Kind::Penalty);
  EXPECT_EQ(s.contacts[0].index_a, 1);
  EXPECT_EQ(s.contacts[0].index_b, 0);
}

// The complete example of docs/case-files.md is the test data file, byte for byte.
TEST(CaseFileLoad, DocumentedExampleMatchesTheDocs) {
  auto read = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in.good()) << path;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  };
  const std::string docs = read(std::string(IMPACTSPH_TEST_DATA) + "/../../docs/case-files.md");
  const auto section = docs.find("## Complete example");
  ASSERT_NE(section, std::string::npos);
  const auto open = docs.find("```toml\n", section);
  ASSERT_NE(open, std::string::npos);
  const auto begin = open + 8;
  const auto end = docs.find("```", begin);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(docs.substr(begin, end - begin), read(std::string(IMPACTSPH_TEST_DATA) + "/example_plate_impact.toml"));
}

// ---- Johnson-Cook strength, damage models, contacts, source lines ----

namespace {

// kBase with the copper strength replaced by `strength` (an inline table's contents) and `extra` lines
// added to the copper material.
std::string copper(const std::string& strength, const std::string& extra = "") {
  return with("strength = { kind = \"perfectly-plastic\", youngs_modulus = \"124 GPa\", poisson_ratio = 0.34, "
              "yield_stress = \"90 MPa\" }",
              "strength = { " + strength + " }" + (extra.empty() ? "" : "\n" + extra));
}

const std::string kJc = "kind = \"johnson-cook\", youngs_modulus = \"124 GPa\", poisson_ratio = 0.34, a = \"90 MPa\", "
                        "b = \"292 MPa\", n = 0.31";

}  // namespace

TEST(CaseFileMaterials, JohnsonCookStrength) {
  CaseSpec s = parse_case_string(
      copper(kJc + ", c = 0.025, m = 1.09, reference_strain_rate = \"1e-3 /s\", melt_temperature = \"1356 K\", "
                   "taylor_quinney = 0.85"),
      "case.toml");
  const auto& st = s.materials[1].params.strength;
  EXPECT_EQ(st.kind, impactsph::StrengthKind::JohnsonCook);
  EXPECT_NEAR(st.shear_modulus, 124e9 / (2 * 1.34), 1);
  EXPECT_DOUBLE_EQ(st.jc_a, 90e6);
  EXPECT_DOUBLE_EQ(st.jc_b, 292e6);
  EXPECT_DOUBLE_EQ(st.jc_n, 0.31);
  EXPECT_DOUBLE_EQ(st.jc_c, 0.025);
  EXPECT_DOUBLE_EQ(st.jc_m, 1.09);
  EXPECT_DOUBLE_EQ(st.reference_strain_rate, 1e-3);
  EXPECT_DOUBLE_EQ(st.melt_temperature, 1356);
  EXPECT_DOUBLE_EQ(st.taylor_quinney, 0.85);
  EXPECT_DOUBLE_EQ(s.materials[1].params.specific_heat, 383);

  // Defaults; a linear EOS from E and nu works as for the other strength kinds; shear_modulus directly.
  s = parse_case_string(copper("kind = \"johnson-cook\", shear_modulus = \"46 GPa\", a = \"90 MPa\", b = 0"), "case.toml");
  const auto& d = s.materials[1].params.strength;
  EXPECT_DOUBLE_EQ(d.shear_modulus, 46e9);
  EXPECT_DOUBLE_EQ(d.jc_b, 0);
  EXPECT_DOUBLE_EQ(d.jc_n, 1);  // not needed without hardening
  EXPECT_DOUBLE_EQ(d.jc_c, 0);
  EXPECT_DOUBLE_EQ(d.jc_m, 1);
  EXPECT_DOUBLE_EQ(d.reference_strain_rate, 1);
  EXPECT_DOUBLE_EQ(d.melt_temperature, 0);  // no thermal softening
  EXPECT_DOUBLE_EQ(d.taylor_quinney, 0.9);

  // Without melt_temperature no specific heat is needed.
  const std::string no_cp = with("specific_heat = \"383 J/(kg K)\"\n", "", copper(kJc));
  EXPECT_NO_THROW(parse_case_string(no_cp, "case.toml"));
}

TEST(CaseFileMaterials, JohnsonCookErrors) {
  struct Case {
    std::string strength, key, hint;
  };
  const std::string k = "materials.copper.strength.";
  const std::vector<Case> cases = {
      {kJc + ", a = 0", k + "a", "at least 100 kPa"},
      {"kind = \"johnson-cook\", shear_modulus = \"46 GPa\", a = 490, b = 0", k + "a", "a bare number is in Pa"},
      {kJc + ", b = \"-1 MPa\"", k + "b", "b = 0 means no strain hardening"},
      {kJc + ", n = 0", k + "n", "greater than 0"},
      {kJc + ", n = 2.5", k + "n", "at most 2"},
      {kJc + ", c = -0.1", k + "c", "at least 0"},
      {kJc + ", c = 1.5", k + "c", "at most 1"},
      {kJc + ", m = 0", k + "m", "greater than 0"},
      {kJc + ", m = 6", k + "m", "at most 5"},
      {kJc + ", reference_strain_rate = 0", k + "reference_strain_rate", "greater than zero"},
      {kJc + ", reference_strain_rate = \"1 m/s\"", k + "reference_strain_rate", "is a velocity; expected a strain rate"},
      {kJc + ", taylor_quinney = 1.2", k + "taylor_quinney", "at most 1"},
      {kJc + ", melt_temperature = \"200 K\"", k + "melt_temperature", "above room_temperature = 293 K"},
      {kJc + ", melt_temperature = \"-5 K\"", k + "melt_temperature", "greater than zero"},
      {kJc + ", yield_stress = \"90 MPa\"", k + "yield_stress", "unknown key"},
      {kJc + ", shear_modulus = \"46 GPa\"", k + "youngs_modulus", "not both"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.strength);
    // Keys given twice in an inline table are invalid TOML, so replace the default ones.
    std::string strength = c.strength;
    for (const std::string key : {"a", "b", "n"}) {
      const std::string given = ", " + key + " = ";
      const auto first = strength.find(given), last = strength.rfind(given);
      if (first != last) strength.erase(first, strength.find(',', first + 1) - first);
    }
    const std::string t = copper(strength);
    expect_error(t, c.key, c.hint, line_of(t, "kind = \"johnson-cook\""));
  }

  // Required constants.
  std::string t = copper("kind = \"johnson-cook\", shear_modulus = \"46 GPa\", b = \"292 MPa\", n = 0.3");
  expect_error(t, "materials.copper.strength.a", "missing in the strength model", -1);
  t = copper("kind = \"johnson-cook\", shear_modulus = \"46 GPa\", a = \"90 MPa\", n = 0.3");
  expect_error(t, "materials.copper.strength.b", "missing", -1);
  t = copper("kind = \"johnson-cook\", shear_modulus = \"46 GPa\", a = \"90 MPa\", b = \"292 MPa\"");
  expect_error(t, "materials.copper.strength.n", "missing", -1);
  t = copper("kind = \"johnson-cook\", a = \"90 MPa\", b = 0");
  expect_error(t, "materials.copper.strength.shear_modulus", "youngs_modulus", -1);

  // Thermal softening heats the material, which needs c_p; the room temperature is the material's.
  t = with("specific_heat = \"383 J/(kg K)\"\n", "", copper(kJc + ", melt_temperature = \"1356 K\""));
  expect_error(t, "materials.copper.specific_heat", "needs the temperature", line_of(t, "[materials.copper]"));
  t = copper(kJc + ", melt_temperature = \"1356 K\"", "room_temperature = \"1400 K\"");
  expect_error(t, "materials.copper.strength.melt_temperature", "above room_temperature = 1400 K", -1);
}

TEST(CaseFileMaterials, DamageModels) {
  CaseSpec s = parse_case_string(
      copper(kJc, "damage = { kind = \"critical-plastic-strain\", critical_plastic_strain = 0.3 }"), "case.toml");
  EXPECT_EQ(s.materials[1].params.damage.kind, impactsph::DamageKind::CriticalPlasticStrain);
  EXPECT_DOUBLE_EQ(s.materials[1].params.damage.critical_plastic_strain, 0.3);
  EXPECT_EQ(s.materials[0].params.damage.kind, impactsph::DamageKind::None);

  // Johnson-Cook failure on a perfectly plastic material; d4, d5 and min_failure_strain default to 0.
  std::string t = with("specific_heat", "damage = { kind = \"johnson-cook\", d1 = -0.09, d2 = 0.25, d3 = -0.5 }\nspecific_heat");
  s = parse_case_string(t, "case.toml");
  const auto& d = s.materials[1].params.damage;
  EXPECT_EQ(d.kind, impactsph::DamageKind::JohnsonCook);
  EXPECT_DOUBLE_EQ(d.d1, -0.09);
  EXPECT_DOUBLE_EQ(d.d2, 0.25);
  EXPECT_DOUBLE_EQ(d.d3, -0.5);
  EXPECT_DOUBLE_EQ(d.d4, 0);
  EXPECT_DOUBLE_EQ(d.d5, 0);
  EXPECT_DOUBLE_EQ(d.min_failure_strain, 0);

  t = copper(kJc, "damage = { kind = \"johnson-cook\", d1 = 0.54, d2 = 4.89, d3 = -3.03, d4 = 0.014, d5 = 1.12, "
                  "min_failure_strain = 0.05 }");
  s = parse_case_string(t, "case.toml");
  const auto& e = s.materials[1].params.damage;
  EXPECT_DOUBLE_EQ(e.d1, 0.54);
  EXPECT_DOUBLE_EQ(e.d2, 4.89);
  EXPECT_DOUBLE_EQ(e.d3, -3.03);
  EXPECT_DOUBLE_EQ(e.d4, 0.014);
  EXPECT_DOUBLE_EQ(e.d5, 1.12);
  EXPECT_DOUBLE_EQ(e.min_failure_strain, 0.05);
}

TEST(CaseFileMaterials, DamageErrors) {
  struct Case {
    std::string damage, key, hint;
  };
  const std::string k = "materials.copper.damage.";
  const std::string jc = "kind = \"johnson-cook\", ";
  const std::vector<Case> cases = {
      {"kind = \"critical-plastic-strain\", critical_plastic_strain = 0", k + "critical_plastic_strain", "greater than 0"},
      {"kind = \"critical-plastic-strain\", critical_plastic_strain = 11", k + "critical_plastic_strain", "at most 10"},
      {"kind = \"critical-plastic-strain\"", k + "critical_plastic_strain", "missing in the damage model"},
      {"kind = \"critical-plastic-strain\", critical_plastic_strain = 0.3, d1 = 1", k + "d1", "unknown key"},
      {"kind = \"fracture-energy\", band_width_factor = 2.3", k + "fracture_energy", "missing in the damage model"},
      {"kind = \"fracture-energy\", fracture_energy = \"0 kJ/m^2\", band_width_factor = 2.3", k + "fracture_energy",
       "greater than 0 J/m^2"},
      {"kind = \"fracture-energy\", fracture_energy = \"150 MPa\", band_width_factor = 2.3", k + "fracture_energy",
       "is a pressure"},
      {"kind = \"fracture-energy\", fracture_energy = \"150 kJ/m^2\"", k + "band_width_factor", "missing in the damage model"},
      {"kind = \"fracture-energy\", fracture_energy = \"150 kJ/m^2\", band_width_factor = 0.2", k + "band_width_factor",
       "initial smoothing lengths"},
      {"kind = \"fracture-energy\", fracture_energy = \"150 kJ/m^2\", band_width_factor = 2, critical_plastic_strain = 0.3",
       k + "critical_plastic_strain", "unknown key"},
      {"kind = \"fracture-energy\", fracture_energy = \"150 kJ/m^2\", band_width_factor = 2, crack_faces = \"open\"",
       k + "crack_faces", "\"scaled\", \"compression\""},
      {"kind = \"critical-plastic-strain\", critical_plastic_strain = 0.3, pair_factor = false, crack_faces = \"compression\"",
       k + "crack_faces", "set pair_factor = true"},
      {jc + "d1 = -1.5, d2 = 1, d3 = -1", k + "d1", "at least -1"},
      {jc + "d1 = 21, d2 = 1, d3 = -1", k + "d1", "at most 20"},
      {jc + "d1 = 0.1, d2 = -0.1, d3 = -1", k + "d2", "at least 0"},
      {jc + "d1 = 0.1, d2 = 1, d3 = -25", k + "d3", "at least -20"},
      {jc + "d1 = 0.1, d2 = 1, d3 = -1, d4 = 30", k + "d4", "at most 20"},
      {jc + "d1 = 0.1, d2 = 1, d3 = -1, d5 = -30", k + "d5", "at least -20"},
      {jc + "d1 = 0.1, d2 = 1, d3 = -1, min_failure_strain = -0.1", k + "min_failure_strain", "at least 0"},
      {jc + "d2 = 1, d3 = -1", k + "d1", "missing in the damage model"},
      {jc + "d1 = 0.1, d2 = 1, d3 = -1, critical_plastic_strain = 0.3", k + "critical_plastic_strain", "unknown key"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.damage);
    const std::string t = with("specific_heat", "damage = { " + c.damage + " }\nspecific_heat");
    expect_error(t, c.key, c.hint, line_of(t, "damage = {"));
  }

  // Damage accumulates plastic strain: an elastic or hydrodynamic material cannot have it.
  std::string t = with("strength = { kind = \"elastic\", shear_modulus = \"80 GPa\" }",
                       "strength = { kind = \"elastic\", shear_modulus = \"80 GPa\" }\n"
                       "damage = { kind = \"critical-plastic-strain\", critical_plastic_strain = 0.5 }");
  expect_error(t, "materials.steel.damage.kind", "the strength kind \"elastic\" has no plasticity",
               line_of(t, "damage = {"));
  t = with("strength = { kind = \"elastic\", shear_modulus = \"80 GPa\" }",
           "strength = { kind = \"hydrodynamic\" }\ndamage = { kind = \"johnson-cook\", d1 = 0.1, d2 = 1, d3 = -1 }");
  expect_error(t, "materials.steel.damage.kind", "use strength kind \"johnson-cook\" or \"perfectly-plastic\"", -1);
}

TEST(CaseFileContacts, ReadsPairs) {
  const std::string t = kBase + R"(
[[contacts]]
bodies = ["projectile", "plate"]

[[contacts]]
bodies = ["plate", "anvil"]
kind = "shared"

[[contacts]]
bodies = ["anvil", "projectile"]
kind = "penalty"
penalty_scale = 0.5
contact_distance = 1.5
)";
  const std::string anvil = with("[numerics]", "[[bodies]]\nname = \"anvil\"\nmaterial = \"steel\"\nshape = \"box\"\n"
                                               "min = [\"0 mm\", \"0 mm\", \"-2 mm\"]\nmax = [\"10 mm\", \"10 mm\", \"0 mm\"]\n\n[numerics]",
                                 t);
  const CaseSpec s = parse_case_string(anvil, "case.toml");
  ASSERT_EQ(s.contacts.size(), 3u);
  const auto& a = s.contacts[0];
  EXPECT_EQ(a.kind, impactsph::ContactSpec::Kind::Penalty);  // the default kind of a listed pair
  EXPECT_EQ(a.body_a, "projectile");
  EXPECT_EQ(a.body_b, "plate");
  EXPECT_EQ(a.index_a, 1);
  EXPECT_EQ(a.index_b, 0);
  EXPECT_DOUBLE_EQ(a.penalty_scale, 0.3);
  EXPECT_DOUBLE_EQ(a.contact_distance, 1.0);
  EXPECT_EQ(a.line, line_of(anvil, "[[contacts]]"));
  EXPECT_EQ(s.contacts[1].kind, impactsph::ContactSpec::Kind::Shared);
  EXPECT_EQ(s.contacts[1].index_b, 2);
  EXPECT_DOUBLE_EQ(s.contacts[2].penalty_scale, 0.5);
  EXPECT_DOUBLE_EQ(s.contacts[2].contact_distance, 1.5);
  EXPECT_EQ(s.contacts[2].index_a, 2);
  EXPECT_EQ(s.contacts[2].index_b, 1);
  EXPECT_TRUE(parse_case_string(kBase, "case.toml").contacts.empty());
}

TEST(CaseFileContacts, Errors) {
  auto contact = [](const std::string& body) { return kBase + "\n[[contacts]]\n" + body + "\n"; };
  std::string t = contact("bodies = [\"projectile\", \"plat\"]");
  expect_error(t, "contacts[0].bodies[1]", "no body named \"plat\"; did you mean \"plate\"?", line_of(t, "bodies = ["));
  expect_error(t, "contacts[0].bodies[1]", "bodies: \"plate\", \"projectile\"", -1);
  t = contact("bodies = [\"plate\", \"plate\"]");
  expect_error(t, "contacts[0].bodies", "names \"plate\" twice", line_of(t, "bodies = ["));
  t = contact("bodies = [\"plate\", \"projectile\"]\n[[contacts]]\nbodies = [\"projectile\", \"plate\"]\nkind = \"shared\"");
  expect_error(t, "contacts[1].bodies", "already listed in contacts[0]", line_of(t, "bodies = [\"projectile\""));
  t = contact("bodies = [\"plate\", \"projectile\"]\nkind = \"glue\"");
  expect_error(t, "contacts[0].kind", "valid: \"penalty\", \"shared\"", line_of(t, "glue"));
  t = contact("bodies = [\"plate\", \"projectile\"]\npenalty_scale = 0");
  expect_error(t, "contacts[0].penalty_scale", "greater than 0", -1);
  t = contact("bodies = [\"plate\", \"projectile\"]\npenalty_scale = 11");
  expect_error(t, "contacts[0].penalty_scale", "at most 10", -1);
  t = contact("bodies = [\"plate\", \"projectile\"]\ncontact_distance = 0.4");
  expect_error(t, "contacts[0].contact_distance", "at least 0.5", -1);
  t = contact("bodies = [\"plate\", \"projectile\"]\ncontact_distance = 3.5");
  expect_error(t, "contacts[0].contact_distance", "at most 3", -1);
  t = contact("bodies = [\"plate\", \"projectile\"]\nkind = \"shared\"\npenalty_scale = 0.3");
  expect_error(t, "contacts[0].penalty_scale", "unknown key \"penalty_scale\" in a contact", -1);
  t = contact("bodies = [\"plate\", \"projectile\"]\npenalty_scal = 0.3");
  expect_error(t, "contacts[0].penalty_scal", "did you mean \"penalty_scale\"?", -1);
  t = contact("bodies = [\"plate\", \"projectile\", \"plate\"]");
  expect_error(t, "contacts[0].bodies", "has 3 entries; expected two body names", -1);
  t = contact("bodies = \"plate\"");
  expect_error(t, "contacts[0].bodies", "expected an array of two body names", -1);
  t = contact("bodies = [\"plate\", 2]");
  expect_error(t, "contacts[0].bodies[1]", "expected a string", -1);
  t = contact("kind = \"penalty\"");
  expect_error(t, "contacts[0].bodies", "missing in a contact", line_of(t, "[[contacts]]"));
  t = "contacts = 3\n" + kBase;
  expect_error(t, "contacts", "expected an array of tables", -1);
}

TEST(CaseFile, SourceLinesOfTables) {
  const std::string t = kBase + R"(
[[boundaries.fixed]]
region = "box"
min = [0, 0, 0]
max = [0.001, 0.01, 0.002]

[[boundaries.symmetry]]
axis = "x"

[[contacts]]
bodies = ["plate", "projectile"]
)";
  const CaseSpec s = parse_case_string(t, "case.toml");
  EXPECT_EQ(s.materials[0].line, line_of(t, "[materials.steel]"));
  EXPECT_EQ(s.materials[1].line, line_of(t, "[materials.copper]"));
  EXPECT_EQ(s.bodies[0].line, line_of(t, "[[bodies]]"));
  EXPECT_EQ(s.bodies[1].line, line_of(t, "[[bodies]]\nname = \"projectile\""));
  EXPECT_EQ(s.fixed[0].line, line_of(t, "[[boundaries.fixed]]"));
  EXPECT_EQ(s.symmetry[0].line, line_of(t, "[[boundaries.symmetry]]"));
  EXPECT_EQ(s.contacts[0].line, line_of(t, "[[contacts]]"));
  EXPECT_EQ(s.numerics.spacing_line, line_of(t, "spacing = "));
  // A value from an override has no line.
  EXPECT_EQ(parse_case_string(t, "case.toml", {}, "1 mm").numerics.spacing_line, 0);
}

// Issue 17: projectile noses on a cylinder, read with their lengths, and every bad nose named by its key.
TEST(CaseFile, ReadsNoses) {
  const std::string flat_end = "length = \"5 mm\"\n";
  auto nose = [&](const std::string& table) { return with(flat_end, flat_end + "nose = " + table + "\n"); };
  CaseSpec s = parse_case_string(kBase, "case.toml");
  EXPECT_EQ(s.bodies[1].nose, Nose::Flat);
  EXPECT_EQ(s.bodies[1].nose_length, 0);
  s = parse_case_string(nose("{ kind = \"flat\" }"), "case.toml");
  EXPECT_EQ(s.bodies[1].nose, Nose::Flat);
  s = parse_case_string(nose("{ kind = \"hemispherical\", at = \"base\" }"), "case.toml");
  EXPECT_EQ(s.bodies[1].nose, Nose::Hemispherical);
  EXPECT_TRUE(s.bodies[1].nose_at_base);
  EXPECT_DOUBLE_EQ(s.bodies[1].nose_length, 2e-3);  // the radius
  s = parse_case_string(nose("{ kind = \"conical\", length = \"3 mm\", at = \"top\" }"), "case.toml");
  EXPECT_EQ(s.bodies[1].nose, Nose::Conical);
  EXPECT_FALSE(s.bodies[1].nose_at_base);
  EXPECT_DOUBLE_EQ(s.bodies[1].nose_length, 3e-3);
  s = parse_case_string(nose("{ kind = \"ogival\", crh = 1.5, at = \"base\" }"), "case.toml");
  EXPECT_EQ(s.bodies[1].nose, Nose::Ogival);
  EXPECT_DOUBLE_EQ(s.bodies[1].nose_crh, 1.5);
  EXPECT_NEAR(s.bodies[1].nose_length, 2e-3 * std::sqrt(5.0), 1e-15);  // R sqrt(4 crh - 1)
}

TEST(CaseFileErrors, BadNoses) {
  const std::string flat_end = "length = \"5 mm\"\n";
  auto nose = [&](const std::string& table) { return with(flat_end, flat_end + "nose = " + table + "\n"); };
  std::string t = nose("{ kind = \"spitzer\", at = \"base\" }");
  expect_error(t, "bodies[1].nose.kind", "unknown kind \"spitzer\"; valid: \"flat\", \"hemispherical\", \"conical\", \"ogival\"",
               line_of(t, "nose ="));
  t = nose("{ kind = \"conical\", at = \"base\" }");
  expect_error(t, "bodies[1].nose.length", "missing", -1);
  t = nose("{ kind = \"conical\", length = \"3 mm\" }");
  expect_error(t, "bodies[1].nose.at", "expected one of \"base\", \"top\"", -1);
  t = nose("{ kind = \"conical\", length = \"3 mm\", at = \"front\" }");
  expect_error(t, "bodies[1].nose.at", "unknown at \"front\"", -1);
  t = nose("{ kind = \"conical\", length = \"6 mm\", at = \"base\" }");
  expect_error(t, "bodies[1].nose.length", "nose is 6 mm long, longer than the cylinder (length = 5 mm)", -1);
  t = nose("{ kind = \"conical\", length = \"3 m/s\", at = \"base\" }");
  expect_error(t, "bodies[1].nose.length", "is a velocity; expected a length", -1);
  t = nose("{ kind = \"ogival\", crh = 0.3, at = \"base\" }");
  expect_error(t, "bodies[1].nose.crh", "must be at least 0.5", -1);
  t = nose("{ kind = \"ogival\", crh = 3, at = \"base\" }");  // 2 mm x sqrt(11) = 6.6 mm > 5 mm
  expect_error(t, "bodies[1].nose.kind", "the ogival nose is 6.63", -1);
  t = nose("{ kind = \"hemispherical\", length = \"2 mm\", at = \"base\" }");
  expect_error(t, "bodies[1].nose.length", "unknown key \"length\"", -1);
  t = nose("{ kind = \"flat\", at = \"base\" }");
  expect_error(t, "bodies[1].nose.at", "unknown key \"at\"", -1);
  t = nose("\"conical\"");
  expect_error(t, "bodies[1].nose", "expected a table such as { kind = \"hemispherical\", at = \"base\" }", -1);
  // A box has no nose.
  t = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]", "max = [\"10 mm\", \"10 mm\", \"2 mm\"]\nnose = { kind = \"flat\" }");
  expect_error(t, "bodies[0].nose", "\"nose\" is a key of a cylinder, not of a box", -1);
}

// Both plate cases take Weldox 460 E from cases/materials/weldox-460e.toml, whose crack-band criterion the
// scene turns into a critical plastic work Gamma / (k h0) at its spacing (damage.hpp): twice as large at
// 1 mm as at 2 mm.
TEST(CaseFileLoad, PlateCasesShareTheWeldoxMaterialFile) {
  const std::string cases = IMPACTSPH_CASES;
  const CaseSpec p8 = impactsph::load_case_file(cases + "/plate-8mm/case.toml", {}, "2 mm");
  const CaseSpec p12 = impactsph::load_case_file(cases + "/plate-12mm/case.toml", {}, "2 mm");
  const auto weldox_index = [](const CaseSpec& s) {
    const auto it = std::find_if(s.materials.begin(), s.materials.end(),
                                 [](const impactsph::MaterialSpec& m) { return m.name == "weldox-460e"; });
    return static_cast<std::size_t>(it - s.materials.begin());
  };
  const std::size_t k = weldox_index(p8), k12 = weldox_index(p12);
  ASSERT_LT(k, p8.materials.size()) << "plate-8mm has no material weldox-460e";
  ASSERT_LT(k12, p12.materials.size()) << "plate-12mm has no material weldox-460e";
  const auto& a = p8.materials[k].params;
  const auto& b = p12.materials[k12].params;
  EXPECT_EQ(a.damage.kind, impactsph::DamageKind::FractureEnergy);
  EXPECT_EQ(b.damage.kind, a.damage.kind);
  EXPECT_EQ(b.damage.fracture_energy, a.damage.fracture_energy);
  EXPECT_EQ(b.damage.band_width_factor, a.damage.band_width_factor);
  EXPECT_EQ(b.strength.jc_a, a.strength.jc_a);
  EXPECT_GT(a.damage.fracture_energy, 0);
  const double h0_2mm = p8.numerics.h_factor * 2e-3;
  const impactsph::Scene coarse = impactsph::build_scene(p8);
  EXPECT_NEAR(coarse.materials[k].damage.critical_plastic_work,
              a.damage.fracture_energy / (a.damage.band_width_factor * h0_2mm), 1e-9 * a.damage.fracture_energy / h0_2mm);
  const impactsph::Scene fine = impactsph::build_scene(impactsph::load_case_file(cases + "/plate-8mm/case.toml", {}, "1 mm"));
  EXPECT_NEAR(fine.materials[k].damage.critical_plastic_work / coarse.materials[k].damage.critical_plastic_work, 2.0, 1e-12);
}

// The material files a case reads, for the run fingerprints (app/run_args.cpp): a changed material file
// must not let a sweep or a ballistic-limit search take an old run as a run of the new inputs.
TEST(CaseFileLoad, ListsTheMaterialFilesItReads) {
  const std::string cases = IMPACTSPH_CASES;
  const std::vector<std::string> files = impactsph::case_material_files(cases + "/plate-8mm/case.toml");
  ASSERT_FALSE(files.empty());
  EXPECT_TRUE(std::any_of(files.begin(), files.end(), [](const std::string& f) {
    return std::filesystem::path(f).filename() == "weldox-460e.toml" && std::filesystem::is_regular_file(f);
  }));
  EXPECT_TRUE(impactsph::case_material_files(cases + "/no-such-case.toml").empty());
}

// A run's fingerprint reads a file's values, not its comments: rewording a comment in a material file
// must not make every run of it stale, and changing a value must.
TEST(CaseFileLoad, FileContentIgnoresCommentsAndLayoutButNotValues) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "impactsph_toml_content";
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const std::string a = write("a.toml", "# steel\ndensity = \"7850 kg/m^3\"\n[eos]\nkind = \"linear\"\n");
  const std::string b = write("b.toml", "density   = \"7850 kg/m^3\"  # F Table 2\n\n# the EOS\n[eos]\nkind = \"linear\"\n");
  const std::string c = write("c.toml", "density = \"7851 kg/m^3\"\n[eos]\nkind = \"linear\"\n");
  const std::string bad = write("bad.toml", "density = \n");
  EXPECT_EQ(impactsph::toml_file_content(a), impactsph::toml_file_content(b));
  EXPECT_NE(impactsph::toml_file_content(a), impactsph::toml_file_content(c));
  EXPECT_EQ(impactsph::toml_file_content(bad), "density = \n");  // not TOML: its text, so it still counts
  EXPECT_EQ(impactsph::toml_file_content((dir / "missing.toml").string()), "");
  std::filesystem::remove_all(dir);
}
