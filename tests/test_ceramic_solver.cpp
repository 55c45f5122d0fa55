// The reference solver on the ceramic-tile scene (JH-2 alumina, Johnson-Cook tungsten) at a coarse
// spacing: fragments and isolated particles, whose kernel-gradient correction matrix is singular (X
// section 3.1), must not produce NaN; the solver falls back to the uncorrected gradient and counts it.
// Variable smoothing length stays within its bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <unistd.h>

#include "common/case_file.hpp"
#include "common/checkpoint.hpp"
#include "common/driver.hpp"
#include "reference/solver.hpp"

namespace {

using namespace impactsph;

Scene tile_scene(const std::vector<std::string>& sets) {
  return build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/ceramic-tile/case.toml", sets, "2.54 mm"));
}

bool all_finite(const ParticleSet& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double v[] = {p.pos[i].x, p.pos[i].y, p.pos[i].z, p.vel[i].x, p.vel[i].y, p.vel[i].z, p.rho[i],
                        p.energy[i], p.pressure[i], p.h[i], p.dev_stress[i].xx, p.dev_stress[i].xy,
                        p.damage[i], p.bulking_pressure[i]};
    for (double x : v)
      if (!std::isfinite(x)) return false;
  }
  return true;
}

TEST(CeramicSolver, IsolatedParticleAndFragmentStayFinite) {
  Scene scene = tile_scene({"output.vtu=false"});
  ParticleSet& p = scene.particles;
  ASSERT_GT(p.size(), 10u);
  // Pull three tile particles far away from everything: one alone, two as a pair one spacing apart; both
  // fully damaged and flying, with a deviatoric stress and a bulking pressure left on them.
  const double dx = scene.spec.numerics.spacing;
  const Vec3d far{0.2, 0.2, 0.1};
  const std::size_t lone = 0, a = 1, b = 2;
  p.pos[lone] = far;
  p.pos[a] = far + Vec3d{0.05, 0, 0};
  p.pos[b] = far + Vec3d{0.05 + dx, 0, 0};
  for (std::size_t i : {lone, a, b}) {
    p.vel[i] = Vec3d{300, -200, 100};
    p.damage[i] = 1.0;
    p.dev_stress[i] = Sym3d{1e8, -5e7, -5e7, 2e7, 0, 0};
    p.bulking_pressure[i] = 2e8;
  }
  p.vel[b] = Vec3d{-300, -200, 100};  // the pair collides
  reference::ReferenceSolver solver(scene);
  double dt = solver.stable_time_step(p);
  for (int s = 0; s < 20; ++s) {
    solver.step(p, dt);
    ASSERT_TRUE(all_finite(p)) << "step " << s;
  }
  EXPECT_GE(solver.last_stats().correction_fallbacks, 3u);  // at least the lone particle and the pair
}

TEST(CeramicSolver, VariableSmoothingLengthStaysWithinItsBounds) {
  Scene scene = tile_scene({"output.vtu=false", "rod.variable_h=true", "rod.h_min=0.9", "rod.h_max=1.1",
                            "tile.variable_h=true"});
  ParticleSet& p = scene.particles;
  const double h0 = p.h[0];
  reference::ReferenceSolver solver(scene);
  const double dt = solver.stable_time_step(p);
  for (int s = 0; s < 25; ++s) solver.step(p, dt);
  ASSERT_TRUE(all_finite(p));
  bool changed = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (scene.bodies[static_cast<std::size_t>(p.body[i])].name == "rod") {
      EXPECT_GE(p.h[i], 0.9 * h0 * (1 - 1e-12));
      EXPECT_LE(p.h[i], 1.1 * h0 * (1 + 1e-12));
    }
    changed = changed || p.h[i] != h0;
  }
  EXPECT_TRUE(changed) << "the impact compresses the rod's nose: its h must change";
}

// Checkpoint and restart carry the ceramic state (damage, bulking pressure, variable h): an interrupted
// run of the tile continues bit for bit.
class StopAfter final : public Stepper {
 public:
  StopAfter(const Scene& scene, long n) : inner_(scene), n_(n) {}
  std::string name() const override { return inner_.name(); }
  double stable_time_step(const ParticleSet& p) override { return inner_.stable_time_step(p); }
  void step(ParticleSet& p, double dt) override {
    inner_.step(p, dt);
    if (++steps_ == n_) std::raise(SIGINT);
  }
  StepStats last_stats() const override { return inner_.last_stats(); }

 private:
  reference::ReferenceSolver inner_;
  long n_, steps_ = 0;
};

template <class T> bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(CeramicSolver, RestartContinuesBitForBit) {
  namespace fs = std::filesystem;
  const std::vector<std::string> sets{"output.vtu=false", "time.end=2us", "time.output_interval=1us",
                                      "time.frame_interval=1us", "tile.variable_h=true"};
  const fs::path root = fs::temp_directory_path() / ("impactsph-tile-restart-" + std::to_string(::getpid()));
  fs::remove_all(root);
  RunOptions opt;
  opt.quiet = true;
  opt.fingerprint = "tile";
  Scene straight = tile_scene(sets);
  reference::ReferenceSolver solver(straight);
  opt.out_dir = root / "straight";
  ASSERT_FALSE(run_simulation(straight, solver, opt).interrupted);

  Scene stopped = tile_scene(sets);
  StopAfter stopping(stopped, 15);
  opt.out_dir = root / "stopped";
  ASSERT_TRUE(run_simulation(stopped, stopping, opt).interrupted);
  Scene resumed = tile_scene(sets);
  reference::ReferenceSolver solver2(resumed);
  opt.restart = true;
  ASSERT_FALSE(run_simulation(resumed, solver2, opt).interrupted);
  const ParticleSet &a = straight.particles, &b = resumed.particles;
  EXPECT_TRUE(same_bits(a.pos, b.pos));
  EXPECT_TRUE(same_bits(a.vel, b.vel));
  EXPECT_TRUE(same_bits(a.damage, b.damage));
  EXPECT_TRUE(same_bits(a.bulking_pressure, b.bulking_pressure));
  EXPECT_TRUE(same_bits(a.h, b.h));
  double bulk = 0;
  for (double x : a.bulking_pressure) bulk = std::max(bulk, x);
  EXPECT_GT(bulk, 0.0) << "the impact should have bulked some ceramic by 2 us";
  fs::remove_all(root);
}

}  // namespace
