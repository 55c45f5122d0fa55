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
#include "tests/case_file_fixture.hpp"

using impactsph::CaseError;
using impactsph::CaseSpec;
using impactsph::parse_case_string;
using impactsph::Nose;
using namespace impactsph::case_file_test;

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
  EXPECT_DOUBLE_EQ(cu.strength.perfectly_plastic.yield_stress, 90e6);
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
  EXPECT_EQ(s.numerics.artificial_stress_of, impactsph::ArtificialStressOf::Total);
  EXPECT_EQ(parse_case_string(toml, "case.toml").numerics.artificial_stress_of, impactsph::ArtificialStressOf::Deviatoric);
  EXPECT_EQ(parse_case_string(with("spacing = \"0.5 mm\"", "spacing = \"0.5 mm\"\nartificial_stress = 0.3\nartificial_stress_of = \"total-bounded\"", toml),
                              "case.toml").numerics.artificial_stress_of,
            impactsph::ArtificialStressOf::TotalBounded);
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
  const std::string valid = "valid keys: name, material, shape, velocity, direction, variable_h, h_min, h_max, coarse, center, radius";
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
  EXPECT_DOUBLE_EQ(weldox.strength.johnson_cook.a, 490e6);
  EXPECT_DOUBLE_EQ(weldox.strength.johnson_cook.b, 807e6);
  EXPECT_DOUBLE_EQ(weldox.strength.reference_strain_rate, 5e-4);
  EXPECT_DOUBLE_EQ(weldox.strength.melt_temperature, 0);  // F neglects thermal effects
  EXPECT_EQ(weldox.damage.kind, impactsph::DamageKind::CriticalPlasticStrain);
  EXPECT_DOUBLE_EQ(weldox.damage.critical_plastic_strain.strain, 0.3);
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
