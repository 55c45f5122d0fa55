// Scene builder (common/scene.hpp): lattice counts, positions and masses for boxes, cylinders, spheres and
// noses, clipping at symmetry planes, and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/case_file.hpp"
#include "common/case_observables.hpp"
#include "common/errors.hpp"
#include "common/scene.hpp"


#include "tests/scene_fixture.hpp"

using namespace impactsph;
using namespace impactsph::scene_test;

TEST(Scene, BoxLatticeCountMassAndOrder) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("bar", {0, 0, 0}, {10 * dx, 4 * dx, 4 * dx}));
  s.bodies[0].velocity = {1, 2, 3};
  const Scene scene = build_scene(s);
  const ParticleSet& p = scene.particles;
  ASSERT_EQ(p.size(), 160u);  // 10 x 4 x 4
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_EQ(scene.bodies[0].name, "bar");
  EXPECT_EQ(scene.bodies[0].material, 0);
  EXPECT_EQ(scene.bodies[0].particle_count, 160u);
  const double volume = 10 * dx * 4 * dx * 4 * dx;
  EXPECT_NEAR(scene.bodies[0].initial_mass, kRho * volume, 1e-12 * kRho * volume);
  double total = 0;
  for (std::size_t i = 0; i < p.size(); ++i) total += p.mass[i];
  EXPECT_NEAR(total, kRho * volume, 1e-12 * kRho * volume);

  // Lattice order: x fastest, then y, then z; points at min + (i + 1/2) dx.
  expect_near_vec(p.pos[0], {0.5 * dx, 0.5 * dx, 0.5 * dx}, 1e-15);
  expect_near_vec(p.pos[1], {1.5 * dx, 0.5 * dx, 0.5 * dx}, 1e-15);
  expect_near_vec(p.pos[10], {0.5 * dx, 1.5 * dx, 0.5 * dx}, 1e-15);
  expect_near_vec(p.pos[40], {0.5 * dx, 0.5 * dx, 1.5 * dx}, 1e-15);
  expect_near_vec(p.pos[159], {9.5 * dx, 3.5 * dx, 3.5 * dx}, 1e-15);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_DOUBLE_EQ(p.rho[i], kRho);
    EXPECT_DOUBLE_EQ(p.h[i], 1.2 * dx);
    EXPECT_DOUBLE_EQ(p.energy[i], 0);
    EXPECT_DOUBLE_EQ(p.vel[i].z, 3);
    EXPECT_EQ(p.body[i], 0);
    EXPECT_EQ(p.material[i], 0);
    EXPECT_EQ(p.fixed[i], 0);
    EXPECT_DOUBLE_EQ(p.dev_stress[i].xy, 0);
  }
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_DOUBLE_EQ(scene.materials[0].eos.rho0, kRho);
}

TEST(Scene, BoxExtentNotAMultipleIsStretched) {
  // 10.5 spacings: round(10.5) = 11 cells (a tie takes the finer lattice) of 10.5/11 dx, the outermost
  // ending on the faces; the mass is rho0 V.
  const double dx = 1e-3, w = 10.5 / 11 * dx;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("bar", {0, 0, 0}, {10.5 * dx, 2 * dx, 2 * dx}));
  const Scene scene = build_scene(s);
  ASSERT_EQ(scene.particles.size(), 44u);
  EXPECT_NEAR(scene.particles.pos[0].x, 0.5 * w, 1e-15);
  EXPECT_NEAR(scene.particles.pos[10].x, 10.5 * dx - 0.5 * w, 1e-15);
  EXPECT_NEAR(scene.particles.mass[0], kRho * w * dx * dx, 1e-18);
  EXPECT_NEAR(scene.bodies[0].initial_mass, kRho * 10.5 * dx * 2 * dx * 2 * dx, 1e-15);
  EXPECT_NEAR(scene.bodies[0].lattice_spacing.x, w, 1e-15);
  EXPECT_NEAR(scene.bodies[0].max_stretch, 0.5 / 11, 1e-12);
  EXPECT_TRUE(scene.bodies[0].warnings.empty());
  // 10.4 spacings: 10 cells of 1.04 dx, stretched by 4 %.
  s.bodies[0].box_max.x = 10.4 * dx;
  const Scene stretched = build_scene(s);
  EXPECT_EQ(stretched.particles.size(), 40u);
  EXPECT_NEAR(stretched.bodies[0].lattice_spacing.x, 1.04 * dx, 1e-15);
}

