// Taylor bar (issue 3, CTest label `validation`: minutes): OFHC copper at 190 m/s on a rigid wall,
// cases/taylor-bar. Experiment (Johnson and Cook 1983, as reported by Zerilli and Armstrong 1987): final length 16.21 mm (target within 3 %),
// impact-face diameter 13.56 mm (within 5 %). Runs three spacings, prints both figures at each and
// asserts the targets at the finest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/case_observables.hpp"
#include "verification/harness.hpp"

namespace impactsph::verification {
namespace {

TEST(TaylorBar, FinalShapeAgainstExperiment) {
  constexpr double kLength = 16.21e-3, kDiameter = 13.56e-3;
  CaseObservables finest;
  for (const char* spacing : {"0.5 mm", "0.4 mm", "0.3 mm"}) {
    Scene scene = load_case("taylor-bar", spacing);
    reference::ReferenceSolver solver(scene);
    const long steps = run_reference(scene, solver, scene.spec.time.end);
    finest = measure_observables(scene, scene.particles);
    std::printf("Taylor bar at %s: %zu particles, %ld steps: final length %.3f mm (%+.1f %%), impact-face diameter "
                "%.3f mm (%+.1f %%)\n",
                spacing, scene.particles.size(), steps, finest.final_length * 1e3,
                100 * (finest.final_length / kLength - 1), finest.impact_face_diameter * 1e3,
                100 * (finest.impact_face_diameter / kDiameter - 1));
  }
  EXPECT_NEAR(finest.final_length / kLength, 1.0, 0.03);
  EXPECT_NEAR(finest.impact_face_diameter / kDiameter, 1.0, 0.05);
}

}  // namespace
}  // namespace impactsph::verification
