// Case-file keys of the ceramic work (docs/case-files.md): JH-2 strength and damage, the Grueneisen-cubic
// tungsten, material files (materials.NAME.file), variable smoothing length per body, SRAD of the penalty
// contact. One test per class of bad input: unknown key, missing or wrong unit, out-of-range constant,
// and the cross-key rules; each asserts the file, the key and a hint of what is valid.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "common/case_file.hpp"
#include "common/errors.hpp"

namespace {

using impactsph::CaseError;
using impactsph::CaseSpec;
using impactsph::parse_case_string;

const std::string kJh2 =
    "kind = \"johnson-holmquist-2\", shear_modulus = \"90.16 GPa\", a = 0.93, b = 0.31, c = 0.0, m = 0.6, n = 0.6, "
    "hel = \"2.79 GPa\", p_hel = \"1.46 GPa\", tensile_strength = \"0.2 GPa\"";
const std::string kJh2Damage = "kind = \"johnson-holmquist-2\", d1 = 0.005, d2 = 1.0, bulking = 1.0";

std::string ceramic_case(const std::string& strength = kJh2, const std::string& damage = kJh2Damage,
                         const std::string& rod_extra = "", const std::string& contact = "") {
  return R"toml([case]
name = "tile"

[materials.alumina]
density = "3921 kg/m^3"
eos = { kind = "polynomial", k1 = "130.95 GPa" }
strength = { )toml" + strength + R"toml( }
damage = { )toml" + damage + R"toml( }

[materials.tungsten]
density = "17162 kg/m^3"
eos = { kind = "gruneisen-cubic", c0 = "4029 m/s", s1 = 1.23, gamma0 = 1.54 }
strength = { kind = "johnson-cook", shear_modulus = "124 GPa", a = "1200 MPa", b = "141 MPa", n = 0.12, c = 0.016 }
damage = { kind = "johnson-cook", d1 = 0.0, d2 = 0.33, d3 = -1.5, pair_factor = false }

[[bodies]]
name = "tile"
material = "alumina"
shape = "box"
min = ["0 mm", "0 mm", "-4 mm"]
max = ["8 mm", "8 mm", "0 mm"]

[[bodies]]
name = "rod"
material = "tungsten"
shape = "cylinder"
base = ["4 mm", "4 mm", "0 mm"]
axis = "z"
radius = "2 mm"
length = "4 mm"
velocity = "900 m/s"
direction = [0, 0, -1]
)toml" + rod_extra + "\n" + contact + R"toml(
[numerics]
spacing = "1 mm"

[time]
end = "1 us"
output_interval = "1 us"
)toml";
}

CaseError error_of(const std::string& toml, const std::string& file = "case.toml") {
  try {
    parse_case_string(toml, file);
  } catch (const CaseError& e) {
    return e;
  }
  ADD_FAILURE() << "the case was accepted";
  return CaseError("", 0, "", "");
}

void expect_error(const std::string& toml, const std::string& key, const std::string& hint) {
  const CaseError e = error_of(toml);
  EXPECT_EQ(e.file(), "case.toml") << e.what();
  EXPECT_EQ(e.key(), key) << e.what();
  EXPECT_NE(std::string(e.what()).find(hint), std::string::npos) << e.what() << "\n  lacks: " << hint;
}

