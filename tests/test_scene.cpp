// Scene builder (common/scene.hpp): lattice counts, positions and masses for boxes and cylinders, and
// the geometry errors (thin bodies, overlaps, symmetry planes, fixed regions that select nothing).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/case_file.hpp"
#include "common/errors.hpp"
#include "common/scene.hpp"

using namespace impactsph;

namespace {

constexpr double kRho = 7850;

CaseSpec spec_with_spacing(double dx) {
  CaseSpec s;
  s.source_file = "scene.toml";
  s.name = "scene-test";
  MaterialSpec steel;
  steel.name = "steel";
  steel.params.eos.rho0 = kRho;
  steel.params.eos.k1 = 160e9;
  s.materials.push_back(steel);
  s.numerics.spacing = dx;
  s.time.end = 1e-5;
  s.time.output_interval = 1e-6;
  return s;
}

BodySpec box(const std::string& name, Vec3d lo, Vec3d hi) {
  BodySpec b;
  b.name = name;
  b.material = "steel";
  b.material_index = 0;
  b.shape = Shape::Box;
  b.box_min = lo;
  b.box_max = hi;
  return b;
}

BodySpec cylinder(const std::string& name, Vec3d base, int axis, double radius, double length) {
  BodySpec b;
  b.name = name;
  b.material = "steel";
  b.material_index = 0;
  b.shape = Shape::Cylinder;
  b.base = base;
  b.axis = axis;
  b.radius = radius;
  b.length = length;
  return b;
}

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

CaseError scene_error(const CaseSpec& s) {
  try {
    build_scene(s);
  } catch (const CaseError& e) {
    EXPECT_EQ(e.file(), "scene.toml");
    return e;
  }
  ADD_FAILURE() << "the scene was accepted";
  return CaseError("", 0, "", "");
}

void expect_near_vec(Vec3d a, Vec3d b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace

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

TEST(Scene, BoxExtentNotAMultipleIsCentred) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("bar", {0, 0, 0}, {10.5 * dx, 2 * dx, 2 * dx}));
  const Scene scene = build_scene(s);
  ASSERT_EQ(scene.particles.size(), 40u);
  EXPECT_NEAR(scene.particles.pos[0].x, 0.75 * dx, 1e-15);
  EXPECT_NEAR(scene.particles.pos[9].x, 9.75 * dx, 1e-15);
}

TEST(Scene, SmallCylinderCount) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(cylinder("rod", {0, 0, 0}, 2, 2 * dx, 5 * dx));
  const Scene scene = build_scene(s);
  // Offsets +-0.5 and +-1.5 dx with u^2 + v^2 <= 4 dx^2: 12 per layer, 5 layers.
  ASSERT_EQ(scene.particles.size(), 60u);
  EXPECT_NEAR(scene.bodies[0].initial_mass, 60 * kRho * dx * dx * dx, 1e-15);
  expect_near_vec(scene.particles.pos[0], {-0.5 * dx, -1.5 * dx, 0.5 * dx}, 1e-15);
  for (const Vec3d& q : scene.particles.pos) {
    EXPECT_LE(q.x * q.x + q.y * q.y, 4 * dx * dx * (1 + 1e-12));
    EXPECT_GT(q.z, 0);
    EXPECT_LT(q.z, 5 * dx);
  }
}

TEST(Scene, LargeCylinderMassApproachesRhoV) {
  const double dx = 0.5e-3, r = 20 * dx, len = 4 * dx;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(cylinder("disk", {0, 0, 0}, 2, r, len));
  const Scene scene = build_scene(s);
  const double exact = kRho * Constants<double>::pi * r * r * len;
  EXPECT_NEAR(scene.bodies[0].initial_mass, exact, 0.01 * exact);
  EXPECT_EQ(scene.particles.size() % 4, 0u);  // four layers of the same cross-section
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

TEST(SceneErrors, BodyThinnerThanTwoParticles) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("foil", {0, 0, 0}, {10 * dx, 10 * dx, 1.5 * dx}));
  CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[0]");
  EXPECT_TRUE(Contains(e.what(), "thick along z"));
  EXPECT_TRUE(Contains(e.what(), "at least two particles"));

  s.bodies[0] = cylinder("wire", {0, 0, 0}, 2, 0.8 * dx, 10 * dx);
  e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[0]");
  EXPECT_TRUE(Contains(e.what(), "diameter of 1.6 mm"));

  s.bodies[0] = cylinder("coin", {0, 0, 0}, 2, 5 * dx, 1.5 * dx);
  e = scene_error(s);
  EXPECT_TRUE(Contains(e.what(), "1.5 mm long"));
}