TEST(Scene, SmallCylinderCount) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(cylinder("rod", {0, 0, 0}, 2, 2 * dx, 5 * dx));
  const Scene scene = build_scene(s);
  // Offsets +-0.5 and +-1.5 ds with u^2 + v^2 <= 4 dx^2: 12 per layer, 5 layers; ds fitted so that the
  // 12 cells hold the circle, 12 ds^2 = pi (2 dx)^2: ds = 1.0233 dx (that lattice still holds 12 points:
  // 1.5^2 + 1.5^2 = 4.5 > 4 / 1.0233^2).
  const double ds = std::sqrt(Constants<double>::pi * 4 / 12) * dx;
  ASSERT_EQ(scene.particles.size(), 60u);
  EXPECT_NEAR(scene.bodies[0].lattice_spacing.x, ds, 1e-15);
  EXPECT_NEAR(scene.bodies[0].lattice_spacing.z, dx, 1e-15);
  EXPECT_NEAR(scene.bodies[0].initial_mass, kRho * Constants<double>::pi * 4 * dx * dx * 5 * dx, 1e-15);
  EXPECT_NEAR(scene.bodies[0].mass_scale, 1, 1e-12);
  expect_near_vec(scene.particles.pos[0], {-0.5 * ds, -1.5 * ds, 0.5 * dx}, 1e-15);
  for (const Vec3d& q : scene.particles.pos) {
    EXPECT_LE(q.x * q.x + q.y * q.y, 4 * dx * dx * (1 + 1e-12));
    EXPECT_GT(q.z, 0);
    EXPECT_LT(q.z, 5 * dx);
  }
}

TEST(Scene, LargeCylinderMassIsRhoV) {
  const double dx = 0.5e-3, r = 20 * dx, len = 4 * dx;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(cylinder("disk", {0, 0, 0}, 2, r, len));
  const Scene scene = build_scene(s);
  const double exact = kRho * Constants<double>::pi * r * r * len;
  EXPECT_NEAR(scene.bodies[0].initial_mass, exact, 1e-12 * exact);
  EXPECT_EQ(scene.particles.size() % 4, 0u);  // four layers of the same cross-section
  // Each particle's mass is rho0 times its cell, ds^2 dz: the lattice fits, nothing is scaled.
  const Vec3d& cell = scene.bodies[0].lattice_spacing;
  EXPECT_NEAR(scene.particles.mass[0], kRho * cell.x * cell.y * cell.z, 1e-12 * scene.particles.mass[0]);
  EXPECT_LT(scene.bodies[0].max_stretch, 0.1);
}

TEST(Scene, CylinderAlongX) {
  const double dx = 1e-3, r = 3 * dx, len = 6 * dx;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(cylinder("rod", {1e-3, 2e-3, 3e-3}, 0, r, len));
  const Scene scene = build_scene(s);
  ASSERT_GT(scene.particles.size(), 0u);
  EXPECT_NEAR(scene.particles.pos[0].x, 1e-3 + 0.5 * dx, 1e-15);
  for (const Vec3d& q : scene.particles.pos) {
    EXPECT_GT(q.x, 1e-3);
    EXPECT_LT(q.x, 1e-3 + len);
    EXPECT_LE(std::pow(q.y - 2e-3, 2) + std::pow(q.z - 3e-3, 2), r * r * (1 + 1e-9));
  }
}