TEST(CaseFileCeramic, ReadsJh2AndTungsten) {
  const CaseSpec s = parse_case_string(ceramic_case(), "case.toml");
  const auto& a = s.materials[0].params;
  EXPECT_EQ(a.strength.kind, impactsph::StrengthKind::JohnsonHolmquist2);
  EXPECT_DOUBLE_EQ(a.strength.shear_modulus, 90.16e9);
  EXPECT_DOUBLE_EQ(a.strength.jh2.a, 0.93);
  EXPECT_DOUBLE_EQ(a.strength.jh2.b, 0.31);
  EXPECT_DOUBLE_EQ(a.strength.jh2.m, 0.6);
  EXPECT_DOUBLE_EQ(a.strength.jh2.n, 0.6);
  EXPECT_DOUBLE_EQ(a.strength.jh2.hel, 2.79e9);
  EXPECT_DOUBLE_EQ(a.strength.jh2.p_hel, 1.46e9);
  EXPECT_DOUBLE_EQ(a.strength.jh2.tensile_pressure, 0.2e9);
  EXPECT_DOUBLE_EQ(a.strength.jh2.sfmax, 1e30);  // default: no cap
  EXPECT_DOUBLE_EQ(a.strength.reference_strain_rate, 1.0);
  EXPECT_EQ(a.damage.kind, impactsph::DamageKind::JohnsonHolmquist2);
  EXPECT_DOUBLE_EQ(a.damage.jh2.d1, 0.005);
  EXPECT_DOUBLE_EQ(a.damage.jh2.d2, 1.0);
  EXPECT_DOUBLE_EQ(a.damage.jh2.bulking, 1.0);
  EXPECT_FALSE(a.damage.scale_pairs);  // JH-2 default
  const auto& w = s.materials[1].params;
  EXPECT_EQ(w.eos.kind, impactsph::EosKind::GruneisenCubic);
  EXPECT_FALSE(w.damage.scale_pairs);
  EXPECT_FALSE(s.bodies[1].variable_h);
  EXPECT_DOUBLE_EQ(s.bodies[1].h_min_factor, 0.2);
  EXPECT_DOUBLE_EQ(s.bodies[1].h_max_factor, 2.0);
}

TEST(CaseFileCeramic, VariableSmoothingLengthAndSrad) {
  const CaseSpec s =
      parse_case_string(ceramic_case(kJh2, kJh2Damage, "variable_h = true\nh_min = 0.5\nh_max = 1.5",
                                     "[[contacts]]\nbodies = [\"rod\", \"tile\"]\nkind = \"penalty\"\nsrad = 1.2\n"
                                     "penalty_scale = 1.0"),
                        "case.toml");
  EXPECT_TRUE(s.bodies[1].variable_h);
  EXPECT_DOUBLE_EQ(s.bodies[1].h_min_factor, 0.5);
  EXPECT_DOUBLE_EQ(s.bodies[1].h_max_factor, 1.5);
  ASSERT_EQ(s.contacts.size(), 1u);
  EXPECT_DOUBLE_EQ(s.contacts[0].srad, 1.2);
  EXPECT_DOUBLE_EQ(s.contacts[0].penalty_scale, 1.0);
}

TEST(CaseFileCeramicErrors, UnknownKeys) {
  const std::string k = "materials.alumina.";
  expect_error(ceramic_case(kJh2 + ", hell = \"2 GPa\""), k + "strength.hell", "did you mean \"hel\"?");
  expect_error(ceramic_case(kJh2 + ", d1 = 0.005"), k + "strength.d1", "valid keys: kind, shear_modulus");
  expect_error(ceramic_case(kJh2, kJh2Damage + ", d3 = 1"), k + "damage.d3", "unknown key \"d3\"");
  expect_error(ceramic_case(kJh2, kJh2Damage, "hmax = 2"), "bodies[1].hmax", "did you mean \"h_max\"?");
  expect_error(ceramic_case(kJh2, kJh2Damage, "", "[[contacts]]\nbodies = [\"rod\", \"tile\"]\nkind = \"shared\"\nsrad = 1.2"),
               "contacts[0].srad", "unknown key \"srad\" in a contact");
}

