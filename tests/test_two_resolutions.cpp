// Two resolutions in one body ([bodies.coarse], issue 18): the case keys and their errors, the lattice
// (the one-resolution lattice with its complete blocks of ratio^3 cells in the region merged), each particle's h,
// the coarse part's copy of the material, and the neighbour list that holds a pair within the larger of
// its two radii.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "common/case_file.hpp"
#include "common/damage.hpp"
#include "common/errors.hpp"
#include "common/scene.hpp"
#include "reference/neighbours.hpp"
#include "tests/case_file_fixture.hpp"
#include "tests/scene_fixture.hpp"

using namespace impactsph;
using namespace impactsph::scene_test;
using impactsph::case_file_test::error_of;
using impactsph::case_file_test::expect_error;
using impactsph::case_file_test::kBase;
using impactsph::case_file_test::line_of;
using impactsph::case_file_test::with;

namespace {

// A 12 x 4 x 4 dx bar, coarse (at 2 dx) where x > 6 dx.
CaseSpec bar_with_coarse_half(double dx, int ratio) {
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(box("bar", {0, 0, 0}, {12 * dx, 4 * dx, 4 * dx}));
  s.bodies[0].coarse_ratio = ratio;
  s.bodies[0].coarse_region.kind = FixedRegionSpec::Kind::Box;
  s.bodies[0].coarse_region.box_min = {6 * dx, 0, 0};
  s.bodies[0].coarse_region.box_max = {12 * dx, 4 * dx, 4 * dx};
  return s;
}

std::tuple<long, long, long> key_of(const Vec3d& x, double dx) {
  return {std::lround(x.x / (0.25 * dx)), std::lround(x.y / (0.25 * dx)), std::lround(x.z / (0.25 * dx))};
}

// Compares a two-resolution scene with its case at one resolution: every fine particle (h below 1.5 dx)
// stands on a point of the one-resolution lattice and each coarse one stands for eight of them;
// `coarse_point` checks where each coarse particle stands. Returns the number of coarse particles.
template <class CoarsePoint>
std::size_t expect_blocks_of_the_lattice(const CaseSpec& s, const Scene& two, double dx, CoarsePoint coarse_point) {
  CaseSpec uniform_spec = s;
  uniform_spec.bodies[0].coarse_ratio = 1;
  const Scene one = build_scene(uniform_spec);
  std::set<std::tuple<double, double, double>> uniform_points;
  for (const Vec3d& x : one.particles.pos) uniform_points.insert({x.x, x.y, x.z});
  std::size_t fine = 0, coarse = 0;
  for (std::size_t i = 0; i < two.particles.size(); ++i) {
    const Vec3d& x = two.particles.pos[i];
    if (two.particles.h[i] > 1.5 * dx) {
      ++coarse;
      coarse_point(x);
      continue;
    }
    ++fine;
    EXPECT_TRUE(uniform_points.count({x.x, x.y, x.z})) << "a fine point off the one-resolution lattice";
  }
  EXPECT_EQ(fine + 8 * coarse, one.particles.size());
  return coarse;
}

}  // namespace