TEST(Scene, SmallSphereCountAndOrder) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  // r = dx, the smallest sphere: the 8 points (+-1/2, +-1/2, +-1/2) dx, x fastest, then y, then z. Their
  // cells would hold the ball at s = 0.806 dx, outside the +-10 % the fit allows: dx is kept and the
  // masses scaled to rho0 V, with a warning.
  s.bodies.push_back(sphere("ball", {1e-3, 2e-3, 3e-3}, dx));
  Scene scene = build_scene(s);
  ASSERT_EQ(scene.particles.size(), 8u);
  EXPECT_NEAR(scene.bodies[0].mass_scale, Constants<double>::pi / 6, 1e-12);
  EXPECT_NEAR(scene.bodies[0].initial_mass, kRho * 4.0 / 3.0 * Constants<double>::pi * dx * dx * dx, 1e-15);
  EXPECT_TRUE(AnyContains(scene.bodies[0].warnings, "no round lattice within 10 % of the spacing holds exactly its volume"));
  expect_near_vec(scene.particles.pos[0], {0.5e-3, 1.5e-3, 2.5e-3}, 1e-15);
  expect_near_vec(scene.particles.pos[1], {1.5e-3, 1.5e-3, 2.5e-3}, 1e-15);
  expect_near_vec(scene.particles.pos[2], {0.5e-3, 2.5e-3, 2.5e-3}, 1e-15);
  expect_near_vec(scene.particles.pos[4], {0.5e-3, 1.5e-3, 3.5e-3}, 1e-15);
  // r = 2 dx: offsets (i + 1/2) s with |o|^2 <= 4 dx^2: the 8 of (1/2, 1/2, 1/2) and the 24 of
  // (1/2, 1/2, 3/2) and its permutations (|o|^2 = 2.75 s^2); (1/2, 3/2, 3/2) is at 4.75 s^2. The 32 cells
  // hold the ball at 32 s^3 = (4/3) pi (2 dx)^3, s = 1.0155 dx.
  s.bodies[0] = sphere("ball", {0, 0, 0}, 2 * dx);
  scene = build_scene(s);
  ASSERT_EQ(scene.particles.size(), 32u);
  EXPECT_NEAR(scene.bodies[0].lattice_spacing.x, std::cbrt(4.0 / 3.0 * Constants<double>::pi * 8 / 32) * dx, 1e-15);
  EXPECT_NEAR(scene.bodies[0].initial_mass, kRho * 4.0 / 3.0 * Constants<double>::pi * 8 * dx * dx * dx, 1e-15);
  EXPECT_TRUE(scene.bodies[0].warnings.empty());
  for (const Vec3d& q : scene.particles.pos) EXPECT_LE(norm2(q), 4 * dx * dx * (1 + 1e-12));
}

TEST(Scene, SphereMassIsRhoVAtEverySpacing) {
  // With dx kept, the particle count times dx^3 misses (4/3) pi r^3 by the surface cells (+1.46 % at
  // r = 8 dx, -5.8 % at 3.4 dx); the fitted lattice's cells hold the ball exactly.
  const double r = 4e-3;
  const Vec3d c{1e-3, -2e-3, 3e-3};
  for (const double n : {3.4, 8.0, 16.0, 32.0}) {
    SCOPED_TRACE(n);
    const double dx = r / n;
    CaseSpec s = spec_with_spacing(dx);
    s.bodies.push_back(sphere("ball", c, r));
    const Scene scene = build_scene(s);
    const double volume = 4.0 / 3.0 * Constants<double>::pi * r * r * r;
    // 1e-9: the sum over up to 137 000 particles rounds.
    EXPECT_NEAR(scene.bodies[0].initial_mass, kRho * volume, 1e-9 * kRho * volume);
    EXPECT_NEAR(scene.bodies[0].mass_scale, 1, 1e-9);  // fitted, not scaled
    const double cell = scene.bodies[0].lattice_spacing.x;
    EXPECT_NEAR(double(scene.particles.size()) * cell * cell * cell, volume, 1e-9 * volume);
    for (const Vec3d& q : scene.particles.pos) EXPECT_LE(norm(q - c), r * (1 + 1e-9));
  }
}

