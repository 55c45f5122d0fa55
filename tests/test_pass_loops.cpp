// The reference's pass loops (reference/solver.cpp) drop the Verlet skin before they take a pair, keep the
// pairs of pass 1 for pass 2 and split each row into its SPH pairs and its penalty contact pairs. The gpu
// port's host build (double) takes the SPH pairs of both passes over cluster pairs in SIMD lanes
// (gpu/solver_clusters.hpp) or, as the CUDA kernels do, every list entry through the unfiltered
// common/stages.hpp add_gradient_neighbour and add_rate_neighbour; penalty contact every entry through
// add_contact_neighbour. They differ only in the order of their sums, so one step of each from the same state
// must agree to round-off: a pair that the prefilter or a lane mask drops, or one sent to the wrong sum, moves
// a rate by a whole pair term, many orders above the bound. The float build's cluster pairs (16 lanes, 8 in
// double) are checked against its rows in the same way.
// The scenes are set up so that every branch of the loops has pairs: penalty contact, failed and partly
// damaged particles (crack faces), mirror images, a wall that some particles let go of, the artificial
// stress, the limited viscosity, variable smoothing lengths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/case_file.hpp"
#include "common/stepper.hpp"
#include "gpu/solver.hpp"
#include "reference/solver.hpp"

namespace impactsph {
namespace {

// Largest |a_ref - a_port| over the particles against the largest step increment |a_ref - a_0|.
struct FieldGap {
  double gap = 0;
  double increment = 0;
};
template <class Get>
FieldGap field_gap(const ParticleSet& before, const ParticleSet& ref, const ParticleSet& port, Get get) {
  FieldGap g;
  for (std::size_t i = 0; i < before.size(); ++i) {
    g.gap = std::max(g.gap, std::abs(get(ref, i) - get(port, i)));
    g.increment = std::max(g.increment, std::abs(get(ref, i) - get(before, i)));
  }
  return g;
}

// One step of two solvers from the same state: each field's largest gap between them against its largest
// step increment, for the velocity, density, energy, deviatoric stress and smoothing length.
std::vector<std::pair<std::string, FieldGap>> step_gaps(const Scene& scene, Stepper& first, Scene& a, Stepper& second,
                                                        Scene& b) {
  const double dt = first.stable_time_step(a.particles);
  first.step(a.particles, dt);
  second.step(b.particles, dt);
  const ParticleSet& p0 = scene.particles;
  const ParticleSet& pr = a.particles;
  const ParticleSet& pp = b.particles;
  std::vector<std::pair<std::string, FieldGap>> gaps;
  if (pr.size() != pp.size()) {
    ADD_FAILURE() << "the two solvers' particle counts differ";
    return gaps;
  }
  for (int c = 0; c < 3; ++c)
    gaps.emplace_back("vel[" + std::to_string(c) + "]",
                      field_gap(p0, pr, pp, [c](const ParticleSet& p, std::size_t i) { return p.vel[i][c]; }));
  gaps.emplace_back("rho", field_gap(p0, pr, pp, [](const ParticleSet& p, std::size_t i) { return p.rho[i]; }));
  gaps.emplace_back("energy", field_gap(p0, pr, pp, [](const ParticleSet& p, std::size_t i) { return p.energy[i]; }));
  gaps.emplace_back("dev_stress.xx",
                    field_gap(p0, pr, pp, [](const ParticleSet& p, std::size_t i) { return p.dev_stress[i].xx; }));
  gaps.emplace_back("dev_stress.yz",
                    field_gap(p0, pr, pp, [](const ParticleSet& p, std::size_t i) { return p.dev_stress[i].yz; }));
  gaps.emplace_back("h", field_gap(p0, pr, pp, [](const ParticleSet& p, std::size_t i) { return p.h[i]; }));
  return gaps;
}
void expect_gaps_within(const std::vector<std::pair<std::string, FieldGap>>& gaps, const std::string& what,
                        double bound) {
  for (const auto& [field, g] : gaps) {
    SCOPED_TRACE(what + ", " + field);
    if (field != "h") EXPECT_GT(g.increment, 0.0);
    EXPECT_LE(g.gap, bound * g.increment);
  }
}

// One step of the reference and of the port (double, host) from the same state: every field within 1e-9 of
// its largest increment. Measured: 1e-16 to 2.5e-14 of it (round-off of the reordered sums); a pair dropped
// within the last 1 % of the support's radius gave 1e-7 to 4e-5, contact pairs or a crack face or a wall's
// let-go missed 0.03 to 1.8.
void expect_same_step_as(const Scene& scene, const std::string& what, bool cluster_pairs) {
  Scene a = scene, b = scene;
  reference::ReferenceSolver ref(a);
  std::unique_ptr<gpu::GpuStepper> port = gpu::host::make_solver(b, gpu::Precision::Double);
  port->use_cluster_pairs(cluster_pairs);
  expect_gaps_within(step_gaps(scene, ref, a, *port, b), what, 1e-9);
}
// The float port's cluster pairs (16 lanes, a layout of their own) against its rows, one step from the same
// state: the same terms summed in another order, so within float round-off: 1e-4 of the increment. Measured:
// 7e-9 to 6.4e-7 of it, the density 1.3e-5 (plate, Taylor bar); a pair dropped or doubled moves a field by a
// pair's whole share.
void expect_same_float_step(const Scene& scene, const std::string& what) {
  Scene a = scene, b = scene;
  std::unique_ptr<gpu::GpuStepper> rows = gpu::host::make_solver(a, gpu::Precision::Float);
  std::unique_ptr<gpu::GpuStepper> clusters = gpu::host::make_solver(b, gpu::Precision::Float);
  rows->use_cluster_pairs(false);
  clusters->use_cluster_pairs(true);
  expect_gaps_within(step_gaps(scene, *rows, a, *clusters, b), what + ", float cluster pairs against float rows", 1e-4);
}
// The port both ways: its host build's pair passes over cluster pairs in SIMD lanes (gpu/solver_clusters.hpp),
// and over the rows entry by entry as the CUDA kernels take them; and the float build's two against each other.
void expect_same_step(const Scene& scene, const std::string& what) {
  expect_same_step_as(scene, what + ", cluster pairs", true);
  expect_same_step_as(scene, what + ", rows", false);
  expect_same_float_step(scene, what);
}

// A deterministic disturbance added to the state, so that no pair term cancels by symmetry and the pair
// distances leave the lattice's few values: positions by up to 5 % of the spacing dx (m), velocity (m/s),
// density (a fraction of rho0) and deviatoric stress (Pa) varying over a few spacings.
void disturb(ParticleSet& p, double dx, double dv, double drho, double dS) {
  const double length = 4 * dx;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3d x = (1 / length) * p.pos[i];
    const double k = static_cast<double>(i);
    p.pos[i] = p.pos[i] + 0.05 * dx * Vec3d{std::sin(2.1 * k), std::sin(3.7 * k + 1), std::sin(5.3 * k + 2)};
    p.vel[i] = p.vel[i] + dv * Vec3d{std::sin(x.y + 0.3), std::cos(1.3 * x.z), std::sin(0.7 * x.x + x.y)};
    p.rho[i] *= 1 + drho * std::sin(x.x + 1.7 * x.z);
    const Sym3d S{dS * std::sin(x.z), -dS * std::cos(x.x), dS * 0.3 * std::sin(x.y), 0.4 * dS * std::cos(x.y + x.z),
                  0.2 * dS * std::sin(x.x), 0.5 * dS * std::cos(x.z)};
    const double mean = (S.xx + S.yy + S.zz) / 3;
    p.dev_stress[i] = p.dev_stress[i] + Sym3d{S.xx - mean, S.yy - mean, S.zz - mean, S.xy, S.yz, S.zx};
  }
}

std::int32_t body_index(const Scene& s, const std::string& name) {
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    if (s.bodies[b].name == name) return static_cast<std::int32_t>(b);
  ADD_FAILURE() << "no body " << name;
  return -1;
}

// The 8 mm plate at 2 mm (quarter model: two mirror planes; penalty contact; non-local fracture energy,
// bounded artificial stress): the projectile pressed 0.3 spacings into the contact gap, a ring of failed
// plate particles (crack faces) and a ring of partly damaged ones around the axis.
TEST(ReferencePassLoops, PlateWithContactCrackFacesAndImagesAsTheUnfilteredLoops) {
  Scene s = build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/plate-8mm/case.toml",
                                       {"projectile.velocity=190.7 m/s"}, "2 mm"));
  ParticleSet& p = s.particles;
  const std::int32_t plate = body_index(s, "plate"), projectile = body_index(s, "projectile");
  const double dx = 2e-3;
  std::size_t failed = 0, damaged = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.body[i] == projectile) p.pos[i].z -= 0.3 * dx;
    if (p.body[i] != plate) continue;
    const double r = std::hypot(p.pos[i].x, p.pos[i].y);
    if (r > 9e-3 && r < 11.5e-3) { p.damage[i] = 1; ++failed; }
    if (r > 15e-3 && r < 17.5e-3) { p.damage[i] = 0.4; ++damaged; }
  }
  ASSERT_GT(failed, 20u);
  ASSERT_GT(damaged, 20u);
  disturb(p, dx, 5.0, 2e-3, 80e6);
  expect_same_step(s, "plate-8mm at 2 mm");
}

