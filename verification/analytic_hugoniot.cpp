// Hugoniot (issue 2): symmetric plate impact of 4340 steel, hydrodynamic, cases/hugoniot-4340.
// Rankine-Hugoniot with Us = c0 + s up, up = V/2 (shared/data/validation.md): shock pressure rho0 Us up
// and shock speed Us within 3 %. The shocked material is at rest in the laboratory, so the front in the
// target runs at Us - up; its half-pressure point is fitted over time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/observables.hpp"
#include "verification/harness.hpp"

namespace impactsph::verification {
namespace {

constexpr double kRho0 = 7810, kC0 = 4578, kS = 1.33;

void check_hugoniot(double impact_speed) {
  const double up = impact_speed / 2, us = kC0 + kS * up, p_rh = kRho0 * us * up;
  char speed[64];
  std::snprintf(speed, sizeof speed, "%.10g m/s", up);
  Scene scene = load_case("hugoniot-4340", "", {std::string("flyer.velocity=") + speed,
                                                 std::string("target.velocity=") + speed});
  const double dx = scene.spec.numerics.spacing;
  reference::ReferenceSolver solver(scene);
  const Totals t0 = summarise_totals(scene.particles);
  const double momentum_scale = t0.kinetic_energy / up;  // sum m |v|
  const int slabs = static_cast<int>(std::lround(20e-3 / dx));
  auto pressure = [&](std::size_t i) { return scene.particles.pressure[i]; };

  std::vector<double> times, fronts;
  double next_sample = 0.3e-6;
  const double end = scene.spec.time.end;
  const long steps = run_reference(scene, solver, end, [&](double t) {
    if (t < next_sample) return;
    next_sample += 0.1e-6;
    times.push_back(t);
    fronts.push_back(leading_crossing(slab_profile(scene.particles, 0, -10e-3, dx, slabs, pressure), 0.5 * p_rh));
  });
  const LineFit fit = fit_line(times, fronts);
  const double us_measured = fit.slope + up;

  const double front = fronts.back();
  const Profile prof = slab_profile(scene.particles, 0, -10e-3, dx, slabs, pressure);
  double p_sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < prof.x.size(); ++k)
    if (std::abs(prof.x[k]) < 0.7 * front) {
      p_sum += prof.value[k];
      ++n;
    }
  const double p_measured = p_sum / n;
  const Totals t1 = summarise_totals(scene.particles);
  std::printf("Hugoniot at %.0f m/s: %zu particles, %ld steps: Us %.1f m/s (RH %.1f, %+.2f %%), P %.3f GPa (RH %.3f, "
              "%+.2f %%), momentum %.3g of sum m|v|, energy drift %.3g\n",
              impact_speed, scene.particles.size(), steps, us_measured, us, 100 * (us_measured / us - 1),
              p_measured / 1e9, p_rh / 1e9, 100 * (p_measured / p_rh - 1), norm(t1.momentum) / momentum_scale,
              (t1.total_energy() - t0.total_energy()) / t0.total_energy());
  EXPECT_NEAR(us_measured / us, 1.0, 0.03);
  EXPECT_NEAR(p_measured / p_rh, 1.0, 0.03);
  EXPECT_LT(norm(t1.momentum) / momentum_scale, 1e-12) << "total momentum of the symmetric impact is not zero";
  EXPECT_LT(std::abs(t1.total_energy() - t0.total_energy()) / t0.total_energy(), 0.005);
}

TEST(Hugoniot, Steel4340At500MetresPerSecond) { check_hugoniot(500); }
TEST(Hugoniot, Steel4340At1000MetresPerSecond) { check_hugoniot(1000); }

}  // namespace
}  // namespace impactsph::verification