// Issue 20: the body the solver sees is the body the case gives, whether or not the spacing divides its
// sizes. At spacings that do (1 mm, 0.5 mm for the whole-millimetre sizes below) and do not (0.9, 0.7,
// 0.43 mm), for each primitive: the mass is rho0 V (the issue asks 0.1 %; the lattice gives it to
// rounding), the sizes as generated are those specified, the centre of mass is the shape's centre, the
// outermost particle centres lie half a cell inside the faces, and the cells are within 5 % of dx (no
// warning; a body only a few spacings across may need more, and is warned of).
TEST(Scene, PrimitivesAsSpecifiedAtAnySpacing) {
  const double mm = 1e-3;
  struct Primitive {
    BodySpec body;
    Vec3d centre;
  };
  BodySpec block = box("block", {-3 * mm, 1 * mm, 0}, {7 * mm, 9 * mm, 6 * mm});
  BodySpec rod = cylinder("rod", {1 * mm, 2 * mm, 3 * mm}, 0, 10 * mm, 80 * mm);  // the plate projectile, along x
  BodySpec plate = cylinder("plate", {0, 0, -8 * mm}, 2, 30 * mm, 8 * mm);
  BodySpec ball = sphere("ball", {1 * mm, -2 * mm, 3 * mm}, 3.435 * mm);
  const Primitive primitives[] = {{block, {2 * mm, 5 * mm, 3 * mm}},
                                  {rod, {41 * mm, 2 * mm, 3 * mm}},
                                  {plate, {0, 0, -4 * mm}},
                                  {ball, ball.center}};
  for (const double dx : {1 * mm, 0.9 * mm, 0.7 * mm, 0.5 * mm, 0.43 * mm}) {
    for (const Primitive& prim : primitives) {
      SCOPED_TRACE(prim.body.name + " at " + std::to_string(dx / mm) + " mm");
      CaseSpec s = spec_with_spacing(dx);
      s.bodies.push_back(prim.body);
      const Scene scene = build_scene(s);
      const BodyInfo& info = scene.bodies[0];
      const ParticleSet& p = scene.particles;
      const BodySpec& b = prim.body;
      double volume = 0;
      if (b.shape == Shape::Box) volume = (b.box_max.x - b.box_min.x) * (b.box_max.y - b.box_min.y) * (b.box_max.z - b.box_min.z);
      else if (b.shape == Shape::Cylinder) volume = Constants<double>::pi * b.radius * b.radius * b.length;
      else volume = 4.0 / 3.0 * Constants<double>::pi * b.radius * b.radius * b.radius;

      double mass = 0;
      Vec3d moment{0, 0, 0};
      for (std::size_t i = 0; i < p.size(); ++i) {
        mass += p.mass[i];
        moment += p.mass[i] * p.pos[i];
      }
      EXPECT_NEAR(mass, kRho * volume, 1e-9 * kRho * volume);
      EXPECT_NEAR(info.specified_mass, kRho * volume, 1e-12 * kRho * volume);
      EXPECT_NEAR(info.generated_mass, kRho * volume, 1e-9 * kRho * volume);
      EXPECT_NEAR(info.mass_scale, 1, 1e-9);  // the lattice fits: masses are rho0 x cell, not scaled
      expect_near_vec(moment * (1 / mass), prim.centre, 1e-9 * mm);
      for (const BodySize& size : info.sizes) {
        SCOPED_TRACE(size.name);
        EXPECT_NEAR(size.generated, size.specified, 1e-9 * size.specified);
      }
      EXPECT_TRUE(info.warnings.empty());
      EXPECT_LE(info.max_stretch, 0.05);

      // Outermost centres: half a cell inside each face (box, cylinder length); within one cross-section
      // spacing inside the round surface.
      Vec3d lo{1, 1, 1}, hi{-1, -1, -1};
      double r_max = 0;
      for (const Vec3d& q : p.pos) {
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], q[a]), hi[a] = std::max(hi[a], q[a]);
        if (b.shape == Shape::Cylinder) {
          const int u = (b.axis + 1) % 3, v = (b.axis + 2) % 3;
          r_max = std::max(r_max, std::hypot(q[u] - b.base[u], q[v] - b.base[v]));
        } else if (b.shape == Shape::Sphere) {
          r_max = std::max(r_max, norm(q - b.center));
        }
      }
      const Vec3d& cell = info.lattice_spacing;
      if (b.shape == Shape::Box) {
        for (int a = 0; a < 3; ++a) {
          EXPECT_NEAR(lo[a], b.box_min[a] + 0.5 * cell[a], 1e-12);
          EXPECT_NEAR(hi[a], b.box_max[a] - 0.5 * cell[a], 1e-12);
        }
      } else if (b.shape == Shape::Cylinder) {
        EXPECT_NEAR(lo[b.axis], b.base[b.axis] + 0.5 * cell[b.axis], 1e-12);
        EXPECT_NEAR(hi[b.axis], b.base[b.axis] + b.length - 0.5 * cell[b.axis], 1e-12);
        const double ds = cell[(b.axis + 1) % 3];
        EXPECT_LE(r_max, b.radius * (1 + 1e-9));
        EXPECT_GE(r_max, b.radius - ds);
      } else {
        EXPECT_LE(r_max, b.radius * (1 + 1e-9));
        EXPECT_GE(r_max, b.radius - cell.x);
      }
    }
  }
}

