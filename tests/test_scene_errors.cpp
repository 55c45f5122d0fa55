// Scene builder errors and checks (common/scene.hpp): thin bodies, overlaps, symmetry planes and walls,
// clipping, fixed regions, materials, contacts, and the lines errors name.
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

TEST(SceneErrors, SphereGeometry) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  // Thinner than two particles.
  s.bodies.push_back(sphere("shot", {0, 0, 0}, 0.9 * dx));
  s.bodies[0].line = 12;
  CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[0]");
  EXPECT_EQ(e.line(), 12);
  EXPECT_TRUE(Contains(e.what(), "\"shot\" has a diameter of 1.8 mm at spacing 1 mm"));
  EXPECT_TRUE(Contains(e.what(), "make it at least 2 mm"));

  // Overlap with a plate: a plate particle inside the ball.
  s.bodies[0] = box("plate", {-5 * dx, -5 * dx, -2 * dx}, {5 * dx, 5 * dx, 0});
  s.bodies.push_back(sphere("ball", {0, 0, 2 * dx}, 3 * dx));
  e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[1]");
  EXPECT_TRUE(Contains(e.what(), "\"ball\" overlaps bodies[0] (\"plate\"): the particle of \"plate\" at (-0.5 mm, -1.5 mm, -0.5 mm) lies inside \"ball\""));
  // Resting on it (centre one radius above its top face) is fine.
  s.bodies[1].center.z = 3 * dx;
  EXPECT_NO_THROW(build_scene(s));

  // A symmetry plane 0.4 dx off the centre leaves particles 0.5 ds - 0.4 dx from it (ds = 0.9404 dx, the
  // lattice fitted to a ball of radius 3 dx: 70.19 um).
  s.bodies.pop_back();
  s.bodies[0] = sphere("ball", {0, -0.4 * dx, 0}, 3 * dx);
  s.symmetry.push_back({1, 0.0});
  e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[0]");
  EXPECT_TRUE(Contains(e.what(), "is 70.1912 um from the symmetry plane y = 0 mm (boundaries.symmetry[0])"));
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

  // A body across the plane is clipped (below); bodies wholly on both sides are an error.
  s.bodies[0] = box("above", {0, 1 * dx, 0}, {4 * dx, 4 * dx, 4 * dx});
  s.bodies.push_back(box("below", {0, -4 * dx, 0}, {4 * dx, -1 * dx, 4 * dx}));
  s.bodies[1].line = 17;
  CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[1]");
  EXPECT_EQ(e.line(), 17);
  EXPECT_TRUE(Contains(e.what(), "other side of the symmetry plane y = 0 mm (boundaries.symmetry[0]) from bodies[0]"));

  // Also when a body across the plane lies between them: the first body wholly on one side decides.
  s.bodies.insert(s.bodies.begin(), box("across", {5 * dx, -2 * dx, 0}, {9 * dx, 2 * dx, 4 * dx}));
  e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[2]");
  EXPECT_TRUE(Contains(e.what(), "from bodies[1] (\"above\")"));
}

TEST(SceneErrors, ABodyThroughAWall) {
  // A wall is not a plane of symmetry: a body that reaches through it is an error, not clipped.
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  SymmetryPlaneSpec wall{2, 0.0};
  wall.wall = true;
  wall.key = "boundaries.wall[0]";
  s.symmetry.push_back(wall);
  s.bodies.push_back(box("block", {0, 0, 0}, {4 * dx, 4 * dx, 4 * dx}));
  EXPECT_NO_THROW(build_scene(s));
  s.bodies[0] = box("through", {0, 0, -2 * dx}, {4 * dx, 4 * dx, 2 * dx});
  s.bodies[0].line = 7;
  const CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[0]");
  EXPECT_EQ(e.line(), 7);
  EXPECT_TRUE(Contains(e.what(), "reaches through the wall z = 0 mm (boundaries.wall[0])"));
}