TEST(CaseFileCeramicErrors, MissingOrWrongUnits) {
  const std::string k = "materials.alumina.strength.";
  const std::string jh2_no_hel_unit =
      "kind = \"johnson-holmquist-2\", shear_modulus = \"90.16 GPa\", a = 0.93, b = 0.31, m = 0.6, n = 0.6, "
      "hel = 2.79, p_hel = \"1.46 GPa\", tensile_strength = \"0.2 GPa\"";
  expect_error(ceramic_case(jh2_no_hel_unit), k + "hel", "a bare number is in Pa");
  const std::string jh2_wrong_unit =
      "kind = \"johnson-holmquist-2\", shear_modulus = \"90.16 GPa\", a = 0.93, b = 0.31, m = 0.6, n = 0.6, "
      "hel = \"2.79 GPa\", p_hel = \"1.46 GPa\", tensile_strength = \"0.2 m/s\"";
  expect_error(ceramic_case(jh2_wrong_unit), k + "tensile_strength", "expected a pressure");
  const std::string jh2_missing =
      "kind = \"johnson-holmquist-2\", shear_modulus = \"90.16 GPa\", a = 0.93, b = 0.31, m = 0.6, n = 0.6, "
      "hel = \"2.79 GPa\", tensile_strength = \"0.2 GPa\"";
  expect_error(ceramic_case(jh2_missing), k + "p_hel", "missing in the strength model of a material");
}

TEST(CaseFileCeramicErrors, OutOfRangeConstants) {
  const std::string k = "materials.alumina.";
  expect_error(ceramic_case(kJh2 + ", sfmax = 0"), k + "strength.sfmax", "greater than 0");
  expect_error(ceramic_case(
                   "kind = \"johnson-holmquist-2\", shear_modulus = \"90.16 GPa\", a = 7, b = 0.31, m = 0.6, n = 0.6, "
                   "hel = \"2.79 GPa\", p_hel = \"1.46 GPa\", tensile_strength = \"0.2 GPa\""),
               k + "strength.a", "at most 5");
  expect_error(ceramic_case(
                   "kind = \"johnson-holmquist-2\", shear_modulus = \"90.16 GPa\", a = 0.93, b = 0.31, m = 0.6, "
                   "n = 0.6, hel = \"1.4 GPa\", p_hel = \"1.46 GPa\", tensile_strength = \"0.2 GPa\""),
               k + "strength.p_hel", "must be less than hel");
  expect_error(ceramic_case(kJh2, "kind = \"johnson-holmquist-2\", d1 = 2, d2 = 1"), k + "damage.d1", "at most 1");
  expect_error(ceramic_case(kJh2, kJh2Damage + ", min_failure_strain = -1"), k + "damage.min_failure_strain", "at least 0");
  expect_error(ceramic_case(kJh2, "kind = \"johnson-holmquist-2\", d1 = 0.005, d2 = 1, bulking = 1.5"), k + "damage.bulking",
               "at most 1");
  expect_error(ceramic_case(kJh2, kJh2Damage, "variable_h = true\nh_min = 0"), "bodies[1].h_min", "greater than 0");
  expect_error(ceramic_case(kJh2, kJh2Damage, "variable_h = true\nh_max = 0.5"), "bodies[1].h_max", "at least 1");
  expect_error(ceramic_case(kJh2, kJh2Damage, "", "[[contacts]]\nbodies = [\"rod\", \"tile\"]\nsrad = 5"),
               "contacts[0].srad", "at most 3");
}

TEST(CaseFileCeramicErrors, CrossKeyRules) {
  // JH-2 damage needs JH-2 strength; the JH-2 strength does not take Johnson-Cook damage.
  expect_error(ceramic_case("kind = \"elastic\", shear_modulus = \"90 GPa\""), "materials.alumina.damage.kind",
               "needs strength kind \"johnson-holmquist-2\"");
  expect_error(ceramic_case(kJh2, "kind = \"johnson-cook\", d1 = 0, d2 = 0.3, d3 = -1"), "materials.alumina.damage.kind",
               "johnson-holmquist-2");
  expect_error(ceramic_case(kJh2, kJh2Damage, "h_max = 1.5"), "bodies[1].h_max", "needs variable_h = true");
  expect_error(ceramic_case(kJh2, kJh2Damage, "",
                            "[[contacts]]\nbodies = [\"rod\", \"tile\"]\nsrad = 1.2\ncontact_distance = 1.0"),
               "contacts[0].srad", "not both");
}