TEST(TwoResolutions, CompleteBlocksInTheRegionAreMergedIntoCoarseCells) {
  const double dx = 1e-3;
  const Scene two = build_scene(bar_with_coarse_half(dx, 2));
  CaseSpec uniform_spec = bar_with_coarse_half(dx, 2);
  uniform_spec.bodies[0].coarse_ratio = 1;
  const Scene one = build_scene(uniform_spec);
  const ParticleSet& p = two.particles;
  // Fine part 6 x 4 x 4 cells of dx; coarse part 3 x 2 x 2 cells of 2 dx.
  ASSERT_EQ(p.size(), 96u + 12u);
  EXPECT_EQ(two.bodies[0].coarse_particle_count, 12u);
  double mass = 0;
  std::size_t coarse = 0;
  std::set<std::tuple<long, long, long>> fine_points;
  for (std::size_t i = 0; i < p.size(); ++i) {
    mass += p.mass[i];
    if (p.pos[i].x > 6 * dx) {
      ++coarse;
      EXPECT_DOUBLE_EQ(p.h[i], 1.2 * 2 * dx);
      EXPECT_NEAR(p.mass[i], kRho * 8 * dx * dx * dx, 1e-12 * kRho * dx * dx * dx);
      EXPECT_EQ(p.material[i], 1) << "the coarse part takes the material's copy";
    } else {
      EXPECT_DOUBLE_EQ(p.h[i], 1.2 * dx);
      EXPECT_NEAR(p.mass[i], kRho * dx * dx * dx, 1e-12 * kRho * dx * dx * dx);
      EXPECT_EQ(p.material[i], 0);
      fine_points.insert(key_of(p.pos[i], dx));
    }
  }
  EXPECT_EQ(coarse, 12u);
  EXPECT_NEAR(mass, kRho * 12 * 4 * 4 * dx * dx * dx, 1e-12 * mass);
  EXPECT_NEAR(two.bodies[0].generated_mass, two.bodies[0].specified_mass, 1e-12 * mass);
  for (const BodySize& size : two.bodies[0].sizes) EXPECT_NEAR(size.generated, size.specified, 1e-12) << size.name;
  // The fine part is the one-resolution lattice there, point for point.
  std::size_t matched = 0;
  for (std::size_t i = 0; i < one.particles.size(); ++i)
    if (one.particles.pos[i].x < 6 * dx) {
      EXPECT_TRUE(fine_points.count(key_of(one.particles.pos[i], dx))) << "a fine point is missing";
      ++matched;
    }
  EXPECT_EQ(matched, fine_points.size());
  ASSERT_EQ(two.materials.size(), 2u);
  EXPECT_EQ(one.materials.size(), 1u);
}

// A quarter disc (the plate case's layout) with its rim coarse: the body as specified, whole, and each
// layer's area counted once across the fine and coarse layers.
TEST(TwoResolutions, QuarterDiscWithACoarseRimKeepsItsMassAndSizes) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(cylinder("plate", {0, 0, -8 * dx}, 2, 30 * dx, 8 * dx));
  s.bodies[0].coarse_ratio = 2;
  s.bodies[0].coarse_region.kind = FixedRegionSpec::Kind::OutsideCylinder;
  s.bodies[0].coarse_region.axis = 2;
  s.bodies[0].coarse_region.radius = 15 * dx;
  for (int a = 0; a < 2; ++a) {
    SymmetryPlaneSpec plane;
    plane.axis = a;
    s.symmetry.push_back(plane);
  }
  const Scene scene = build_scene(s);
  const BodyInfo& b = scene.bodies[0];
  EXPECT_GT(b.coarse_particle_count, 0u);
  EXPECT_LT(b.coarse_particle_count, b.particle_count);
  EXPECT_NEAR(b.generated_mass / b.specified_mass, 1.0, 1e-12);
  for (const BodySize& size : b.sizes) EXPECT_NEAR(size.generated / size.specified, 1.0, 1e-6) << size.name;
  EXPECT_TRUE(b.warnings.empty()) << b.warnings.front();
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const Vec3d& x = scene.particles.pos[i];
    EXPECT_GT(x.x, 0);
    EXPECT_GT(x.y, 0);
  }
  // The fine part is the one-resolution lattice point for point, the round cross-section included, and each
  // coarse particle stands for eight of its points, centred in the region.
  const std::size_t coarse = expect_blocks_of_the_lattice(
      s, scene, dx, [&](const Vec3d& x) { EXPECT_GE(x.x * x.x + x.y * x.y, sqr(15 * dx)); });
  EXPECT_EQ(coarse, b.coarse_particle_count);
}

// A ball coarse outside a box about its centre: its blocks of eight lie symmetrically about the centre, the
// fine part is the one-resolution lattice, and the ball keeps its mass.
TEST(TwoResolutions, BallWithACoarseShellIsItsLatticeWithBlocksMerged) {
  const double dx = 1e-3;
  CaseSpec s = spec_with_spacing(dx);
  s.bodies.push_back(sphere("ball", {0, 0, 0}, 8 * dx));
  s.bodies[0].coarse_ratio = 2;
  s.bodies[0].coarse_region.kind = FixedRegionSpec::Kind::Box;
  s.bodies[0].coarse_region.box_min = {-20 * dx, -20 * dx, 2.5 * dx};
  s.bodies[0].coarse_region.box_max = {20 * dx, 20 * dx, 20 * dx};
  const Scene two = build_scene(s);
  // a block's centre: (2 I + 1) s on each axis, in the region
  const std::size_t coarse = expect_blocks_of_the_lattice(s, two, dx, [&](const Vec3d& x) {
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(std::fmod(std::abs(x[a]) / two.bodies[0].lattice_spacing[a], 2.0), 1.0, 1e-9);
    EXPECT_GT(x.z, 2.5 * dx);
  });
  EXPECT_GT(coarse, 0u);
  EXPECT_NEAR(two.bodies[0].generated_mass / two.bodies[0].specified_mass, 1.0, 1e-12);
}