TEST(SceneErrors, ClippingErrors) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.symmetry.push_back({1, 0.0});
  // A box across the plane is filled on each side of it: 3 spacings across, 1.5 a side, 2 cells of 0.75 dx
  // each, so no layer lies on the plane (where its particles would coincide with their mirror images).
  s.bodies.push_back(box("odd", {0, -1.5 * dx, 0}, {4 * dx, 1.5 * dx, 4 * dx}));
  Scene split = build_scene(s);
  EXPECT_EQ(split.particles.size(), 4u * 2u * 4u);
  for (const Vec3d& q : split.particles.pos) EXPECT_TRUE(std::abs(q.y - 0.375 * dx) < 1e-15 || std::abs(q.y - 1.125 * dx) < 1e-15);
  EXPECT_NEAR(split.bodies[0].generated_mass, split.bodies[0].specified_mass, 1e-12 * split.bodies[0].specified_mass);
  // Cut off its centre (0.3 dx below the plane, 2.7 dx above), the model mirrored is not the box: the
  // mass and the size along y say so.
  s.bodies[0] = box("near", {0, -0.3 * dx, 0}, {4 * dx, 2.7 * dx, 4 * dx});
  split = build_scene(s);
  EXPECT_NEAR(split.bodies[0].generated_mass / split.bodies[0].specified_mass, 5.4 / 3.0, 1e-12);
  // (The model's 2.7 dx above the plane are 3 cells of 0.9 dx, stretched by 10 %, which is warned of too.)
  EXPECT_TRUE(AnyContains(split.bodies[0].warnings, "its y is 5.4 mm against 3 mm specified (+80.00 %)"));
  EXPECT_TRUE(AnyContains(split.bodies[0].warnings, "a symmetry plane cuts it off its centre"));
  EXPECT_TRUE(AnyContains(split.bodies[0].warnings, "its lattice is stretched by up to 10.00 %"));

  // A cylinder whose axis is 0.4 dx off the plane keeps particles 0.5 ds - 0.4 dx from it (ds = 0.985 dx,
  // fitted to a radius of 3 dx); 0.2 dx off is fine (0.29 dx: the mirror images are 0.58 dx away).
  s.bodies[0] = cylinder("rod", {0, -0.4 * dx, 0}, 2, 3 * dx, 4 * dx);
  s.bodies[0].line = 9;
  CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[0]");
  EXPECT_EQ(e.line(), 9);
  EXPECT_TRUE(Contains(e.what(), "um from the symmetry plane y = 0 mm (boundaries.symmetry[0])"));
  EXPECT_TRUE(Contains(e.what(), "closer than half the spacing (0.5 mm) to its own mirror image"));
  s.bodies[0] = cylinder("rod", {0, -0.2 * dx, 0}, 2, 3 * dx, 4 * dx);
  EXPECT_NO_THROW(build_scene(s));

  // Clipped to nothing: a disc across x = 0 and y = 0 whose lattice misses the quadrant x > 0, y > 0
  // (offsets (i + 1/2) dx from (-2, -2) dx within 3 dx reach x = 0.5 dx and y = 0.5 dx, never both).
  s = spec_with_spacing(dx);
  s.symmetry.push_back({0, 0.0});
  s.symmetry.push_back({1, 0.0});
  s.bodies.push_back(cylinder("disc", {-2 * dx, -2 * dx, 0}, 2, 3 * dx, 2 * dx));
  s.bodies.push_back(box("block", {2 * dx, 2 * dx, 0}, {6 * dx, 6 * dx, 2 * dx}));
  s.bodies[0].line = 4;
  e = scene_error(s);
  EXPECT_EQ(e.key(), "bodies[0]");
  EXPECT_EQ(e.line(), 4);
  EXPECT_TRUE(Contains(e.what(), "\"disc\" would be clipped to nothing"));
  EXPECT_TRUE(Contains(e.what(), "(x > 0 mm, y > 0 mm)"));
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
  // The example of docs/case-files.md at a coarse spacing, to stay fast: a quarter model.
  const CaseSpec spec =
      load_case_file(std::string(IMPACTSPH_TEST_DATA) + "/example_plate_impact.toml", {}, "2 mm");
  const Scene scene = build_scene(spec);
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.bodies[0].name, "plate");
  EXPECT_EQ(scene.bodies[1].name, "projectile");
  EXPECT_EQ(scene.bodies[1].material, 1);
  // A quarter of the 197 g projectile (F section 6): within the lattice's discretisation of the circle.
  EXPECT_NEAR(scene.bodies[1].initial_mass, 0.197 / 4, 0.197 / 4 * 0.05);
  CaseSpec whole_spec = spec;
  whole_spec.symmetry.clear();
  const Scene whole = build_scene(whole_spec);
  EXPECT_EQ(scene.bodies[0].particle_count * 4, whole.bodies[0].particle_count);
  EXPECT_EQ(scene.bodies[1].particle_count * 4, whole.bodies[1].particle_count);
  for (const Vec3d& q : scene.particles.pos) {
    EXPECT_GT(q.x, 0);
    EXPECT_GT(q.y, 0);
  }
  ASSERT_EQ(scene.spec.contacts.size(), 1u);
  EXPECT_EQ(scene.spec.contacts[0].index_a, 1);
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