// Penalty contact reaching beyond the kernel support: particles of the two bodies touch at 3 spacings, the
// support is 2.4 (h = 1.2 dx), so the contact pairs between 2.4 and 3 spacings are taken only because the
// prefilter keeps every penalty pair whatever its distance.
TEST(ReferencePassLoops, ContactBeyondTheKernelSupportAsTheUnfilteredLoops) {
  CaseSpec spec = load_case_file(std::string(IMPACTSPH_CASES) + "/plate-8mm/case.toml",
                                 {"projectile.velocity=190.7 m/s"}, "2 mm");
  ASSERT_EQ(spec.contacts.size(), 1u);
  spec.contacts[0].contact_distance = 3.0;
  Scene s = build_scene(spec);
  disturb(s.particles, 2e-3, 5.0, 2e-3, 80e6);
  expect_same_step(s, "plate-8mm at 2 mm, contact at 3 spacings");
}

// The ceramics physics of paper X (JH-2 damage and bulking, SRAD penalty contact, variable smoothing
// length), with partly damaged ceramic.
TEST(ReferencePassLoops, CeramicsWithSradContactAndVariableHAsTheUnfilteredLoops) {
  Scene s = build_scene(load_case_file(std::string(IMPACTSPH_VERIFICATION_DATA) + "/ceramics.toml", {}, ""));
  ParticleSet& p = s.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (i % 3 == 0) p.damage[i] = 0.25 + 0.5 * static_cast<double>(i % 7) / 7;
  disturb(p, 1e-3, 3.0, 1e-3, 50e6);
  expect_same_step(s, "ceramics");
}

