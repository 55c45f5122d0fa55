// A 2:1 resolution interface (issue 18), cases/elastic-wave-interface: a uniaxial-strain pulse of
// v = 10 m/s crosses from the bar's fine part (0.5 mm) into its coarse part (1 mm, [bodies.coarse]). One
// material on both sides: the exact interface sends nothing back and passes the pulse on at
// c_L = sqrt((K + 4G/3)/rho) = 6144 m/s. Measured against the same case with the bar at one resolution
// (the same fine lattice, so the difference of the two runs in the fine part is the wave the interface
// reflected, free of the lattice's own dispersion wake):
//   - the reflected wave below 1 % of the incident amplitude, in the fine part after the pulse has gone;
//   - the pulse's speed in the coarse part within 0.5 % of c_L (its half-amplitude front, fitted over
//     85-112 mm, well past the interface at 70 mm);
//   - energy drift below 0.5 %.
// The same case with a 3 mm section at 3:1 and a 4 mm section at 4:1 (measured 2026-12-05): 2.1 % reflected,
// -0.36 % speed; 5.2 %, -0.60 %. The case reader therefore takes 2:1 only (common/case_geometry.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/case_file.hpp"
#include "common/observables.hpp"
#include "verification/harness.hpp"
#include "verification/measures.hpp"

namespace impactsph::verification {
namespace {

using X = ElasticWaveExact;
constexpr double kBarEnd = 130e-3;      // m, the bar's far end (the case file)
constexpr double kInterface = 70e-3;    // m, where the coarse region begins
constexpr double kFitFrom = 85e-3, kFitTo = 112e-3;  // m, the fronts fitted for the transmitted speed
constexpr double kReflectFrom = 20e-3, kReflectTo = 60e-3;  // m, where the reflection is at the end

struct InterfaceRun {
  std::size_t particles = 0;
  long steps = 0;
  Profile fine;                     // v_x at the end in slabs of the fine spacing
  std::vector<double> times, fronts;  // the half-amplitude front (slabs of the coarse spacing)
  double energy_drift = 0;
};

// `slab`: the width of the slabs the fronts are taken in, the coarse spacing (every slab holds particles).
InterfaceRun run(const CaseSpec& spec, double slab) {
  Scene scene = build_scene(spec);
  reference::ReferenceSolver solver(scene);
  const double dx = spec.numerics.spacing;
  auto vx = [&](std::size_t i) { return scene.particles.vel[i].x; };
  const Totals t0 = summarise_totals(scene.particles);
  InterfaceRun r;
  r.particles = scene.particles.size();
  double next = 0;
  r.steps = run_reference(scene, solver, spec.time.end, [&](double t) {
    if (t < next) return;
    next += 0.25e-6;
    r.times.push_back(t);
    r.fronts.push_back(leading_crossing(
        slab_profile(scene.particles, 0, 0.0, slab, static_cast<int>(std::lround(kBarEnd / slab)), vx), 0.5 * X::v));
  });
  r.fine = slab_profile(scene.particles, 0, 0.0, dx, static_cast<int>(std::lround(kBarEnd / dx)), vx);
  const Totals t1 = summarise_totals(scene.particles);
  r.energy_drift = (t1.total_energy() - t0.total_energy()) / t0.total_energy();
  return r;
}

double front_speed(const InterfaceRun& r) {
  std::vector<double> t, x;
  for (std::size_t k = 0; k < r.times.size(); ++k)
    if (r.fronts[k] > kFitFrom && r.fronts[k] < kFitTo) t.push_back(r.times[k]), x.push_back(r.fronts[k]);
  return t.size() >= 3 ? fit_line(t, x).slope : std::nan("");
}

TEST(ResolutionInterface, ReflectsBelowOnePercentAndPassesThePulseAtTheWaveSpeed) {
  const CaseSpec two = load_case_file(case_path("elastic-wave-interface"));
  ASSERT_EQ(two.bodies[1].coarse_ratio, 2);
  CaseSpec one = two;
  one.bodies[1].coarse_ratio = 1;
  const double slab = two.bodies[1].coarse_ratio * two.numerics.spacing;
  const InterfaceRun a = run(two, slab), b = run(one, slab);

  double reflected = 0, at = 0, wake = 0;
  for (std::size_t k = 0; k < a.fine.x.size(); ++k) {
    if (a.fine.x[k] < kReflectFrom || a.fine.x[k] > kReflectTo) continue;
    const double d = std::abs(a.fine.value[k] - b.fine.value[k]);
    if (d > reflected) reflected = d, at = a.fine.x[k];
    wake = std::max(wake, std::abs(b.fine.value[k]));
  }
  const double speed_two = front_speed(a), speed_one = front_speed(b);
  std::printf("resolution interface %g mm | %g mm at x = %.0f mm: %zu particles (%zu at one resolution), %ld steps; "
              "reflected %.4f m/s at x = %.1f mm = %.3f %% of the incident %.0f m/s (the one-resolution run's own wake "
              "there: %.3f %%); pulse speed in the coarse part %.1f m/s (%+.3f %% against c_L %.1f; one resolution "
              "%+.3f %%); energy drift %.3g\n",
              two.numerics.spacing * 1e3, slab * 1e3, kInterface * 1e3, a.particles, b.particles, a.steps, reflected, at * 1e3, 100 * reflected / X::v, X::v,
              100 * wake / X::v, speed_two, 100 * (speed_two / X::c_l() - 1), X::c_l(), 100 * (speed_one / X::c_l() - 1),
              a.energy_drift);
  EXPECT_LT(reflected / X::v, 0.01) << "the interface reflects " << reflected << " m/s at x = " << at;
  EXPECT_NEAR(speed_two / X::c_l(), 1.0, 0.005) << "pulse speed in the coarse part " << speed_two << " m/s";
  EXPECT_LT(std::abs(a.energy_drift), 0.005);
}

}  // namespace
}  // namespace impactsph::verification