TEST(SceneErrors, OverlappingBodies) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("plate", {0, 0, 0}, {10 * dx, 10 * dx, 4 * dx}));
  s.bodies.push_back(cylinder("projectile", {5 * dx, 5 * dx, 2 * dx}, 2, 2 * dx, 6 * dx));
  const CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[1]");
  EXPECT_TRUE(Contains(e.what(), "\"projectile\" overlaps bodies[0] (\"plate\")"));
}

TEST(SceneErrors, ParticlesCloserThanHalfASpacing) {
  // Two cylinders touching along a line: both lattices hold the point (1.5, 0.5) dx on the shared
  // surface, so neither particle is inside the other shape, but they coincide.
  const double dx = 1e-3, r = std::sqrt(2.5) * dx;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(cylinder("a", {0, 0, 0}, 2, r, 2 * dx));
  s.bodies.push_back(cylinder("b", {3 * dx, 1 * dx, 0}, 2, r, 2 * dx));
  const CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[1]");
  EXPECT_TRUE(Contains(e.what(), "closer than half the spacing"));
}

TEST(Scene, TouchingBodiesAreFine) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("a", {0, 0, 0}, {10 * dx, 4 * dx, 4 * dx}));
  s.bodies.push_back(box("b", {10 * dx, 0, 0}, {20 * dx, 4 * dx, 4 * dx}));
  s.bodies.push_back(cylinder("c", {5 * dx, 2 * dx, 4 * dx}, 2, 2 * dx, 3 * dx));
  const Scene scene = build_scene(s);
  EXPECT_EQ(scene.particles.size(), 160u + 160u + 36u);
  EXPECT_EQ(scene.bodies[2].particle_count, 36u);
}

TEST(SceneErrors, SymmetryPlanes) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.symmetry.push_back({1, 0.0});
  s.bodies.push_back(box("half", {0, 0, 0}, {4 * dx, 4 * dx, 4 * dx}));
  EXPECT_NO_THROW(build_scene(s));
  s.bodies[0] = box("below", {0, -4 * dx, 0}, {4 * dx, 0, 4 * dx});  // either side will do
  EXPECT_NO_THROW(build_scene(s));

  s.bodies[0] = box("whole", {0, -2 * dx, 0}, {4 * dx, 2 * dx, 4 * dx});
  CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[0]");
  EXPECT_TRUE(Contains(e.what(), "\"whole\" reaches across the symmetry plane y = 0 mm"));
  EXPECT_TRUE(Contains(e.what(), "boundaries.symmetry[0]"));

  s.bodies[0] = box("above", {0, 1 * dx, 0}, {4 * dx, 4 * dx, 4 * dx});
  s.bodies.push_back(box("below", {0, -4 * dx, 0}, {4 * dx, -1 * dx, 4 * dx}));
  e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[1]");
  EXPECT_TRUE(Contains(e.what(), "other side of the symmetry plane y = 0 mm (boundaries.symmetry[0]) from bodies[0]"));
}

TEST(Scene, TwoSymmetryPlanesBoundAChannel) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.symmetry.push_back({1, 0.0});
  s.symmetry.push_back({1, 3 * dx});
  s.bodies.push_back(box("bar", {0, 0, 0}, {10 * dx, 3 * dx, 3 * dx}));
  EXPECT_EQ(build_scene(s).particles.size(), 90u);
}

TEST(Scene, FixedBoxSelectsALayer) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("bar", {0, 0, 0}, {10 * dx, 4 * dx, 4 * dx}));
  FixedRegionSpec f;
  f.kind = FixedRegionSpec::Kind::Box;
  f.box_min = {-1, -1, -1};
  f.box_max = {1 * dx, 1, 1};
  s.fixed.push_back(f);
  const Scene scene = build_scene(s);
  std::size_t fixed = 0;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const bool first_layer = scene.particles.pos[i].x < dx;
    EXPECT_EQ(scene.particles.fixed[i], first_layer ? 1 : 0);
    fixed += scene.particles.fixed[i];
  }
  EXPECT_EQ(fixed, 16u);
}

