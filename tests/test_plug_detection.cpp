// The plug and perforation verdict of measure_observables (common/case_observables.cpp) on the 8 mm
// plate case at 2 mm, with the particles placed and moving as in hand-made states: a plug cut out and
// pushed through, the same plug still in its hole, and a plate dishing under the projectile without
// any failure (the centre moving with the projectile, joined to the clamped rim); and when such a run
// may stop early (track_settling, impact_is_over).
#include <gtest/gtest.h>

#include <cmath>

#include "common/case_file.hpp"
#include "common/case_observables.hpp"
#include "common/run_state.hpp"
#include "common/scene.hpp"

namespace impactsph {
namespace {

constexpr double kV0 = 150.0;       // m/s, projectile speed along -z in every state
constexpr double kRimR = 0.010;     // m, projectile radius
constexpr double kClampR = 0.057;   // m, the plate is clamped outside this radius

// The rim beyond 30 mm at twice the spacing ([bodies.coarse]), for the two-resolution plate.
const char* const kCoarseRim =
    "plate.coarse={ratio=2, region=\"outside-cylinder\", axis=\"z\", axis_point=[\"0 mm\",\"0 mm\",\"0 mm\"], "
    "radius=\"30 mm\"}";

Scene plate_scene(bool coarse_rim = false) {
  std::vector<std::string> sets{"output.vtu=false"};
  if (coarse_rim) sets.push_back(kCoarseRim);
  return build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/plate-8mm/case.toml", sets, "2 mm"));
}

double radius(const Vec3d& x) { return std::hypot(x.x, x.y); }

// The projectile moves on at kV0, its nose `shift` past where it started (the plate's front face).
void move_projectile(Scene& s, double shift) {
  ParticleSet& p = s.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.body[i] == s.spec.observables.projectile_index) {
      p.pos[i].z -= shift;
      p.vel[i] = {0, 0, -kV0};
    }
}

// The plate particles inside the projectile's radius moved by `shift` at kV0, the ring just outside
// failed and left in place, the rest at rest. The ring is two spacings wide: across one, intact particles
// of the plug and the plate can still be within the link distance (1.5 dx) of each other.
void cut_plug(Scene& s, double shift) {
  ParticleSet& p = s.particles;
  const double dx = s.spec.numerics.spacing;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.body[i] != s.spec.observables.target_index) continue;
    const double r = radius(p.pos[i]);
    p.vel[i] = {0, 0, 0};
    if (r < kRimR) {
      p.pos[i].z -= shift;
      p.vel[i] = {0, 0, -kV0};
    } else if (r < kRimR + 2 * dx) {
      p.damage[i] = 1.0;
    }
  }
  move_projectile(s, shift);
}

double plug_form_mass(const Scene& s) {  // the particles inside the projectile radius, whole body
  double m = 0;
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    if (s.particles.body[i] == s.spec.observables.target_index && radius(s.particles.pos[i]) < kRimR)
      m += s.particles.mass[i];
  return symmetry_multiplicity(s.spec, s.spec.observables.target_index) * m;
}

TEST(PlugDetection, PlugPushedThroughIsFoundAndPerforates) {
  Scene s = plate_scene();
  cut_plug(s, 0.012);
  const CaseObservables o = measure_observables(s, s.particles);
  EXPECT_TRUE(o.perforated);
  EXPECT_GT(o.plug_mass, 0.0);
  EXPECT_NEAR(o.plug_mass, plug_form_mass(s), 1e-12);
  EXPECT_NEAR(o.plug_velocity, kV0, 1e-9);
  EXPECT_NEAR(o.residual_velocity, kV0, 1e-9);
}

TEST(PlugDetection, FailedRimMovingWithThePlugIsPartOfIt) {
  // Half of the failed ring (the inner half) leaves with the plug; the outer half stays in the hole.
  Scene s = plate_scene();
  cut_plug(s, 0.012);
  ParticleSet& p = s.particles;
  const double dx = s.spec.numerics.spacing;
  double rim = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = radius(p.pos[i]);
    if (p.body[i] == s.spec.observables.target_index && r >= kRimR && r < kRimR + dx) {
      p.pos[i].z -= 0.012;
      p.vel[i] = {0, 0, -kV0};
      rim += p.mass[i];
    }
  }
  ASSERT_GT(rim, 0.0);
  rim *= symmetry_multiplicity(s.spec, s.spec.observables.target_index);
  const CaseObservables o = measure_observables(s, s.particles);
  EXPECT_TRUE(o.perforated);
  EXPECT_NEAR(o.plug_mass, plug_form_mass(s) + rim, 1e-12);
  EXPECT_NEAR(o.plug_velocity, kV0, 1e-9);
}