TEST(Scene, QuarterAndEighthSphere) {
  // Planes through the centre lie halfway between lattice layers (offsets (i + 1/2) dx), as for a
  // cylinder: two planes keep exactly a quarter of the particles, three an eighth, and the layer next to
  // each plane is dx/2 from it.
  const double dx = 0.5e-3, r = 3.435e-3;
  const Vec3d c{1e-3, -2e-3, 3.5e-3};
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(sphere("ball", c, r));
  const Scene whole = build_scene(s);
  const double ds = whole.bodies[0].lattice_spacing.x;  // the fitted lattice's spacing
  s.symmetry.push_back({0, c.x});
  s.symmetry.push_back({1, c.y});
  const Scene quarter = build_scene(s);
  EXPECT_EQ(quarter.particles.size() * 4, whole.particles.size());
  EXPECT_EQ(quarter.bodies[0].particle_count * 4, whole.bodies[0].particle_count);
  EXPECT_NEAR(quarter.bodies[0].initial_mass * 4, whole.bodies[0].initial_mass, 1e-12 * whole.bodies[0].initial_mass);
  const double eps = 1e-9 * dx;
  double dmin[3] = {1, 1, 1};
  for (const Vec3d& q : quarter.particles.pos)
    for (int a = 0; a < 2; ++a) {
      EXPECT_GT(q[a] - c[a], 0.5 * ds - eps);  // centred on the planes: the positive side, on the tie
      dmin[a] = std::min(dmin[a], q[a] - c[a]);
    }
  EXPECT_NEAR(dmin[0], 0.5 * ds, eps);
  EXPECT_NEAR(dmin[1], 0.5 * ds, eps);
  // The whole body as generated, mirrored back from the quarter, is the ball.
  EXPECT_NEAR(quarter.bodies[0].generated_mass, quarter.bodies[0].specified_mass, 1e-12 * quarter.bodies[0].specified_mass);
  EXPECT_NEAR(quarter.bodies[0].sizes[0].generated, 2 * r, 1e-12 * r);

  // Whole-body masses (case observables) count the sphere 4 times: it reaches across both planes.
  EXPECT_EQ(symmetry_multiplicity(s, 0), 4);

  // A third plane through the centre, on the side that a plate below the sphere decides: an eighth.
  s.bodies.push_back(box("plate", {c.x, c.y, -5e-3}, {c.x + 8e-3, c.y + 8e-3, -3e-3}));
  s.symmetry.push_back({2, c.z});
  const Scene eighth = build_scene(s);
  EXPECT_EQ(eighth.bodies[0].particle_count * 8, whole.particles.size());
  for (std::size_t i = 0; i < eighth.bodies[0].particle_count; ++i) {
    EXPECT_LT(eighth.particles.pos[i].z, c.z - 0.5 * ds + eps);
  }
  EXPECT_EQ(symmetry_multiplicity(s, 0), 8);
  EXPECT_EQ(symmetry_multiplicity(s, 1), 1);  // the plate lies on one side of every plane
}

