// Penalty contact through the reference solver (issue 3): two elastic-plastic blocks of different
// density and size collide obliquely with the penalty law of F 4.1-4.6 built as one pair force applied
// equal and opposite. Total momentum is conserved to round-off, and kinetic + internal energy plus the
// energy the contact took is conserved to the time-integration error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/case_file.hpp"
#include "common/observables.hpp"
#include "verification/harness.hpp"

namespace impactsph::verification {
namespace {

const char* kBlocks = R"(
[case]
name = "contact-blocks"
[materials.steel]
density = "7850 kg/m^3"
eos = { kind = "mie-gruneisen", c0 = "4578 m/s", s = 1.33, gamma0 = 1.67 }
strength = { kind = "perfectly-plastic", shear_modulus = "75 GPa", yield_stress = "500 MPa" }
[materials.tungsten]
density = "17600 kg/m^3"
eos = { kind = "mie-gruneisen", c0 = "4030 m/s", s = 1.237, gamma0 = 1.67 }
strength = { kind = "elastic", shear_modulus = "160 GPa" }
[[bodies]]
name = "block"
material = "steel"
shape = "box"
min = ["0 mm", "0 mm", "0 mm"]
max = ["8 mm", "8 mm", "4 mm"]
[[bodies]]
name = "striker"
material = "tungsten"
shape = "box"
min = ["2 mm", "1 mm", "5 mm"]
max = ["6 mm", "5 mm", "9 mm"]
velocity = ["40 m/s", "-25 m/s", "-300 m/s"]
[[contacts]]
bodies = ["block", "striker"]
kind = "penalty"
[numerics]
spacing = "0.5 mm"
[time]
end = "6 us"
output_interval = "1 us"
)";

TEST(PenaltyContact, ConservesMomentumThroughTheSolver) {
  Scene scene = build_scene(parse_case_string(kBlocks, "contact-blocks.toml"));
  reference::ReferenceSolver solver(scene);
  const Totals t0 = summarise_totals(scene.particles);
  double contact_work = 0;
  const long steps = run_reference(scene, solver, scene.spec.time.end,
                                   [&](double) { contact_work += solver.last_stats().contact_work; });
  const Totals t1 = summarise_totals(scene.particles);
  const std::vector<BodySummary> bodies = summarise_bodies(scene.particles, scene.bodies.size());
  const double p_scale = 0.5 * scene.bodies[1].initial_mass * 300.0;
  const double e0 = t0.total_energy(), e1 = t1.total_energy() + contact_work;
  std::printf("penalty contact: %ld steps, striker vz %.2f m/s, block vz %.2f m/s, momentum error %.3g of m v, "
              "contact took %.4g J of %.4g J, energy error %.3g\n",
              steps, bodies[1].velocity.z, bodies[0].velocity.z, norm(t1.momentum - t0.momentum) / p_scale,
              contact_work, e0, (e1 - e0) / e0);
  EXPECT_LT(bodies[0].velocity.z, -1.0) << "the striker never pushed the block (along -z): no contact happened";
  EXPECT_LT(norm(t1.momentum - t0.momentum) / p_scale, 1e-12);
  // Not a time-integration error: the penalty's stiffness K_p m*/dt^2 and damping K_p M_h/dt (F eq 4.4, 4.6,
  // common/contact.hpp) change with the step, and its energy error does not shrink with it. Measured at step factors 0.1 / 0.2 / 0.3 (2026-12-08):
  // leapfrog 1.72 / 1.64 / 1.91 %, midpoint 1.46 / 0.52 / 1.33 %. The 1 % this test once asked held for the
  // midpoint rule at 0.2 only; 2.5 % bounds both integrators at every factor measured.
  EXPECT_LT(std::abs(e1 - e0) / e0, 0.025);
}

}  // namespace
}  // namespace impactsph::verification