// A count of cells that does not divide by the ratio: the layer left over stays fine, also in the region.
TEST(TwoResolutions, ALayerLeftOverByTheRatioStaysFine) {
  const double dx = 1e-3;
  CaseSpec s = bar_with_coarse_half(dx, 2);
  s.bodies[0].box_max.z = 5 * dx;
  s.bodies[0].coarse_region.box_max.z = 5 * dx;
  const Scene scene = build_scene(s);
  const ParticleSet& p = scene.particles;
  // Fine half 6 x 4 x 5 cells; coarse half 3 x 2 x 2 blocks and the top layer's 6 x 4 cells.
  ASSERT_EQ(p.size(), 120u + 12u + 24u);
  EXPECT_EQ(scene.bodies[0].coarse_particle_count, 12u);
  double mass = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    mass += p.mass[i];
    if (p.pos[i].x > 6 * dx && p.h[i] < 1.5 * dx) EXPECT_NEAR(p.pos[i].z, 4.5 * dx, 1e-12);
  }
  EXPECT_NEAR(mass, kRho * 12 * 4 * 5 * dx * dx * dx, 1e-12 * mass);
}

TEST(TwoResolutions, TheCoarsePartsFractureEnergyFollowsItsSmoothingLength) {
  const double dx = 1e-3;
  CaseSpec s = bar_with_coarse_half(dx, 3);
  s.bodies[0].box_max = {18 * dx, 6 * dx, 6 * dx};
  s.bodies[0].coarse_region.box_min = {9 * dx, 0, 0};
  s.bodies[0].coarse_region.box_max = {18 * dx, 6 * dx, 6 * dx};
  DamageParams<double>& d = s.materials[0].params.damage;
  d.kind = DamageKind::FractureEnergy;
  d.fracture_energy.gamma = 1.7e6;
  d.fracture_energy.band_width_factor = 2.4;
  const Scene scene = build_scene(s);
  ASSERT_EQ(scene.materials.size(), 2u);
  const double fine = scene.materials[0].damage.fracture_energy.critical_work;
  const double coarse = scene.materials[1].damage.fracture_energy.critical_work;
  EXPECT_NEAR(fine, 1.7e6 / (2.4 * 1.2 * dx), 1e-9 * fine);
  EXPECT_NEAR(fine / coarse, 3.0, 1e-12);
}

TEST(TwoResolutions, RegionOutsideTheBodyOrCoveringItIsAnError) {
  const double dx = 1e-3;
  CaseSpec outside = bar_with_coarse_half(dx, 2);
  outside.bodies[0].coarse_region.box_min = {20 * dx, 0, 0};
  outside.bodies[0].coarse_region.box_max = {30 * dx, 4 * dx, 4 * dx};
  try {
    build_scene(outside);
    ADD_FAILURE() << "a coarse region outside the body was accepted";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.key(), "bodies[0].coarse");
    EXPECT_NE(std::string(e.what()).find("lies outside the body"), std::string::npos) << e.what();
  }
  CaseSpec all = bar_with_coarse_half(dx, 2);
  all.bodies[0].coarse_region.box_min = {-dx, -dx, -dx};
  try {
    build_scene(all);
    ADD_FAILURE() << "a coarse region holding the whole body was accepted";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.key(), "bodies[0].coarse");
    EXPECT_NE(std::string(e.what()).find("holds every cell"), std::string::npos) << e.what();
  }
}

