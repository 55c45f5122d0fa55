// The plastic work per unit mass each particle accumulates (ParticleSet::plastic_work, finish_step in
// common/integration.hpp) in both solvers: it is sum sigma_y d eps_p / rho, so with a specific heat the
// adiabatic heating is the Taylor-Quinney share of it, m c_p (T - T_room) = beta m w_p for every particle,
// and the gpu port in double accumulates what the reference does. The copper Taylor bar at a coarse
// spacing, 150 steps into the impact.
#include <gtest/gtest.h>

#include <cmath>

#include "common/case_file.hpp"
#include "common/scene.hpp"
#include "gpu/solver.hpp"
#include "reference/solver.hpp"

namespace impactsph {
namespace {

Scene taylor_scene() {
  return build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/taylor-bar/case.toml", {}, "0.8 mm"));
}

double total_plastic_work(const ParticleSet& p) {
  double w = 0;
  for (std::size_t i = 0; i < p.size(); ++i) w += p.mass[i] * p.plastic_work[i];
  return w;
}

TEST(PlasticWork, IsTheWorkThatHeatsAndTheSameInBothSolvers) {
  Scene a = taylor_scene();
  Scene b = a;
  const MaterialParams<double>& copper = a.materials[0];
  ASSERT_GT(copper.specific_heat, 0);
  for (const double w : a.particles.plastic_work) ASSERT_EQ(w, 0);
  double kinetic0 = 0;
  for (std::size_t i = 0; i < a.particles.size(); ++i) kinetic0 += 0.5 * a.particles.mass[i] * norm2(a.particles.vel[i]);
  reference::ReferenceSolver ref(b);
  std::unique_ptr<gpu::GpuStepper> port = gpu::host::make_solver(a, gpu::Precision::Double);
  for (int s = 0; s < 150; ++s) {
    const double dt = ref.stable_time_step(b.particles);
    ref.step(b.particles, dt);
    port->step(a.particles, dt);
  }
  const ParticleSet& p = b.particles;
  const double work = total_plastic_work(p);
  EXPECT_GT(work, 0.01 * kinetic0) << "the bar must have yielded";
  std::size_t yielded = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_GE(p.plastic_work[i], 0);
    const double heat = copper.specific_heat * (p.temperature[i] - copper.room_temperature);
    EXPECT_NEAR(heat, copper.strength.taylor_quinney * p.plastic_work[i], 1e-9 * (1 + p.plastic_work[i])) << i;
    if (p.plastic_strain[i] > 0) {
      ++yielded;
      EXPECT_GT(p.plastic_work[i], 0) << i;
    } else {
      EXPECT_EQ(p.plastic_work[i], 0) << i;
    }
  }
  EXPECT_GT(yielded, 0u);
  EXPECT_NEAR(total_plastic_work(a.particles), work, 1e-9 * work);
}

}  // namespace
}  // namespace impactsph
