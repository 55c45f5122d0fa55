// Runs that stop when their verdict is known (stop_when_settled; common/case_observables.hpp track_settling,
// track_held): the 8 mm plate at 2.5 mm, held at 120 m/s and perforated at 298 m/s, each run once with the
// early stop and once to a fixed end without it. The early run must end well before the full one with the
// same verdict and figures.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/case_file.hpp"
#include "common/driver.hpp"
#include "reference/solver.hpp"
#include "tests/temp_dir_test.hpp"

namespace impactsph {
namespace {

class EarlyStop : public TempDirTest {
 protected:
  EarlyStop() : TempDirTest("impactsph_early_stop") {}

  RunResult run(double speed, bool stop_early, const std::string& end) {
    const std::vector<std::string> sets{"projectile.velocity=" + std::to_string(speed) + " m/s",
                                        "observables.stop_when_settled=" + std::string(stop_early ? "true" : "false"),
                                        "time.end=" + end, "output.vtu=false", "output.picture=false"};
    Scene scene = build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/plate-8mm/case.toml", sets, "2.5 mm"));
    reference::ReferenceSolver solver(scene);
    RunOptions opt;
    opt.quiet = true;
    opt.fingerprint = "test";
    opt.out_dir = dir_ / (std::to_string(speed) + (stop_early ? "-early" : "-full"));
    return run_simulation(scene, solver, opt);
  }
};

TEST_F(EarlyStop, AHeldRunEndsWithTheVerdictOfTheFullRun) {
  const RunResult early = run(120, true, "400 us");
  const RunResult full = run(120, false, "400 us");
  ASSERT_TRUE(early.settled);
  EXPECT_TRUE(early.held);
  EXPECT_FALSE(full.settled);
  EXPECT_LT(early.clock.time, 0.8 * full.clock.time);
  std::printf("held at 120 m/s: ended at %.1f us (verdict known at %.1f us) against %.1f us; residual velocity %.2f "
              "and %.2f m/s\n",
              early.clock.time * 1e6, early.observables.settled_time * 1e6, full.clock.time * 1e6,
              early.observables.residual_velocity, full.observables.residual_velocity);
  EXPECT_FALSE(early.observables.perforated);
  EXPECT_FALSE(full.observables.perforated);
  EXPECT_EQ(early.observables.plug_mass, 0.0);
  EXPECT_EQ(full.observables.plug_mass, 0.0);
  // No target particle failed after the verdict was known, and the projectile still did not go on.
  EXPECT_EQ(early.observables.damage_fraction, full.observables.damage_fraction);
  EXPECT_LE(full.observables.residual_velocity, 1.0);
}

TEST_F(EarlyStop, APerforatingRunEndsWithTheFiguresOfTheFullRun) {
  const RunResult early = run(298, true, "200 us");
  const RunResult full = run(298, false, "200 us");
  ASSERT_TRUE(early.settled);
  EXPECT_FALSE(early.held);
  EXPECT_LT(early.clock.time, 0.8 * full.clock.time);
  std::printf("perforated at 298 m/s: ended at %.1f us against %.1f us; residual velocity %.2f and %.2f m/s, plug "
              "%.2f and %.2f g\n",
              early.clock.time * 1e6, full.clock.time * 1e6, early.observables.residual_velocity,
              full.observables.residual_velocity, early.observables.plug_mass * 1e3, full.observables.plug_mass * 1e3);
  EXPECT_TRUE(early.observables.perforated);
  EXPECT_TRUE(full.observables.perforated);
  // Steady within the settle tolerance (1 m/s) over a window: the projectile flies on freely.
  EXPECT_NEAR(early.observables.residual_velocity, full.observables.residual_velocity, 1.0);
  // A plug came off in both. Its mass is that of the heaviest intact piece flying with it, which the full
  // run measures later, after the plug has broken up (at this spacing to about half by 200 us):
  // a figure of the moment, not of the verdict.
  EXPECT_GT(early.observables.plug_mass, 0.0);
  EXPECT_GT(full.observables.plug_mass, 0.0);
}

}  // namespace
}  // namespace impactsph
