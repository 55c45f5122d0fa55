// The gpu port's host build through the run driver and on its own: restart bit for bit, the same bits for
// one and two threads, the divergence diagnostic with the last good state kept, and the statistics the
// reference reports (fallbacks, ghosts). Field agreement with the reference is verification/crosscheck.
#include <algorithm>
#include <gtest/gtest.h>
#include <omp.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>

#include "common/case_file.hpp"
#include "common/driver.hpp"
#include "common/errors.hpp"
#include "gpu/solver.hpp"
#include "reference/solver.hpp"

namespace impactsph {
namespace {

namespace fs = std::filesystem;

Scene wave_scene() {
  const std::vector<std::string> sets{"time.end=2us", "time.output_interval=0.25us", "time.frame_interval=1us"};
  return build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/elastic-wave/case.toml", sets, "1 mm"));
}

// The ceramics physics of paper X (JH-2 damage and bulking, SRAD penalty contact, variable h), a few
// hundred particles for 1.5 us.
Scene ceramics_scene() {
  const std::vector<std::string> sets{"time.end=1.5us", "time.output_interval=0.25us", "time.frame_interval=0.5us"};
  return build_scene(load_case_file(std::string(IMPACTSPH_VERIFICATION_DATA) + "/ceramics.toml", sets, ""));
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// The gpu solver as the CLI sets it up (copies to the host deferred to the driver), raising SIGINT after
// `stop_after` steps as Ctrl-C would.
class InterruptingGpu final : public Stepper {
 public:
  InterruptingGpu(const Scene& scene, gpu::Precision precision, long stop_after)
      : inner_(gpu::host::make_solver(scene, precision)), stop_after_(stop_after) {
    inner_->defer_host_copies(true);
  }
  std::string name() const override { return inner_->name(); }
  double stable_time_step(const ParticleSet& p) override { return inner_->stable_time_step(p); }
  void step(ParticleSet& p, double dt) override {
    inner_->step(p, dt);
    if (++steps_ == stop_after_) std::raise(SIGINT);
  }
  StepStats last_stats() const override { return inner_->last_stats(); }
  void copy_to_host(ParticleSet& p) override { inner_->copy_to_host(p); }

 private:
  std::unique_ptr<gpu::GpuStepper> inner_;
  long stop_after_;
  long steps_ = 0;
};

struct RestartCase {
  gpu::Precision precision;
  const char* scene;  // "wave" or "ceramics"
  long stop_after;    // steps before the interrupt
};
Scene restart_scene(const RestartCase& c) { return std::string(c.scene) == "wave" ? wave_scene() : ceramics_scene(); }

class GpuRestart : public ::testing::TestWithParam<RestartCase> {};

TEST_P(GpuRestart, InterruptedRunContinuesBitForBit) {
  const RestartCase rc = GetParam();
  const fs::path root = fs::temp_directory_path() / ("impactsph-gpu-restart-" + std::to_string(::getpid()));
  fs::remove_all(root);
  RunOptions opt;
  opt.quiet = true;
  opt.fingerprint = "test";
  opt.install_signal_handlers = true;

  Scene straight = restart_scene(rc);
  const ParticleSet initial = straight.particles;
  InterruptingGpu solver(straight, rc.precision, -1);
  opt.out_dir = root / "straight";
  const RunResult full = run_simulation(straight, solver, opt);
  ASSERT_FALSE(full.interrupted);

  // At rc.stop_after steps, or halfway where the case's step factor leaves fewer steps than that.
  const long stop_after = std::min(rc.stop_after, full.clock.step / 2);
  ASSERT_GT(stop_after, 5);
  Scene stopped = restart_scene(rc);
  InterruptingGpu interrupting(stopped, rc.precision, stop_after);
  opt.out_dir = root / "stopped";
  const RunResult first = run_simulation(stopped, interrupting, opt);
  ASSERT_TRUE(first.interrupted);
  EXPECT_EQ(first.clock.step, stop_after);

  Scene resumed = restart_scene(rc);
  InterruptingGpu solver2(resumed, rc.precision, -1);
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
  EXPECT_TRUE(same_bits(a.damage, b.damage));
  EXPECT_TRUE(same_bits(a.bulking_pressure, b.bulking_pressure));
  EXPECT_TRUE(same_bits(a.h, b.h));
  // The run moved: the comparison is not between two copies of the initial state.
  EXPECT_FALSE(same_bits(a.vel, initial.vel));
  if (std::string(rc.scene) == "ceramics") {
    // ... and the ceramics physics acted: damage, bulking and a changed smoothing length.
    EXPECT_FALSE(same_bits(a.damage, initial.damage));
    EXPECT_FALSE(same_bits(a.bulking_pressure, initial.bulking_pressure));
    EXPECT_FALSE(same_bits(a.h, initial.h));
  }
  fs::remove_all(root);
}

INSTANTIATE_TEST_SUITE_P(Scenes, GpuRestart,
                         ::testing::Values(RestartCase{gpu::Precision::Double, "wave", 37},
                                           RestartCase{gpu::Precision::Float, "wave", 37},
                                           RestartCase{gpu::Precision::Double, "ceramics", 25},
                                           RestartCase{gpu::Precision::Float, "ceramics", 25}),
                         [](const auto& info) {
                           return std::string(info.param.scene) + "_" + gpu::precision_name(info.param.precision);
                         });

TEST(GpuDeterminism, OneAndTwoThreadsGiveTheSameBits) {
  auto advance = [](int threads) {
    omp_set_num_threads(threads);
    Scene scene = wave_scene();
    std::unique_ptr<gpu::GpuStepper> solver = gpu::host::make_solver(scene, gpu::Precision::Float);
    for (int k = 0; k < 20; ++k) solver->step(scene.particles, solver->stable_time_step(scene.particles));
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

// A NaN in the state stops the step with the particle's scene index, body and fields, and the particles
// keep their state of the step start.
TEST(GpuDivergence, NamesTheParticleAndKeepsTheLastGoodState) {
  Scene scene = wave_scene();
  const std::size_t bad = scene.particles.size() / 3;
  scene.particles.energy[bad] = std::nan("");
  const ParticleSet before = scene.particles;
  std::unique_ptr<gpu::GpuStepper> solver = gpu::host::make_solver(scene, gpu::Precision::Double);
  const double dt = 1e-9;
  try {
    solver->step(scene.particles, dt);
    FAIL() << "no DivergenceError";
  } catch (const DivergenceError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("particle " + std::to_string(bad) + " of body"), std::string::npos) << msg;
    EXPECT_NE(msg.find("specific energy nan"), std::string::npos) << msg;
  }
  EXPECT_TRUE(same_bits(scene.particles.pos, before.pos));
  EXPECT_TRUE(same_bits(scene.particles.vel, before.vel));
}

// The statistics the driver reports match the reference's on the same state: ghosts of the four symmetry
// planes within the search radius (more than the reference's, whose radius has a tiny skin, and at least
// as many), correction fallbacks, and the mean neighbour count within the kernel support.
TEST(GpuStats, FallbacksAndNeighboursMatchTheReference) {
  Scene a = wave_scene();
  Scene b = a;
  reference::ReferenceSolver ref(b);
  std::unique_ptr<gpu::GpuStepper> port = gpu::host::make_solver(a, gpu::Precision::Double);
  const double dt = ref.stable_time_step(b.particles);
  EXPECT_EQ(port->stable_time_step(a.particles), dt);
  ref.step(b.particles, dt);
  port->step(a.particles, dt);
  EXPECT_EQ(port->last_stats().correction_fallbacks, ref.last_stats().correction_fallbacks);
  EXPECT_GE(port->last_stats().ghosts, ref.last_stats().ghosts);
  EXPECT_NEAR(port->last_stats().mean_neighbours, ref.last_stats().mean_neighbours,
              1e-3 * ref.last_stats().mean_neighbours);
  EXPECT_EQ(port->sorts(), 1);
}

}  // namespace
}  // namespace impactsph
