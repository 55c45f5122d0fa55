// Case-file errors (common/case_file.hpp): one test per class of bad input, each asserting the key, a
// useful hint and the line.
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
  expect_error(t, "bodies[0].radius", "valid keys: name, material, shape, velocity, direction, variable_h, h_min, h_max, coarse, min, max",
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
