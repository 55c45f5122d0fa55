// Case files, the material, contact and nose tables and the material files (common/case_file.hpp).
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
  EXPECT_DOUBLE_EQ(st.johnson_cook.a, 90e6);
  EXPECT_DOUBLE_EQ(st.johnson_cook.b, 292e6);
  EXPECT_DOUBLE_EQ(st.johnson_cook.n, 0.31);
  EXPECT_DOUBLE_EQ(st.johnson_cook.c, 0.025);
  EXPECT_DOUBLE_EQ(st.johnson_cook.m, 1.09);
  EXPECT_DOUBLE_EQ(st.reference_strain_rate, 1e-3);
  EXPECT_DOUBLE_EQ(st.melt_temperature, 1356);
  EXPECT_DOUBLE_EQ(st.taylor_quinney, 0.85);
  EXPECT_DOUBLE_EQ(s.materials[1].params.specific_heat, 383);

  // Defaults; a linear EOS from E and nu works as for the other strength kinds; shear_modulus directly.
  s = parse_case_string(copper("kind = \"johnson-cook\", shear_modulus = \"46 GPa\", a = \"90 MPa\", b = 0"), "case.toml");
  const auto& d = s.materials[1].params.strength;
  EXPECT_DOUBLE_EQ(d.shear_modulus, 46e9);
  EXPECT_DOUBLE_EQ(d.johnson_cook.b, 0);
  EXPECT_DOUBLE_EQ(d.johnson_cook.n, 1);  // not needed without hardening
  EXPECT_DOUBLE_EQ(d.johnson_cook.c, 0);
  EXPECT_DOUBLE_EQ(d.johnson_cook.m, 1);
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
  EXPECT_DOUBLE_EQ(s.materials[1].params.damage.critical_plastic_strain.strain, 0.3);
  EXPECT_EQ(s.materials[0].params.damage.kind, impactsph::DamageKind::None);

  // Johnson-Cook failure on a perfectly plastic material; d4, d5 and min_failure_strain default to 0.
  std::string t = with("specific_heat", "damage = { kind = \"johnson-cook\", d1 = -0.09, d2 = 0.25, d3 = -0.5 }\nspecific_heat");
  s = parse_case_string(t, "case.toml");
  const auto& d = s.materials[1].params.damage;
  EXPECT_EQ(d.kind, impactsph::DamageKind::JohnsonCook);
  EXPECT_DOUBLE_EQ(d.johnson_cook.d1, -0.09);
  EXPECT_DOUBLE_EQ(d.johnson_cook.d2, 0.25);
  EXPECT_DOUBLE_EQ(d.johnson_cook.d3, -0.5);
  EXPECT_DOUBLE_EQ(d.johnson_cook.d4, 0);
  EXPECT_DOUBLE_EQ(d.johnson_cook.d5, 0);
  EXPECT_DOUBLE_EQ(d.johnson_cook.min_failure_strain, 0);

  t = copper(kJc, "damage = { kind = \"johnson-cook\", d1 = 0.54, d2 = 4.89, d3 = -3.03, d4 = 0.014, d5 = 1.12, "
                  "min_failure_strain = 0.05 }");
  s = parse_case_string(t, "case.toml");
  const auto& e = s.materials[1].params.damage;
  EXPECT_DOUBLE_EQ(e.johnson_cook.d1, 0.54);
  EXPECT_DOUBLE_EQ(e.johnson_cook.d2, 4.89);
  EXPECT_DOUBLE_EQ(e.johnson_cook.d3, -3.03);
  EXPECT_DOUBLE_EQ(e.johnson_cook.d4, 0.014);
  EXPECT_DOUBLE_EQ(e.johnson_cook.d5, 1.12);
  EXPECT_DOUBLE_EQ(e.johnson_cook.min_failure_strain, 0.05);
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
      {"kind = \"fracture-energy\", fracture_energy = \"150 kJ/m^2\"", k + "band_width_factor",
       "missing; a fracture-energy damage sets its band width by exactly one of band_width_factor"},
      {"kind = \"fracture-energy\", fracture_energy = \"150 kJ/m^2\", band_width_factor = 2, nonlocal_radius = \"6 mm\"",
       k + "nonlocal_radius", "given together with band_width_factor"},
      {"kind = \"fracture-energy\", fracture_energy = \"150 kJ/m^2\", nonlocal_radius = \"0 mm\"", k + "nonlocal_radius",
       "must be greater than 0 mm and at most 1 m (got 0 mm)"},
      {"kind = \"fracture-energy\", fracture_energy = \"150 kJ/m^2\", nonlocal_radius = \"6 MPa\"", k + "nonlocal_radius",
       "length"},
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
  expect_error(t, "materials.steel.damage.kind", "use strength kind \"perfectly-plastic\" or \"johnson-cook\"", -1);
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

// Both plate cases take Weldox 460 E from cases/materials/weldox-460e.toml, whose non-local fracture energy
// the scene turns into the same critical plastic work at every spacing (damage_fracture_energy.hpp).
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
  EXPECT_EQ(b.damage.fracture_energy.gamma, a.damage.fracture_energy.gamma);
  EXPECT_EQ(b.damage.fracture_energy.nonlocal_radius, a.damage.fracture_energy.nonlocal_radius);
  EXPECT_EQ(b.strength.johnson_cook.a, a.strength.johnson_cook.a);
  EXPECT_GT(a.damage.fracture_energy.gamma, 0);
  // The non-local criterion: its critical work Gamma / (32 R / 35) is the same at every spacing.
  const double R = a.damage.fracture_energy.nonlocal_radius;
  EXPECT_GT(R, 0);
  const impactsph::Scene coarse = impactsph::build_scene(p8);
  EXPECT_NEAR(coarse.materials[k].damage.fracture_energy.critical_work, a.damage.fracture_energy.gamma / (32.0 / 35.0 * R),
              1e-9 * a.damage.fracture_energy.gamma / R);
  const impactsph::Scene fine = impactsph::build_scene(impactsph::load_case_file(cases + "/plate-8mm/case.toml", {}, "1 mm"));
  EXPECT_EQ(fine.materials[k].damage.fracture_energy.critical_work, coarse.materials[k].damage.fracture_energy.critical_work);
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
