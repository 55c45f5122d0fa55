// The Taylor-bar face measures of measure_observables (common/case_observables.cpp) on the copper bar of
// cases/taylor-bar at 0.4 mm: the lattice measure 2 (r_max + ds/2) reads high at t = 0 because the outermost
// centres lie almost on the surface; the shifted measure 2 (r_max(t) + R0 - r_max(0)) and the area measure
// (the circle of the wall layer's volume over its thickness) are the bar's 7.62 mm then, and follow a
// uniform radial spread of the face by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/case_file.hpp"
#include "common/case_observables.hpp"
#include "common/scene.hpp"

namespace impactsph {
namespace {

constexpr double kD0 = 7.62e-3;  // m, the bar's diameter

Scene bar_scene() {
  return build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/taylor-bar/case.toml", {"output.vtu=false"},
                                    "0.4 mm"));
}

TEST(TaylorBarFace, MeasuresAtRest) {
  const Scene s = bar_scene();
  const CaseObservables o = measure_observables(s, s.particles);
  ASSERT_TRUE(o.taylor_bar);
  EXPECT_NEAR(o.final_length, 25.4e-3, 1e-12);
  EXPECT_NEAR(o.impact_face_diameter_shifted, kD0, 1e-12);
  EXPECT_NEAR(o.impact_face_diameter_area, kD0, 1e-9 * kD0);
  EXPECT_GT(o.impact_face_diameter, kD0 * 1.02);  // the lattice measure's bias at rest
}

// The wall layer spread radially by 1.2 at constant thickness: its centres move out by 1.2 and its density
// falls by 1.2^2, so its area grows by 1.44 and the area diameter by 1.2; the shifted measure moves with the
// outermost centre.
TEST(TaylorBarFace, FollowsARadialSpread) {
  Scene s = bar_scene();
  const double r0 = s.bodies[0].outer_centre_radius;
  const double dz = s.bodies[0].lattice_spacing.z;
  ParticleSet p = s.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.pos[i].z >= dz) continue;
    p.pos[i].x *= 1.2;
    p.pos[i].y *= 1.2;
    p.rho[i] /= 1.44;
  }
  const CaseObservables o = measure_observables(s, p);
  EXPECT_NEAR(o.impact_face_diameter_area, 1.2 * kD0, 1e-9 * kD0);
  EXPECT_NEAR(o.impact_face_diameter_shifted, 2 * (1.2 * r0 + 0.5 * kD0 - r0), 1e-12);
}

// A bar that bounced off a wall that does not pull: the gap between the wall and its face is not part of
// its length, and its face is its own first layer.
TEST(TaylorBarFace, ABarThatLeftTheWallIsMeasuredFromItsFace) {
  Scene s = bar_scene();
  const CaseObservables at_rest = measure_observables(s, s.particles);
  ParticleSet p = s.particles;
  for (Vec3d& x : p.pos) x.z += 1.3e-3;
  const CaseObservables left = measure_observables(s, p);
  EXPECT_NEAR(left.final_length, at_rest.final_length, 1e-12);
  EXPECT_NEAR(left.impact_face_diameter_area, at_rest.impact_face_diameter_area, 1e-12);
  EXPECT_NEAR(left.impact_face_diameter_shifted, at_rest.impact_face_diameter_shifted, 1e-12);
}

}  // namespace
}  // namespace impactsph