// An elastic bar on a rigid wall: its lowest particles on one side (x > 0.75 mm) in tension and moving off the
// wall let go of it (no pairs with the images behind it, no images of their own), the rest press on it, so
// that rows that let go have the images of particles that do not within their support.
TEST(ReferencePassLoops, WallLetGoAsTheUnfilteredLoops) {
  Scene s = build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/wall-rebound/case.toml", {}, ""));
  ParticleSet& p = s.particles;
  std::size_t letting_go = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.pos[i].z < 1.2e-3 && p.pos[i].x > 0.75e-3) {
      p.rho[i] *= 0.999;                          // in tension: P < 0
      p.dev_stress[i] = Sym3d{-50e6, -50e6, 100e6, 0, 0, 0};  // S_zz - P > 0
      p.vel[i].z = 2.0;                            // moving off the wall (the model lies at z > 0)
      ++letting_go;
    }
  }
  ASSERT_GT(letting_go, 5u);
  disturb(p, 0.5e-3, 0.5, 0.0, 0.0);
  expect_same_step(s, "wall-rebound");
}

// The copper Taylor bar at 0.8 mm on its rigid wall (h = 2 dx, the limited viscosity: the midpoint jump with
// van Leer's limiter, faded within one spacing): the pairs of nearest neighbours, disturbed by up to 5 % of
// the spacing, lie on both sides of the close-approach radius.
TEST(ReferencePassLoops, TaylorBarWithTheLimitedViscosityAsTheUnfilteredLoops) {
  Scene s = build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/taylor-bar/case.toml", {}, "0.8 mm"));
  ASSERT_TRUE(s.spec.numerics.viscosity.limited);
  disturb(s.particles, 0.8e-3, 20.0, 2e-3, 30e6);
  expect_same_step(s, "taylor-bar at 0.8 mm");
}

}  // namespace
}  // namespace impactsph