TEST(Scene, BuildIsDeterministic) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("a", {0, 0, 0}, {5 * dx, 5 * dx, 2 * dx}));
  s.bodies.push_back(cylinder("b", {2.5 * dx, 2.5 * dx, 2 * dx}, 2, 2 * dx, 3 * dx));
  const Scene one = build_scene(s), two = build_scene(s);
  ASSERT_EQ(one.particles.size(), two.particles.size());
  for (std::size_t i = 0; i < one.particles.size(); ++i) {
    EXPECT_EQ(one.particles.pos[i].x, two.particles.pos[i].x);
    EXPECT_EQ(one.particles.pos[i].z, two.particles.pos[i].z);
    EXPECT_EQ(one.particles.body[i], two.particles.body[i]);
  }
  // Bodies in file order: all particles of "a" first.
  EXPECT_EQ(one.particles.body[0], 0);
  EXPECT_EQ(one.particles.body[one.bodies[0].particle_count], 1);
  EXPECT_EQ(one.particles.body.back(), 1);
}

TEST(Scene, BodyAcrossAPlaneIsClipped) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.symmetry.push_back({1, 0.0});
  s.bodies.push_back(box("whole", {0, -2 * dx, 0}, {4 * dx, 2 * dx, 4 * dx}));
  Scene scene = build_scene(s);
  ASSERT_EQ(scene.particles.size(), 32u);  // half of 4 x 4 x 4
  EXPECT_EQ(scene.bodies[0].particle_count, 32u);
  EXPECT_NEAR(scene.bodies[0].initial_mass, 32 * kRho * dx * dx * dx, 1e-15);
  for (const Vec3d& q : scene.particles.pos) EXPECT_GT(q.y, 0);  // centred on the plane: the positive side
  // Lattice order is kept: the first particle is the first of the whole box with y > 0.
  expect_near_vec(scene.particles.pos[0], {0.5 * dx, 0.5 * dx, 0.5 * dx}, 1e-15);
  expect_near_vec(scene.particles.pos[4], {0.5 * dx, 1.5 * dx, 0.5 * dx}, 1e-15);

  // Most of the body below the plane: the negative side.
  s.bodies[0] = box("low", {0, -6 * dx, 0}, {4 * dx, 2 * dx, 4 * dx});
  scene = build_scene(s);
  EXPECT_EQ(scene.particles.size(), 96u);
  for (const Vec3d& q : scene.particles.pos) EXPECT_LT(q.y, 0);

  // A body wholly on one side decides, even against the majority of a body across the plane.
  s.bodies.push_back(box("above", {5 * dx, 0, 0}, {9 * dx, 2 * dx, 4 * dx}));
  scene = build_scene(s);
  EXPECT_EQ(scene.bodies[0].particle_count, 32u);
  EXPECT_EQ(scene.bodies[1].particle_count, 32u);
  for (const Vec3d& q : scene.particles.pos) EXPECT_GT(q.y, 0);
}

TEST(Scene, QuarterCylinder) {
  const double dx = 0.5e-3, r = 10e-3, len = 4e-3;
  for (int axis = 0; axis < 3; ++axis) {
    SCOPED_TRACE(axis);
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const Vec3d base{1e-3, -2e-3, 3e-3};
    CaseSpec s = spec_with_spacing(dx);
    s.bodies.push_back(cylinder("rod", base, axis, r, len));
    const Scene whole = build_scene(s);
    const double ds = whole.bodies[0].lattice_spacing[u];  // the fitted cross-section spacing
    s.symmetry.push_back({u, base[u]});
    s.symmetry.push_back({v, base[v]});
    const Scene quarter = build_scene(s);
    ASSERT_GT(whole.particles.size(), 0u);
    EXPECT_EQ(whole.particles.size() % 4, 0u);
    EXPECT_EQ(quarter.particles.size() * 4, whole.particles.size());
    EXPECT_EQ(quarter.bodies[0].particle_count * 4, whole.bodies[0].particle_count);
    EXPECT_NEAR(quarter.bodies[0].initial_mass * 4, whole.bodies[0].initial_mass, 1e-12 * whole.bodies[0].initial_mass);
    const double eps = 1e-9 * dx;
    double du_min = 1, dv_min = 1;
    for (const Vec3d& q : quarter.particles.pos) {
      const double du = q[u] - base[u], dv = q[v] - base[v];
      EXPECT_GT(du, 0.5 * ds - eps);  // no particle within ds/2 - eps of a plane, every one on the + side
      EXPECT_GT(dv, 0.5 * ds - eps);
      du_min = std::min(du_min, du);
      dv_min = std::min(dv_min, dv);
    }
    EXPECT_NEAR(du_min, 0.5 * ds, eps);  // the layer next to each plane is ds/2 from it
    EXPECT_NEAR(dv_min, 0.5 * ds, eps);
    EXPECT_NEAR(quarter.bodies[0].generated_mass, quarter.bodies[0].specified_mass, 1e-12 * quarter.bodies[0].specified_mass);
  }
}

