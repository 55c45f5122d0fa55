// Elastic wave (issue 2): a uniaxial-strain pulse in a bar of Weldox-like steel, cases/elastic-wave.
// Closed forms (shared/data/validation.md): c_L = sqrt((K + 4G/3)/rho) = 6144 m/s and, behind the front,
// the stress rho c_L v with v = 10 m/s the particle velocity (half the 20 m/s impact speed).
// Targets: wave speed within 1 % and stress amplitude within 3 % at the CI spacing (1 mm), the error
// of the velocity profile smaller at 0.5 mm, total energy drift below 0.5 %, momentum to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/observables.hpp"
#include "verification/harness.hpp"

namespace impactsph::verification {
namespace {

constexpr double kRho = 7850, kE = 200e9, kNu = 0.33;
const double kBulk = kE / (3 * (1 - 2 * kNu)), kShear = kE / (2 * (1 + kNu));
const double kCL = std::sqrt((kBulk + 4 * kShear / 3) / kRho);
constexpr double kV = 10.0;        // particle velocity behind the front, m/s
constexpr double kFlyer = 20e-3;   // flyer length; the impact face is at x = 20 mm
constexpr double kBar = 100e-3;

struct WaveResult {
  double speed;             // fitted speed of the half-amplitude point, m/s
  double speed_stderr;
  double stress;            // mean -sigma_xx in the middle of the pulse, Pa
  double velocity_l1;       // L1 error of the velocity profile against the exact rectangle, relative
  double energy_drift;      // (E_end - E_0)/E_0
  double momentum_error;    // |p_end - p_0| / |p_0|
  std::size_t particles;
  long steps;
};

WaveResult run_wave(const std::string& spacing) {
  Scene scene = load_case("elastic-wave", spacing);
  const double dx = scene.spec.numerics.spacing;
  reference::ReferenceSolver solver(scene);
  const Totals t0 = summarise_totals(scene.particles);
  const int slabs = static_cast<int>(std::lround(kBar / dx));
  auto vx = [&](std::size_t i) { return scene.particles.vel[i].x; };

  std::vector<double> times, fronts;
  double next_sample = 4e-6;
  const double end = scene.spec.time.end;
  const long steps = run_reference(scene, solver, end, [&](double t) {
    if (t < next_sample) return;
    next_sample += 0.5e-6;
    const Profile prof = slab_profile(scene.particles, 0, 0.0, dx, slabs, vx);
    times.push_back(t);
    fronts.push_back(leading_crossing(prof, 0.5 * kV));
  });
  const LineFit fit = fit_line(times, fronts);

  // The pulse at `end`: the exact solution is v = kV on [front - 2 L_flyer, front), zero elsewhere.
  const double front = kFlyer + kCL * end;
  const Profile vprof = slab_profile(scene.particles, 0, 0.0, dx, slabs, vx);
  double l1 = 0;
  for (std::size_t k = 0; k < vprof.x.size(); ++k) {
    const double exact = (vprof.x[k] >= front - 2 * kFlyer && vprof.x[k] < front) ? kV : 0.0;
    l1 += std::abs(vprof.value[k] - exact) * dx;
  }
  const Profile sprof = slab_profile(scene.particles, 0, 0.0, dx, slabs, [&](std::size_t i) {
    return scene.particles.pressure[i] - scene.particles.dev_stress[i].xx;
  });
  double stress = 0;
  int n = 0;
  for (std::size_t k = 0; k < sprof.x.size(); ++k)
    if (sprof.x[k] > front - 30e-3 && sprof.x[k] < front - 10e-3) {
      stress += sprof.value[k];
      ++n;
    }
  const Totals t1 = summarise_totals(scene.particles);
  WaveResult r;
  r.speed = fit.slope;
  r.speed_stderr = fit.slope_stderr;
  r.stress = stress / n;
  r.velocity_l1 = l1 / (kV * 2 * kFlyer);
  r.energy_drift = (t1.total_energy() - t0.total_energy()) / t0.total_energy();
  r.momentum_error = norm(t1.momentum - t0.momentum) / norm(t0.momentum);
  r.particles = scene.particles.size();
  r.steps = steps;
  std::printf("elastic wave at %s: %zu particles, %ld steps: speed %.2f m/s (c_L %.2f, %+.3f %%), stress %.2f MPa "
              "(rho c_L v %.2f, %+.3f %%), velocity L1 error %.4f, energy drift %.3g, momentum error %.3g\n",
              spacing.c_str(), r.particles, r.steps, r.speed, kCL, 100 * (r.speed / kCL - 1), r.stress / 1e6,
              kRho * kCL * kV / 1e6, 100 * (r.stress / (kRho * kCL * kV) - 1), r.velocity_l1, r.energy_drift,
              r.momentum_error);
  return r;
}

TEST(ElasticWave, SpeedAmplitudeAndConservationAtCiSpacing) {
  const WaveResult r = run_wave("1 mm");
  EXPECT_NEAR(r.speed / kCL, 1.0, 0.01) << "wave speed " << r.speed << " m/s against c_L " << kCL;
  EXPECT_NEAR(r.stress / (kRho * kCL * kV), 1.0, 0.03) << "stress amplitude " << r.stress << " Pa";
  EXPECT_LT(std::abs(r.energy_drift), 0.005);
  // Pair forces are antisymmetric and the mirror planes are parallel to x: x-momentum is exact up to
  // the rounding of a sum over ~10^4 terms each step.
  EXPECT_LT(r.momentum_error, 1e-12);
}

TEST(ElasticWave, ErrorShrinksWithSpacing) {
  const WaveResult coarse = run_wave("1 mm");
  const WaveResult fine = run_wave("0.5 mm");
  EXPECT_LT(fine.velocity_l1, 0.8 * coarse.velocity_l1) << "velocity profile error did not shrink";
  // The speed error is below the resolution of the front fit at both spacings (0.025 % and 0.047 %
  // measured), so it need not fall; it may not grow past 0.2 %. The error that must shrink is the profile's.
  EXPECT_LE(std::abs(fine.speed / kCL - 1), std::abs(coarse.speed / kCL - 1) + 2e-3);
  EXPECT_NEAR(fine.speed / kCL, 1.0, 0.01);
  EXPECT_NEAR(fine.stress / (kRho * kCL * kV), 1.0, 0.03);
  EXPECT_LT(std::abs(fine.energy_drift), 0.005);
}

}  // namespace
}  // namespace impactsph::verification