TEST(PlugDetection, PlugStillInItsHoleIsFoundButDoesNotPerforate) {
  Scene s = plate_scene();
  cut_plug(s, 0.0);  // cut by the failed ring but not moved yet: the nose has not passed the rear face
  const CaseObservables o = measure_observables(s, s.particles);
  EXPECT_NEAR(o.plug_mass, plug_form_mass(s), 1e-12);
  EXPECT_FALSE(o.perforated);
}

void dishing_plate_has_no_plug(bool coarse_rim) {
  // No failure: the plate deflects as a cone, w(r) = W (1 - r/R) up to the clamp radius, and moves with
  // the same profile of speeds; the projectile rides on its centre, its nose well past the rear face of
  // the clamped rim. Joined to the rim through intact material, the centre is no plug.
  Scene s = plate_scene(coarse_rim);
  ParticleSet& p = s.particles;
  const double W = 0.012;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.body[i] != s.spec.observables.target_index) continue;
    const double f = std::max(0.0, 1.0 - radius(p.pos[i]) / kClampR);
    p.pos[i].z -= W * f;
    p.vel[i] = {0, 0, -kV0 * f};
  }
  move_projectile(s, W);
  const CaseObservables o = measure_observables(s, s.particles);
  EXPECT_NEAR(o.residual_velocity, kV0, 1e-9);
  EXPECT_EQ(o.plug_mass, 0.0);
  EXPECT_FALSE(o.perforated);
}
TEST(PlugDetection, DishingPlateHasNoPlug) { dishing_plate_has_no_plug(false); }
// Its coarse rim's particles are 4 mm apart: linked at 1.5 dx they would each be a piece, and the fine
// centre, cut off from the clamped particles, a plug.
TEST(PlugDetection, DishingTwoResolutionPlateHasNoPlug) { dishing_plate_has_no_plug(true); }

TEST(PlugDetection, PlugPushedThroughATwoResolutionPlateIsFound) {
  Scene s = plate_scene(true);
  ASSERT_GT(s.bodies[static_cast<std::size_t>(s.spec.observables.target_index)].coarse_particle_count, 0u);
  cut_plug(s, 0.012);
  const CaseObservables o = measure_observables(s, s.particles);
  EXPECT_TRUE(o.perforated);
  EXPECT_NEAR(o.plug_mass, plug_form_mass(s), 1e-12);
}

TEST(PlugDetection, StoppedProjectileHasNoPlug) {
  Scene s = plate_scene();
  cut_plug(s, 0.012);
  for (std::size_t i = 0; i < s.particles.size(); ++i) s.particles.vel[i] = {0, 0, 0};
  const CaseObservables o = measure_observables(s, s.particles);
  EXPECT_EQ(o.plug_mass, 0.0);
  EXPECT_FALSE(o.perforated);
}

TEST(PlugDetection, DishingPlateIsNotOverPerforationAndReboundAre) {
  Scene s = plate_scene();
  const ObservablesSpec& spec = s.spec.observables;
  CaseObservables dishing;
  dishing.target = true;
  dishing.residual_velocity = 12.3;  // steady, riding on the deflecting plate
  EXPECT_FALSE(impact_is_over(spec, dishing));
  CaseObservables through = dishing;
  through.perforated = true;
  EXPECT_TRUE(impact_is_over(spec, through));
  CaseObservables rebound = dishing;
  rebound.residual_velocity = -10.6;
  EXPECT_TRUE(impact_is_over(spec, rebound));
  CaseObservables stuck = dishing;
  stuck.residual_velocity = 0.5 * spec.settle_tolerance;
  EXPECT_TRUE(impact_is_over(spec, stuck));
  CaseObservables no_target;
  no_target.residual_velocity = 12.3;
  EXPECT_TRUE(impact_is_over(spec, no_target));
}