TEST(Scene, HalfCylinderOnTheNegativeSide) {
  // A plate wholly below z = 0 decides the side of the plane for a cylinder lying across it.
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(cylinder("rod", {0, 0, -3 * dx}, 0, 3 * dx, 6 * dx));  // along x, axis in z = -3 dx
  s.bodies.push_back(box("plate", {0, -10 * dx, -20 * dx}, {6 * dx, 10 * dx, -10 * dx}));
  const std::size_t whole = build_scene(s).bodies[0].particle_count;
  s.symmetry.push_back({2, -3 * dx});
  const Scene half = build_scene(s);
  EXPECT_EQ(half.bodies[0].particle_count * 2, whole);
  for (std::size_t i = 0; i < half.particles.size(); ++i) EXPECT_LT(half.particles.pos[i].z, -3.4 * dx);
}

TEST(Scene, TwoSymmetryPlanesBoundAChannel) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.symmetry.push_back({1, 0.0});
  s.symmetry.push_back({1, 3 * dx});
  s.bodies.push_back(box("bar", {0, 0, 0}, {10 * dx, 3 * dx, 3 * dx}));
  EXPECT_EQ(build_scene(s).particles.size(), 90u);
}

namespace {

// The nose profile written out here on its own (not the scene builder's): radius at the distance t from
// the base of a cylinder of radius r, length len, nose of length ln at the base or the top.
double profile_radius(const BodySpec& b, double t) {
  const double x = b.nose_at_base ? b.nose_length - t : t - (b.length - b.nose_length);
  if (x <= 0) return b.radius;
  if (x >= b.nose_length) return 0;
  switch (b.nose) {
    case Nose::Hemispherical: return std::sqrt(b.radius * b.radius - x * x);
    case Nose::Conical: return b.radius * (1 - x / b.nose_length);
    case Nose::Ogival: {
      const double s = 2 * b.nose_crh * b.radius;
      return std::sqrt(s * s - x * x) - (s - b.radius);
    }
    default: return b.radius;
  }
}

BodySpec nosed(const std::string& name, Nose nose, bool at_base, double nose_length, double crh) {
  const double mm = 1e-3;
  BodySpec b = cylinder(name, {0, 0, 0}, 2, 10 * mm, 80 * mm);
  b.nose = nose;
  b.nose_at_base = at_base;
  b.nose_length = nose_length;
  b.nose_crh = crh;
  return b;
}

}  // namespace