// Material files: the constants come from the file, errors in it name it and its line.
class MaterialFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("impactsph-matfile-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_ / "materials");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void write(const std::string& rel, const std::string& text) {
    std::ofstream(dir_ / rel) << text;
  }
  std::string case_path() const { return (dir_ / "case.toml").string(); }
  std::filesystem::path dir_;
};

std::string with_alumina_file(const std::string& table) {
  std::string c = ceramic_case();
  const std::string from = "[materials.alumina]\n";
  const auto at = c.find(from), end = c.find("[materials.tungsten]");
  return c.substr(0, at) + "[materials.alumina]\n" + table + "\n\n" + c.substr(end);
}

TEST_F(MaterialFiles, ReadsTheFileAndOverridesApply) {
  write("materials/al.toml", "density = \"3921 kg/m^3\"\neos = { kind = \"polynomial\", k1 = \"130.95 GPa\" }\n"
                             "strength = { " + kJh2 + " }\ndamage = { " + kJh2Damage + " }\n");
  write("case.toml", with_alumina_file("file = \"materials/al.toml\""));
  CaseSpec s = impactsph::load_case_file(case_path(), {}, "");
  EXPECT_DOUBLE_EQ(s.materials[0].params.strength.jh2.hel, 2.79e9);
  s = impactsph::load_case_file(case_path(), {"alumina.strength.hel=3 GPa"}, "");
  EXPECT_DOUBLE_EQ(s.materials[0].params.strength.jh2.hel, 3e9);
}

TEST_F(MaterialFiles, ErrorsNameTheMaterialFile) {
  write("materials/bad.toml", "density = \"3921 kg/m^3\"\neos = { kind = \"polynomial\", k1 = \"130.95 GPa\" }\n"
                              "strength = { " + kJh2 + ", a = 9 }\n");
  write("case.toml", with_alumina_file("file = \"materials/bad.toml\""));
  try {
    impactsph::load_case_file(case_path(), {}, "");
    ADD_FAILURE() << "accepted";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.file(), (dir_ / "materials/bad.toml").string()) << e.what();
    EXPECT_EQ(e.line(), 3) << e.what();
  }
  write("case.toml", with_alumina_file("file = \"materials/none.toml\""));
  try {
    impactsph::load_case_file(case_path(), {}, "");
    ADD_FAILURE() << "accepted";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.key(), "materials.alumina.file") << e.what();
    EXPECT_NE(std::string(e.what()).find("no material file"), std::string::npos) << e.what();
  }
  write("materials/al.toml", "density = \"3921 kg/m^3\"\n");
  write("case.toml", with_alumina_file("file = \"materials/al.toml\"\ndensity = \"4000 kg/m^3\""));
  try {
    impactsph::load_case_file(case_path(), {}, "");
    ADD_FAILURE() << "accepted";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.key(), "materials.alumina.density") << e.what();
    EXPECT_NE(std::string(e.what()).find("give only file"), std::string::npos) << e.what();
  }
}

// The committed material files and the tile case load.
TEST(CeramicTileCase, LoadsWithItsMaterialFiles) {
  const CaseSpec s = impactsph::load_case_file(std::string(IMPACTSPH_CASES) + "/ceramic-tile/case.toml", {}, "");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].params.strength.kind, impactsph::StrengthKind::JohnsonHolmquist2);
  EXPECT_DOUBLE_EQ(s.materials[0].params.eos.rho0, 3921);
  EXPECT_EQ(s.materials[1].params.strength.kind, impactsph::StrengthKind::JohnsonCook);
  EXPECT_DOUBLE_EQ(s.materials[1].params.eos.rho0, 17162);
  EXPECT_DOUBLE_EQ(s.materials[1].params.strength.melt_temperature, 1723);
  EXPECT_EQ(s.observables.projectile, "rod");
}

}  // namespace