TEST(SceneErrors, GeometryErrorsNameTheBodysLine) {
  const std::string toml = R"([case]
name = "lines"

[materials.steel]
density = "7850 kg/m^3"
eos = { kind = "linear", bulk_modulus = "160 GPa" }
strength = { kind = "elastic", shear_modulus = "80 GPa" }

[[bodies]]
name = "plate"
material = "steel"
shape = "box"
min = ["0 mm", "0 mm", "0 mm"]
max = ["10 mm", "10 mm", "4 mm"]

[[bodies]]
name = "projectile"
material = "steel"
shape = "cylinder"
base = ["5 mm", "5 mm", "2 mm"]
axis = "z"
radius = "2 mm"
length = "6 mm"

[[boundaries.fixed]]
region = "box"
min = ["50 mm", "0 mm", "0 mm"]
max = ["60 mm", "1 mm", "1 mm"]

[numerics]
spacing = "1 mm"

[time]
end = "20 us"
output_interval = "1 us"
)";
  auto error = [](const std::string& text) {
    try {
      build_scene(parse_case_string(text, "lines.toml"));
    } catch (const CaseError& e) {
      return e;
    }
    ADD_FAILURE() << "accepted";
    return CaseError("", 0, "", "");
  };
  // Overlap: the later body, at the line of its [[bodies]].
  CaseError e = error(toml);
  EXPECT_EQ(e.key(), "bodies[1]");
  EXPECT_EQ(e.line(), 16);
  EXPECT_TRUE(Contains(e.what(), "lines.toml:16: bodies[1]: \"projectile\" overlaps"));

  // A thin body.
  std::string t = toml;
  t.replace(t.find("radius = \"2 mm\""), 15, "radius = \"0.4 mm\"");
  t.replace(t.find("\"2 mm\"]"), 6, "\"4 mm\"");
  e = error(t);
  EXPECT_EQ(e.key(), "bodies[1]");
  EXPECT_EQ(e.line(), 16);
  EXPECT_TRUE(Contains(e.what(), "diameter of 0.8 mm"));
  t = toml;
  t.replace(t.find("\"4 mm\"]"), 6, "\"1.5 mm\"");
  e = error(t);
  EXPECT_EQ(e.key(), "bodies[0]");
  EXPECT_EQ(e.line(), 9);
  EXPECT_TRUE(Contains(e.what(), "thick along z"));

  // A fixed region that selects nothing, at the line of its [[boundaries.fixed]].
  t = toml;
  t.replace(t.find("\"2 mm\"]"), 6, "\"4 mm\"");
  e = error(t);
  EXPECT_EQ(e.key(), "boundaries.fixed[0]");
  EXPECT_EQ(e.line(), 25);
}

TEST(Scene, ContactsBuiltInCodeAreResolved) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("plate", {0, 0, 0}, {10 * dx, 10 * dx, 4 * dx}));
  s.bodies.push_back(box("block", {0, 0, 5 * dx}, {4 * dx, 4 * dx, 9 * dx}));
  ContactSpec c;
  c.body_a = "block";
  c.body_b = "plate";
  c.line = 30;
  s.contacts.push_back(c);
  Scene scene = build_scene(s);
  EXPECT_EQ(scene.spec.contacts[0].index_a, 1);
  EXPECT_EQ(scene.spec.contacts[0].index_b, 0);

  s.contacts.push_back(c);
  std::swap(s.contacts[1].body_a, s.contacts[1].body_b);
  CaseError e = scene_error(s);
  EXPECT_EQ(e.key(), "contacts[1].bodies");
  EXPECT_EQ(e.line(), 30);
  EXPECT_TRUE(Contains(e.what(), "already listed in contacts[0]"));

  s.contacts.pop_back();
  s.contacts[0].body_b = "block";
  e = scene_error(s);
  EXPECT_TRUE(Contains(e.what(), "names \"block\" twice"));
  s.contacts[0].body_b = "anvil";
  e = scene_error(s);
  EXPECT_EQ(e.key(), "contacts[0].bodies");
  EXPECT_TRUE(Contains(e.what(), "no body named \"anvil\""));
}
