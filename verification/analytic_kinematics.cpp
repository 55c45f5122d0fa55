// Kinematic checks of the reference solver's pass 1 on a free block of particles (no symmetry planes):
// - patch test: the corrected velocity gradient of a linear velocity field is exact at every particle,
//   surface and corners included, on a randomly perturbed lattice (F eqs 2.13-2.14);
// - objectivity: the deviatoric stress of a pre-stressed block in prescribed rigid rotation, advanced
//   with the solver's velocity gradients and the shared Jaumann rate by the solver's midpoint scheme,
//   rotates with the block (S = R S0 R^T) and keeps its invariants within 1e-6.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "common/case_file.hpp"
#include "common/material.hpp"
#include "verification/harness.hpp"

namespace impactsph::verification {
namespace {

const char* kBlock = R"(
[case]
name = "block"
[materials.steel]
density = "7850 kg/m^3"
eos = { kind = "linear", bulk_modulus = "196 GPa" }
strength = { kind = "elastic", shear_modulus = "75 GPa" }
[[bodies]]
name = "block"
material = "steel"
shape = "box"
min = ["-4 mm", "-4 mm", "-4 mm"]
max = ["4 mm", "4 mm", "4 mm"]
[numerics]
spacing = "1 mm"
[time]
end = "1 us"
output_interval = "1 us"
)";

Scene perturbed_block(double amplitude) {
  Scene scene = build_scene(parse_case_string(kBlock, "block.toml"));
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (Vec3d& x : scene.particles.pos) x += Vec3d{u(rng), u(rng), u(rng)};
  return scene;
}

TEST(PatchTest, CorrectedVelocityGradientIsExactForLinearField) {
  Scene scene = perturbed_block(0.1e-3);
  const Mat3d A{{{3.0, -1.0, 0.5}, {2.0, 0.25, -4.0}, {1.5, 0.75, -2.0}}};  // 1/s
  const Vec3d b{7.0, -3.0, 1.0};
  for (std::size_t i = 0; i < scene.particles.size(); ++i) scene.particles.vel[i] = A * scene.particles.pos[i] + b;
  reference::ReferenceSolver solver(scene);
  std::vector<Mat3d> grad;
  const std::size_t fallbacks = solver.velocity_gradients(scene.particles, grad);
  EXPECT_EQ(fallbacks, 0u);
  double worst = 0;
  for (const Mat3d& g : grad) worst = std::max(worst, frobenius(g - A) / frobenius(A));
  EXPECT_LT(worst, 1e-10) << "largest relative error of the corrected gradient";
}

Mat3d rotation_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
}

TEST(Objectivity, PrestressedBlockInRigidRotationKeepsInvariants) {
  Scene scene = perturbed_block(0.05e-3);
  ParticleSet& p = scene.particles;
  const std::vector<Vec3d> x0 = p.pos;
  const MaterialParams<double>& mat = scene.materials[0];
  const Sym3d s0{200e6, -50e6, -150e6, 80e6, -30e6, 60e6};  // deviatoric, Pa
  const double omega = 2e4;                                   // rad/s: rim speed 80 m/s
  const double turn = 0.5 * Constants<double>::pi;
  reference::ReferenceSolver solver(scene);
  // The solver's own CFL step for this block (signal speed plus the rim speed), rounded so that a whole
  // number of steps makes the quarter turn: the midpoint scheme is second order, so the time step is
  // part of what is verified.
  for (std::size_t i = 0; i < p.size(); ++i) p.vel[i] = Vec3d{-omega * p.pos[i].y, omega * p.pos[i].x, 0.0};
  const int steps = static_cast<int>(std::ceil(turn / omega / solver.stable_time_step(p)));
  const double dt = turn / omega / steps;

  std::vector<Sym3d> s(p.size(), s0);
  auto place = [&](double t) {
    const Mat3d r = rotation_z(omega * t);
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.pos[i] = r * x0[i];
      p.vel[i] = Vec3d{-omega * p.pos[i].y, omega * p.pos[i].x, 0.0};
    }
  };
  std::vector<Mat3d> grad;
  for (int k = 0; k < steps; ++k) {
    const double t = k * dt;
    place(t);
    solver.velocity_gradients(p, grad);
    std::vector<Sym3d> s_half(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) s_half[i] = s[i] + (0.5 * dt) * deviatoric_stress_rate(mat, s[i], grad[i]);
    place(t + 0.5 * dt);
    solver.velocity_gradients(p, grad);
    for (std::size_t i = 0; i < p.size(); ++i) s[i] = s[i] + dt * deviatoric_stress_rate(mat, s_half[i], grad[i]);
  }
  const Mat3d r = rotation_z(turn);
  const Mat3d expected = r * s0.full() * r.transpose();
  const double j2_0 = ddot(s0, s0), j3_0 = determinant(s0.full());
  double worst_invariant = 0, worst_tensor = 0;
  for (const Sym3d& si : s) {
    worst_invariant = std::max({worst_invariant, std::abs(ddot(si, si) / j2_0 - 1),
                                std::abs(determinant(si.full()) / j3_0 - 1)});
    worst_tensor = std::max(worst_tensor, frobenius(si.full() - expected) / frobenius(expected));
  }
  std::printf("objectivity: %d steps, worst invariant change %.3g, worst tensor error %.3g (J3_0 %.4g Pa^3, |S0|^3 %.4g)\n",
              steps, worst_invariant, worst_tensor, j3_0, std::pow(ddot(s0, s0), 1.5));
  EXPECT_LT(worst_invariant, 1e-6) << "stress invariants changed under a rigid rotation";
  EXPECT_LT(worst_tensor, 1e-5) << "stress did not rotate with the block (Jaumann sign?)";
}

}  // namespace
}  // namespace impactsph::verification
