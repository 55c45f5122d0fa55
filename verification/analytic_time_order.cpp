// Time integration: both integrators (numerics.integrator) are second order in time, and the answers of the
// elastic-wave case do not depend on the step factor chosen. At a fixed spacing the velocity field at t = 4 us
// is computed with C_CFL = 0.4, 0.2, 0.1 and compared with C_CFL = 0.025: the difference must fall by about 4
// for each halving of the time step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "verification/harness.hpp"

namespace impactsph::verification {
namespace {

std::vector<Vec3d> velocities_at_4us(const std::string& integrator, double cfl) {
  char set[64];
  std::snprintf(set, sizeof set, "numerics.cfl=%.6g", cfl);
  Scene scene = load_case("elastic-wave", "1 mm", {set, "numerics.integrator=" + integrator});
  reference::ReferenceSolver solver(scene);
  run_reference(scene, solver, 4e-6);
  return scene.particles.vel;
}

double rms_difference(const std::vector<Vec3d>& a, const std::vector<Vec3d>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += norm2(a[i] - b[i]);
  return std::sqrt(s / static_cast<double>(a.size()));
}

void expect_second_order(const std::string& integrator) {
  const std::vector<Vec3d> reference = velocities_at_4us(integrator, 0.025);
  const double e4 = rms_difference(velocities_at_4us(integrator, 0.4), reference);
  const double e2 = rms_difference(velocities_at_4us(integrator, 0.2), reference);
  const double e1 = rms_difference(velocities_at_4us(integrator, 0.1), reference);
  const double order_a = std::log2(e4 / e2), order_b = std::log2(e2 / e1);
  std::printf("time integration (%s): rms velocity difference to CFL 0.025 at CFL 0.4, 0.2, 0.1: %.3g, %.3g, %.3g m/s "
              "(observed orders %.2f, %.2f; the pulse carries 10 m/s)\n",
              integrator.c_str(), e4, e2, e1, order_a, order_b);
  EXPECT_GT(order_a, 1.7);
  EXPECT_GT(order_b, 1.7);
  EXPECT_LT(order_b, 2.5);
  // At the default CFL (0.2) the time-stepping error is far below the spatial error of the case.
  EXPECT_LT(e2, 0.01 * 10.0);
}

TEST(TimeIntegration, MidpointSecondOrderAndIndependentOfCfl) { expect_second_order("midpoint"); }
TEST(TimeIntegration, LeapfrogSecondOrderAndIndependentOfCfl) { expect_second_order("leapfrog"); }

}  // namespace
}  // namespace impactsph::verification