TEST(PlugDetection, SettlesAfterTheVelocityLeftItsStartAndHeldForTheWindow) {
  Scene s = plate_scene();
  const ObservablesSpec& spec = s.spec.observables;  // window 30 us, tolerance 1 m/s
  RunClock c;
  const double us = 1e-6;
  track_settling(spec, 0, 150.0, c);
  track_settling(spec, 2 * us, 149.5, c);  // within the tolerance of the start: the impact has not begun
  EXPECT_LT(c.settle_window_start, 0);
  track_settling(spec, 4 * us, 120.0, c);  // left it: a window opens
  EXPECT_DOUBLE_EQ(c.settle_window_start, 4 * us);
  track_settling(spec, 20 * us, 100.0, c);  // moved on by more than the tolerance: the window restarts
  EXPECT_DOUBLE_EQ(c.settle_window_start, 20 * us);
  track_settling(spec, 40 * us, 100.6, c);
  EXPECT_LT(c.settled_time, 0);  // 20 us held, the window is 30 us
  track_settling(spec, 50 * us, 99.8, c);
  EXPECT_DOUBLE_EQ(c.settled_time, 20 * us);
  track_settling(spec, 52 * us, 98.0, c);  // leaves the band again: not settled any more
  EXPECT_LT(c.settled_time, 0);
}

// Near the ballistic limit a projectile can slow slowly enough to stay within the tolerance for a whole
// window while it is still coming to a stop in the hole: that is not a steady residual velocity. The same
// drift at a speed that it would take more than ten windows to lose is steady.
TEST(PlugDetection, AProjectileSlowingToAStopHasNotSettled) {
  Scene s = plate_scene();
  const ObservablesSpec& spec = s.spec.observables;  // window 30 us, tolerance 1 m/s
  const double us = 1e-6;
  auto settles = [&](double v_at_window_start) {
    RunClock c;
    track_settling(spec, 0, 150.0, c);
    for (int k = 0; k <= 32; ++k) track_settling(spec, (10 + k) * us, v_at_window_start - 0.025 * k, c);
    return c.settled_time >= 0;  // 0.8 m/s lost over 32 us: within the tolerance
  };
  EXPECT_FALSE(settles(4.0));   // 3.2 m/s left, 7.5 m/s lost in ten windows at that rate: stopping
  EXPECT_TRUE(settles(40.0));   // 39.2 m/s left: steady
  RunClock stopped;
  track_settling(spec, 0, 150.0, stopped);
  for (int k = 0; k <= 32; ++k) track_settling(spec, (10 + k) * us, 0.9 - 0.025 * k, stopped);
  EXPECT_GE(stopped.settled_time, 0);  // within the tolerance of zero: stopped, whatever the drift
}

}  // namespace
}  // namespace impactsph

namespace impactsph {
namespace {

// A held projectile: the verdict is known once the projectile has stopped or moves back (residual velocity
// at most the tolerance) with no target particle failing for a whole window; a failure restarts the
// window, and a projectile moving on clears it.
TEST(PlugDetection, AHeldProjectileIsKnownAfterAWindowWithoutFailures) {
  Scene s = plate_scene();
  const ObservablesSpec& spec = s.spec.observables;  // window 30 us, tolerance 1 m/s
  const double us = 1e-6;
  CaseObservables o;
  o.projectile = o.target = true;
  RunClock c;
  o.residual_velocity = 20.0;  // still pushing
  track_held(spec, 100 * us, o, c);
  EXPECT_LT(c.held_window_start, 0);
  o.residual_velocity = 0.5;  // at rest
  o.damage_fraction = 0.01;
  track_held(spec, 110 * us, o, c);
  EXPECT_DOUBLE_EQ(c.held_window_start, 110 * us);
  o.residual_velocity = -5.0;  // moving back, and a particle fails: the window starts again there
  o.damage_fraction = 0.012;
  track_held(spec, 120 * us, o, c);
  EXPECT_DOUBLE_EQ(c.held_window_start, 120 * us);
  track_held(spec, 148 * us, o, c);
  EXPECT_LT(c.held_time, 0);  // 28 us, the window is 30 us
  EXPECT_LT(verdict_time(c), 0);
  track_held(spec, 150 * us, o, c);
  EXPECT_DOUBLE_EQ(c.held_time, 120 * us);
  EXPECT_DOUBLE_EQ(verdict_time(c), 120 * us);
  o.perforated = true;  // a perforation clears it
  track_held(spec, 154 * us, o, c);
  EXPECT_LT(c.held_time, 0);
  EXPECT_LT(c.held_window_start, 0);
}

}  // namespace
}  // namespace impactsph