TEST(TwoResolutions, CaseKeysAndTheirErrors) {
  const std::string table = "max = [\"10 mm\", \"10 mm\", \"2 mm\"]\n\n[bodies.coarse]\n";
  const std::string region =
      "region = \"outside-cylinder\"\naxis = \"z\"\naxis_point = [\"5 mm\", \"5 mm\", \"0 mm\"]\nradius = \"3 mm\"\n";
  const CaseSpec ok = parse_case_string(with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]\n", table + "ratio = 2\n" + region),
                                        "case.toml", {}, "0.25 mm");
  EXPECT_EQ(ok.bodies[0].coarse_ratio, 2);
  EXPECT_EQ(ok.bodies[0].coarse_region.kind, FixedRegionSpec::Kind::OutsideCylinder);
  EXPECT_DOUBLE_EQ(ok.bodies[0].coarse_region.radius, 3e-3);
  EXPECT_EQ(ok.bodies[1].coarse_ratio, 1);

  std::string t = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]\n", table + "ratio = 5\n" + region);
  expect_error(t, "bodies[0].coarse.ratio", "must be 2 (got 5)", line_of(t, "ratio = 5"));
  t = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]\n", table + "ratio = 4\n" + region);
  expect_error(t, "bodies[0].coarse.ratio", "4:1 reflect", line_of(t, "ratio = 4"));
  t = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]\n", table + region);
  expect_error(t, "bodies[0].coarse.ratio", "missing in the coarse region of a body", -1);
  t = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]\n", table + "ratio = 2\nspacing = \"1 mm\"\n" + region);
  expect_error(t, "bodies[0].coarse.spacing", "valid keys: region, ratio, max_spacing, axis, axis_point, radius", -1);
  t = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]\n", table + "ratio = 2\nmax_spacing = \"-1 mm\"\n" + region);
  expect_error(t, "bodies[0].coarse.max_spacing", "must be greater than zero", line_of(t, "max_spacing"));
  // max_spacing: the region is built at spacings up to it, and above it the body is at one resolution.
  const std::string bounded = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]\n",
                                   table + "ratio = 2\nmax_spacing = \"0.25 mm\"\n" + region);
  const CaseSpec at = parse_case_string(bounded, "case.toml", {}, "0.25 mm");
  EXPECT_EQ(at.bodies[0].coarse_ratio, 2);
  EXPECT_EQ(at.bodies[0].coarse_off_above, 0.0);
  const CaseSpec above = parse_case_string(bounded, "case.toml", {}, "0.5 mm");
  EXPECT_EQ(above.bodies[0].coarse_ratio, 1);
  EXPECT_DOUBLE_EQ(above.bodies[0].coarse_off_above, 0.25e-3);
  t = with("max = [\"10 mm\", \"10 mm\", \"2 mm\"]\n", "max = [\"10 mm\", \"10 mm\", \"2 mm\"]\nvariable_h = true\n\n[bodies.coarse]\nratio = 2\n" + region);
  expect_error(t, "bodies[0].variable_h", "two initial smoothing lengths", -1);
}

TEST(TwoResolutions, ThinCoarseLatticeNamesTheRatio) {
  const double dx = 1e-3;
  CaseSpec s = bar_with_coarse_half(dx, 2);
  s.bodies[0].box_max = {12 * dx, 3 * dx, 4 * dx};  // 1.5 coarse cells across y
  try {
    build_scene(s);
    ADD_FAILURE() << "a body thinner than two coarse cells was accepted";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("coarse.ratio"), std::string::npos) << e.what();
  }
}

// A pair is held within the larger of its two radii, so the list is symmetric and a fine particle's row
// holds no coarse-only candidate beyond its own reach.
TEST(TwoResolutions, NeighbourListHoldsAPairWithinTheLargerRadius) {
  const std::vector<Vec3d> pts{{0, 0, 0}, {1.5, 0, 0}, {3.5, 0, 0}, {0, 2.5, 0}};
  const std::vector<double> radius{1.0, 2.0, 1.0, 1.0};
  reference::NeighbourList list;
  reference::build_neighbour_list(pts, pts.size(), 2.0, list, &radius);
  auto row = [&](std::size_t i) {
    return std::vector<std::int32_t>(list.indices.begin() + list.offsets[i], list.indices.begin() + list.offsets[i + 1]);
  };
  auto sorted = [](std::vector<std::int32_t> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  EXPECT_EQ(sorted(row(0)), (std::vector<std::int32_t>{1}));     // 1.5 < max(1, 2); 2.5 from 3 > 1
  EXPECT_EQ(sorted(row(1)), (std::vector<std::int32_t>{0}));     // 2.0 to 2 is not < 2; 2.92 to 3 > 2
  EXPECT_EQ(sorted(row(2)), (std::vector<std::int32_t>{}));
  EXPECT_EQ(sorted(row(3)), (std::vector<std::int32_t>{}));
  reference::NeighbourList one;
  reference::build_neighbour_list(pts, pts.size(), 2.0, one);
  EXPECT_EQ(one.offsets[4] - one.offsets[0], 2 + 0 + 0 + 0);  // (0,1) both ways only: 2.0 is not < 2
}