TEST(Scene, FixedOutsideCylinderAndBodyRestriction) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(cylinder("plate", {0, 0, 0}, 2, 10 * dx, 2 * dx));
  s.bodies.push_back(cylinder("rod", {0, 0, 3 * dx}, 2, 12 * dx, 2 * dx));  // wider, so also outside 8 dx
  FixedRegionSpec f;
  f.kind = FixedRegionSpec::Kind::OutsideCylinder;
  f.axis = 2;
  f.axis_point = {0, 0, 0};
  f.radius = 8 * dx;
  f.body = "plate";
  s.fixed.push_back(f);
  const Scene scene = build_scene(s);
  const ParticleSet& p = scene.particles;
  std::size_t expected = 0, fixed = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool outside = p.pos[i].x * p.pos[i].x + p.pos[i].y * p.pos[i].y > 64 * dx * dx;
    const bool want = p.body[i] == 0 && outside;
    expected += want;
    fixed += p.fixed[i];
    EXPECT_EQ(p.fixed[i], want ? 1 : 0);
  }
  EXPECT_GT(expected, 0u);
  EXPECT_EQ(fixed, expected);
}

TEST(SceneErrors, FixedRegionThatSelectsNothing) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("bar", {0, 0, 0}, {10 * dx, 4 * dx, 4 * dx}));
  FixedRegionSpec f;
  f.box_min = {0.1, 0.1, 0.1};
  f.box_max = {0.2, 0.2, 0.2};
  s.fixed.push_back(f);
  CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "boundaries.fixed[0]");
  EXPECT_TRUE(Contains(e.what(), "selects no particle"));
  EXPECT_TRUE(Contains(e.what(), "which lie from (0.5 mm, 0.5 mm, 0.5 mm) to (9.5 mm, 3.5 mm, 3.5 mm)"));

  s.fixed[0].body = "nothing";
  e = scene_error(s);
  EXPECT_EQ(e.key(), "boundaries.fixed[0].body");
}

TEST(SceneErrors, MaterialsAndEmptyCases) {
  CaseSpec s = spec_with_spacing(1e-3);
  CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies");

  s.bodies.push_back(box("bar", {0, 0, 0}, {4e-3, 4e-3, 4e-3}));
  s.bodies[0].material_index = -1;  // resolved by name
  EXPECT_EQ(build_scene(s).particles.material[0], 0);
  s.bodies[0].material = "unobtainium";
  e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[0].material");

  s = spec_with_spacing(0);
  s.bodies.push_back(box("bar", {0, 0, 0}, {4e-3, 4e-3, 4e-3}));
  e = scene_error(s);
  EXPECT_EQ(e.key(), "numerics.spacing");
}

TEST(Scene, FromTheDocumentedExample) {
  // The example of docs/case-files.md at a coarse spacing, to stay fast.
  const CaseSpec spec =
      load_case_file(std::string(IMPACTSPH_TEST_DATA) + "/example_plate_impact.toml", {}, "2 mm");
  const Scene scene = build_scene(spec);
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.bodies[0].name, "plate");
  EXPECT_EQ(scene.bodies[1].name, "projectile");
  EXPECT_EQ(scene.bodies[1].material, 1);
  // 197 g projectile (F section 6): within the lattice's discretisation of the circle.
  EXPECT_NEAR(scene.bodies[1].initial_mass, 0.197, 0.197 * 0.05);
  std::size_t fixed = 0;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    fixed += scene.particles.fixed[i];
    if (scene.particles.fixed[i]) {
      EXPECT_EQ(scene.particles.body[i], 0);
    }
  }
  EXPECT_GT(fixed, 0u);
  EXPECT_DOUBLE_EQ(scene.particles.vel.back().z, -298);
  EXPECT_DOUBLE_EQ(scene.particles.h[0], 1.2 * 2e-3);
}
