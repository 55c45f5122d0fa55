// Checkpoint and restart through the run driver: a run stopped by SIGINT writes a checkpoint, and the
// restarted run ends with the same bits as an uninterrupted one (same thread count).
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <unistd.h>

#include "common/case_file.hpp"
#include "common/checkpoint.hpp"
#include "common/driver.hpp"
#include "reference/solver.hpp"

namespace impactsph {
namespace {

namespace fs = std::filesystem;

// Passes steps through to the reference solver and raises SIGINT after `stop_after` of them, as a user
// pressing Ctrl-C would.
class InterruptingStepper final : public Stepper {
 public:
  InterruptingStepper(const Scene& scene, long stop_after) : inner_(scene), stop_after_(stop_after) {}
  std::string name() const override { return inner_.name(); }
  double stable_time_step(const ParticleSet& p) override { return inner_.stable_time_step(p); }
  void step(ParticleSet& p, double dt) override {
    inner_.step(p, dt);
    if (++steps_ == stop_after_) std::raise(SIGINT);
  }
  StepStats last_stats() const override { return inner_.last_stats(); }

 private:
  reference::ReferenceSolver inner_;
  long stop_after_;
  long steps_ = 0;
};

Scene wave_scene(const std::string& integrator = "leapfrog") {
  const std::vector<std::string> sets{"time.end=2us", "time.output_interval=0.25us", "time.frame_interval=1us",
                                      "numerics.integrator=" + integrator};
  return build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/elastic-wave/case.toml", sets, "1 mm"));
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// Both integrators: the leapfrog carries the rates of its last evaluation in the checkpoint.
class Restart : public ::testing::TestWithParam<const char*> {};
INSTANTIATE_TEST_SUITE_P(Integrators, Restart, ::testing::Values("leapfrog", "midpoint"));

TEST_P(Restart, InterruptedRunContinuesBitForBit) {
  const auto wave_scene = [this] { return impactsph::wave_scene(GetParam()); };
  const fs::path root =
      fs::temp_directory_path() / ("impactsph-restart-" + std::string(GetParam()) + std::to_string(::getpid()));
  fs::remove_all(root);
  RunOptions opt;
  opt.quiet = true;
  opt.fingerprint = "test";

  Scene straight = wave_scene();
  reference::ReferenceSolver solver(straight);
  opt.out_dir = root / "straight";
  const RunResult full = run_simulation(straight, solver, opt);
  ASSERT_FALSE(full.interrupted);

  // Stopped halfway, whatever the case's step factor makes of the 2 us.
  const long stop_after = full.clock.step / 2;
  ASSERT_GT(stop_after, 5);
  Scene stopped = wave_scene();
  InterruptingStepper interrupting(stopped, stop_after);
  opt.out_dir = root / "stopped";
  const RunResult first = run_simulation(stopped, interrupting, opt);
  ASSERT_TRUE(first.interrupted);
  EXPECT_EQ(first.clock.step, stop_after);
  EXPECT_TRUE(fs::exists(checkpoint_path(opt.out_dir)));

  Scene resumed = wave_scene();
  reference::ReferenceSolver solver2(resumed);
  opt.restart = true;
  const RunResult second = run_simulation(resumed, solver2, opt);
  ASSERT_FALSE(second.interrupted);
  EXPECT_EQ(second.clock.step, full.clock.step);
  EXPECT_EQ(second.clock.time, full.clock.time);
  const ParticleSet& a = straight.particles;
  const ParticleSet& b = resumed.particles;
  EXPECT_TRUE(same_bits(a.pos, b.pos));
  EXPECT_TRUE(same_bits(a.vel, b.vel));
  EXPECT_TRUE(same_bits(a.rho, b.rho));
  EXPECT_TRUE(same_bits(a.energy, b.energy));
  EXPECT_TRUE(same_bits(a.dev_stress, b.dev_stress));

  // A restart with other inputs is refused.
  Scene other = wave_scene();
  reference::ReferenceSolver solver3(other);
  opt.fingerprint = "another case";
  EXPECT_THROW(run_simulation(other, solver3, opt), std::runtime_error);
  fs::remove_all(root);
}

// The 8 mm plate at 2.5 mm and 300 m/s with the non-local fracture energy (common/nonlocal.hpp): its first
// failures come at about 32 us.
Scene nonlocal_plate_scene() {
  const std::vector<std::string> sets{
      "projectile.velocity=300 m/s", "time.end=40us", "output.vtu=false", "output.picture=false",
      "weldox-460e.damage={kind=\"fracture-energy\", fracture_energy=\"1300 kJ/m^2\", nonlocal_radius=\"6 mm\", "
      "crack_faces=\"compression\"}"};
  return build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/plate-8mm/case.toml", sets, "2.5 mm"));
}

// The non-local average runs over the initial configuration, which a restarted solver takes from the scene
// it was made from, before the checkpoint replaces the particles: a run stopped before the first failures
// continues with the same bits, failures included.
TEST(RestartNonlocal, NonlocalDamageContinuesBitForBit) {
  const fs::path root = fs::temp_directory_path() / ("impactsph-restart-nonlocal-" + std::to_string(::getpid()));
  fs::remove_all(root);
  RunOptions opt;
  opt.quiet = true;
  opt.fingerprint = "test";
  Scene straight = nonlocal_plate_scene();
  reference::ReferenceSolver solver(straight);
  opt.out_dir = root / "straight";
  const RunResult full = run_simulation(straight, solver, opt);
  ASSERT_FALSE(full.interrupted);

  // Stopped three quarters of the way (30 of the 40 us), before the first failure.
  Scene stopped = nonlocal_plate_scene();
  InterruptingStepper interrupting(stopped, full.clock.step * 3 / 4);
  opt.out_dir = root / "stopped";
  ASSERT_TRUE(run_simulation(stopped, interrupting, opt).interrupted);
  const auto failed = [](const ParticleSet& p) { return std::count_if(p.damage.begin(), p.damage.end(), [](double d) { return d >= 1; }); };
  EXPECT_EQ(failed(stopped.particles), 0);

  Scene resumed = nonlocal_plate_scene();
  reference::ReferenceSolver solver2(resumed);
  opt.restart = true;
  ASSERT_FALSE(run_simulation(resumed, solver2, opt).interrupted);
  EXPECT_GT(failed(straight.particles), 0);
  EXPECT_TRUE(same_bits(straight.particles.damage, resumed.particles.damage));
  EXPECT_TRUE(same_bits(straight.particles.pos, resumed.particles.pos));
  EXPECT_TRUE(same_bits(straight.particles.vel, resumed.particles.vel));
  fs::remove_all(root);
}

}  // namespace
}  // namespace impactsph

namespace impactsph {
namespace {

// Gathers in a fixed order make the reference independent of the thread count, which is stronger than
// the design's rule (same thread count, same bits).
TEST(Determinism, OneAndTwoThreadsGiveTheSameBits) {
  auto advance = [](int threads) {
    omp_set_num_threads(threads);
    Scene scene = wave_scene();
    reference::ReferenceSolver solver(scene);
    for (int k = 0; k < 20; ++k) solver.step(scene.particles, solver.stable_time_step(scene.particles));
    return scene.particles;
  };
  const int saved = omp_get_max_threads();
  const ParticleSet a = advance(1);
  const ParticleSet b = advance(2);
  omp_set_num_threads(saved);
  EXPECT_TRUE(same_bits(a.pos, b.pos));
  EXPECT_TRUE(same_bits(a.vel, b.vel));
  EXPECT_TRUE(same_bits(a.rho, b.rho));
  EXPECT_TRUE(same_bits(a.energy, b.energy));
  EXPECT_TRUE(same_bits(a.dev_stress, b.dev_stress));
}

}  // namespace
}  // namespace impactsph