// Issue 17: a cylinder with a hemispherical, conical or ogival nose holds the closed-form mass and centre
// of mass at 16 particles across its diameter (the issue asks 0.5 %). Volume and centre are integrated
// here by Simpson's rule over the profile (for the hemisphere and the cone also checked against 2/3 pi R^3
// and pi R^2 L / 3); the lattice's cells before the mass scale must hold the volume within 0.5 %, the
// masses then give rho0 V, the centre lies on the axis and its distance from the base is within 0.5 % of
// the closed form; every particle lies within the profile. The same with the two symmetry planes of a
// quarter model.
TEST(Scene, NosesHoldTheirClosedFormMassAndCentre) {
  const double mm = 1e-3, pi = Constants<double>::pi, r = 10 * mm;
  const BodySpec noses[] = {
      nosed("hemispherical", Nose::Hemispherical, true, r, 0),
      nosed("conical", Nose::Conical, false, 20 * mm, 0),
      nosed("ogival-3", Nose::Ogival, true, r * std::sqrt(11.0), 3),
      nosed("ogival-1.5", Nose::Ogival, false, r * std::sqrt(5.0), 1.5),
  };
  for (const bool quarter : {false, true})
    for (const BodySpec& b : noses) {
      SCOPED_TRACE(b.name + (quarter ? " (quarter)" : ""));
      const int steps = 200000;  // Simpson's rule, error far below the tolerance
      double volume = 0, moment = 0;
      for (int i = 0; i <= steps; ++i) {
        const double t = b.length * i / steps;
        const double w = (i == 0 || i == steps) ? 1 : (i % 2 ? 4 : 2);
        const double rt = profile_radius(b, t), area = pi * rt * rt;
        volume += w * area;
        moment += w * area * t;
      }
      volume *= b.length / (3.0 * steps);
      moment *= b.length / (3.0 * steps);
      const double centre = moment / volume;  // m from the base
      if (b.nose == Nose::Hemispherical) {
        EXPECT_NEAR(volume, pi * r * r * (b.length - r) + 2.0 / 3.0 * pi * r * r * r, 1e-7 * volume);
      }
      if (b.nose == Nose::Conical) {
        EXPECT_NEAR(volume, pi * r * r * (b.length - b.nose_length) + pi * r * r * b.nose_length / 3, 1e-7 * volume);
      }

      CaseSpec s = spec_with_spacing(2 * r / 16);
      s.bodies.push_back(b);
      if (quarter) {
        s.symmetry.push_back({0, 0.0});
        s.symmetry.push_back({1, 0.0});
      }
      const Scene scene = build_scene(s);
      const BodyInfo& info = scene.bodies[0];
      const ParticleSet& p = scene.particles;
      EXPECT_NEAR(info.specified_mass, kRho * volume, 1e-6 * kRho * volume);
      EXPECT_NEAR(info.generated_mass, kRho * volume, 1e-9 * kRho * volume);
      // Cells against the closed-form volume: the mass scale is what the lattice missed.
      EXPECT_NEAR(1 / info.mass_scale, 1, 0.005);
      double mass = 0;
      Vec3d first{0, 0, 0};
      for (std::size_t i = 0; i < p.size(); ++i) {
        mass += p.mass[i];
        first += p.mass[i] * p.pos[i];
        const double t = p.pos[i].z - b.base.z;
        EXPECT_LE(std::hypot(p.pos[i].x, p.pos[i].y), profile_radius(b, t) * (1 + 1e-9) + 1e-15);
      }
      const Vec3d cm = first * (1 / mass);
      if (!quarter) {
        EXPECT_NEAR(cm.x, 0, 1e-9 * mm);
        EXPECT_NEAR(cm.y, 0, 1e-9 * mm);
      }
      EXPECT_NEAR(cm.z - b.base.z, centre, 0.005 * centre);
      // Its sizes: the length to within half a spacing (a sharp tip's last layers may hold no point; a
      // warning says so), the shank's diameter exact.
      for (const BodySize& size : info.sizes) {
        SCOPED_TRACE(size.name);
        if (size.name == "diameter") {
          EXPECT_NEAR(size.generated, 2 * r, 1e-9 * r);
        }
        if (size.name == "length") {
          EXPECT_LE(size.generated, b.length * (1 + 1e-12));
        }
      }
    }
}

// A nose whose lattice misses its volume by more than 1 % (a nose a few spacings long) is warned of, and
// the warning says by how much the masses were scaled.
TEST(Scene, CoarseNoseIsWarnedOf) {
  const double mm = 1e-3;
  BodySpec b = nosed("cone", Nose::Conical, true, 20 * mm, 0);
  CaseSpec s = spec_with_spacing(5 * mm);  // 4 particles across
  s.bodies.push_back(b);
  const Scene scene = build_scene(s);
  EXPECT_TRUE(AnyContains(scene.bodies[0].warnings, "of its volume with the nose; its particle masses are scaled by"));
  EXPECT_NEAR(scene.bodies[0].generated_mass, scene.bodies[0].specified_mass, 1e-9 * scene.bodies[0].specified_mass);
}
