// A case's expected answers (common/expected.hpp): the files shipped beside the cases parse and give their
// figures in SI; a malformed file names the file, the line and the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "common/expected.hpp"
#include "temp_dir_test.hpp"

namespace impactsph {
namespace {

class ExpectedFile : public TempDirTest {
 protected:
  ExpectedFile() : TempDirTest("impactsph_expected") {}
  std::string write(const std::string& text) {
    const std::string path = (dir_ / "expected.toml").string();
    std::ofstream(path) << text;
    return path;
  }
  // The message of the CaseError that reading `text` throws.
  std::string error_of(const std::string& text) {
    try {
      read_expected(write(text));
    } catch (const CaseError& e) {
      return e.what();
    }
    return "no error";
  }
};

TEST_F(ExpectedFile, GivesValuesInSiWithTheirTolerance) {
  const ExpectedAnswers e = read_expected(write(
      "[final_length]\nvalue = \"16.21 mm\"\ntolerance = 0.03\nsource = \"experiment\"\n"
      "[recht_ipson_a]\nvalue = \"0.909\"\nsource = \"a = m_p / (m_p + m_plug)\"\n"));
  EXPECT_DOUBLE_EQ(e.value("final_length", Dimension::Length), 16.21e-3);
  EXPECT_DOUBLE_EQ(e.tolerance("final_length"), 0.03);
  EXPECT_DOUBLE_EQ(e.value("recht_ipson_a", Dimension::Dimensionless), 0.909);
  EXPECT_EQ(e.figure("final_length").source, "experiment");
}

TEST_F(ExpectedFile, MistakesNameTheFileLineAndKey) {
  EXPECT_NE(error_of("[a]\nvalue = \"1 mm\"\nsource = \"s\"\nunit = \"mm\"\n").find("expected.toml:4: a.unit: unknown key"),
            std::string::npos);
  EXPECT_NE(error_of("[a]\nvalue = \"1 mm\"\n").find("a.source: missing"), std::string::npos);
  EXPECT_NE(error_of("[a]\nsource = \"s\"\n").find("a.value: missing"), std::string::npos);
  EXPECT_NE(error_of("[a]\nvalue = \"1 mm\"\ntolerance = 3\nsource = \"s\"\n").find("expected.toml:3: a.tolerance"),
            std::string::npos);
  EXPECT_NE(error_of("a = 3\n").find("expected a table [a]"), std::string::npos);
  const ExpectedAnswers e = read_expected(write("[a]\nvalue = \"200 m/s\"\nsource = \"s\"\n"));
  try {
    e.value("a", Dimension::Length);
    ADD_FAILURE() << "a velocity read as a length";
  } catch (const CaseError& err) {
    EXPECT_NE(std::string(err.what()).find("expected.toml:2: a.value"), std::string::npos) << err.what();
  }
  EXPECT_THROW(e.tolerance("a"), CaseError);
  try {
    e.figure("b");
    ADD_FAILURE() << "an absent figure was found";
  } catch (const CaseError& err) {
    EXPECT_NE(std::string(err.what()).find("this file has: a"), std::string::npos) << err.what();
  }
}

// Every expected.toml in cases/ parses, and the figures the validation tests and verify read are there with
// their dimension.
TEST(ExpectedAnswersOfTheCases, ReadAsTheirReadersAskForThem) {
  const std::string cases = IMPACTSPH_CASES;
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(cases))
    if (std::filesystem::exists(entry.path() / "expected.toml")) {
      EXPECT_NO_THROW(read_expected((entry.path() / "expected.toml").string())) << entry.path();
      ++files;
    }
  EXPECT_GE(files, 4);
  const ExpectedAnswers bar = read_expected(cases + "/taylor-bar/expected.toml");
  EXPECT_NEAR(bar.value("final_length", Dimension::Length), 16.21e-3, 1e-12);
  EXPECT_NEAR(bar.value("impact_face_diameter", Dimension::Length), 13.56e-3, 1e-12);
  const ExpectedAnswers bilinear = read_expected(cases + "/taylor-bar-bilinear/expected.toml");
  EXPECT_GT(bilinear.value("foot_radius", Dimension::Length), 0);
  EXPECT_GT(bilinear.tolerance("final_length"), 0);
  const ExpectedAnswers plate = read_expected(cases + "/plate-8mm/expected.toml");
  EXPECT_NEAR(plate.value("ballistic_limit", Dimension::Velocity), 152.5, 1e-12);
  EXPECT_GT(plate.value("recht_ipson_a", Dimension::Dimensionless), 0);
  EXPECT_GT(plate.value("recht_ipson_p", Dimension::Dimensionless), 0);
  const ExpectedAnswers tile = read_expected(cases + "/ceramic-tile/expected.toml");
  EXPECT_NEAR(tile.value("residual_mass", Dimension::Mass), 6.42e-3, 1e-15);
  EXPECT_GT(tile.tolerance("residual_velocity"), 0);
}

}  // namespace
}  // namespace impactsph
