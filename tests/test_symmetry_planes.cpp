// Symmetry planes (common/integration.hpp): the mirror images both solvers build as ghost particles, the
// mirrored stress of an image, and the reflection of a particle that crossed a plane. Hand values.
#include <gtest/gtest.h>

#include "common/integration.hpp"
#include "common/particle_set.hpp"

namespace impactsph {
namespace {

Vec3d image_of(Vec3d sign, Vec3d shift, Vec3d x) { return hadamard(sign, x) + shift; }

TEST(SymmetryPlanes, MirrorThroughPlaneReflectsAPointWithinTheMargin) {
  Vec3d sign{1, 1, 1}, shift{0, 0, 0};
  const Vec3d x{0.3, 2.0, -1.0};
  // Plane x = 0.5, margin 0.25: x lies 0.2 from it, so its image is at 2 * 0.5 - 0.3 = 0.7.
  ASSERT_TRUE(mirror_through_plane(sign, shift, x, 0, 0.5, 0.25));
  const Vec3d img = image_of(sign, shift, x);
  EXPECT_DOUBLE_EQ(img.x, 0.7);
  EXPECT_DOUBLE_EQ(img.y, 2.0);
  EXPECT_DOUBLE_EQ(img.z, -1.0);
  EXPECT_EQ(sign.x, -1.0);
  EXPECT_EQ(shift.x, 1.0);
}

TEST(SymmetryPlanes, MirrorThroughPlaneLeavesAFarPointAlone) {
  Vec3d sign{1, 1, 1}, shift{0, 0, 0};
  // 0.25 from the plane x = 0.5 with a margin of 0.25: not within it (the margin is exclusive).
  EXPECT_FALSE(mirror_through_plane(sign, shift, Vec3d{0.25, 0, 0}, 0, 0.5, 0.25));
  EXPECT_FALSE(mirror_through_plane(sign, shift, Vec3d{-3.0, 0, 0}, 0, 0.5, 0.25));
  EXPECT_EQ(sign.x, 1.0);
  EXPECT_EQ(shift.x, 0.0);
}

TEST(SymmetryPlanes, TwoPlanesGiveTheCornerImage) {
  // Planes x = 0 and y = 0 (a quarter model): the image through both is the point turned half round the z axis.
  const Vec3d x{0.1, 0.2, 0.3};
  Vec3d sign{1, 1, 1}, shift{0, 0, 0};
  ASSERT_TRUE(mirror_through_plane(sign, shift, x, 0, 0.0, 0.5));
  ASSERT_TRUE(mirror_through_plane(sign, shift, x, 1, 0.0, 0.5));
  const Vec3d img = image_of(sign, shift, x);
  EXPECT_DOUBLE_EQ(img.x, -0.1);
  EXPECT_DOUBLE_EQ(img.y, -0.2);
  EXPECT_DOUBLE_EQ(img.z, 0.3);
  // An image is tested against the next plane where it lies, not where its source does: the image of x
  // through x = 1 is at 1.9, 0.9 from the plane x = 1 and 1.9 from x = 0, so a margin of 1 takes it through
  // the first plane only.
  Vec3d s2{1, 1, 1}, t2{0, 0, 0};
  ASSERT_TRUE(mirror_through_plane(s2, t2, x, 0, 1.0, 1.0));
  EXPECT_DOUBLE_EQ(image_of(s2, t2, x).x, 1.9);
  EXPECT_FALSE(mirror_through_plane(s2, t2, x, 0, 0.0, 1.0));
}

TEST(SymmetryPlanes, MirroredStressFlipsTheShearAcrossThePlane) {
  const Sym3d s{1, 2, 3, 4, 5, 6};  // xx yy zz xy yz zx
  const Sym3d m = mirror(s, Vec3d{1, 1, -1});  // plane normal to z: xz and yz change sign, xy does not
  EXPECT_EQ(m.xx, 1);
  EXPECT_EQ(m.yy, 2);
  EXPECT_EQ(m.zz, 3);
  EXPECT_EQ(m.xy, 4);
  EXPECT_EQ(m.yz, -5);
  EXPECT_EQ(m.zx, -6);
  // Both lateral planes: the corner image is the half turn about z, which keeps xy and flips yz and zx.
  const Sym3d c = mirror(s, Vec3d{-1, -1, 1});
  EXPECT_EQ(c.xy, 4);
  EXPECT_EQ(c.yz, -5);
  EXPECT_EQ(c.zx, -6);
}

TEST(SymmetryPlanes, AParticleThatCrossedIsReflectedWithItsNormalVelocityReversed) {
  // Model on the side z >= 0 of the plane z = 0 (side +1).
  Vec3d x{0.1, 0.2, -0.05}, v{1.0, 2.0, -3.0};
  reflect_at_plane(x, v, 2, 0.0, 1.0);
  EXPECT_DOUBLE_EQ(x.z, 0.05);
  EXPECT_DOUBLE_EQ(v.z, 3.0);
  EXPECT_DOUBLE_EQ(v.x, 1.0);  // frictionless: the tangential velocity is kept
  Vec3d y{0.1, 0.2, 0.05}, u{1.0, 2.0, -3.0};
  reflect_at_plane(y, u, 2, 0.0, 1.0);  // on the model's side: untouched
  EXPECT_DOUBLE_EQ(y.z, 0.05);
  EXPECT_DOUBLE_EQ(u.z, -3.0);
}

TEST(Walls, AParticleLetsGoWhenInTensionAndLeaving) {
  // Wall normal to z, the model above it (side +1). sigma_nn = S_nn - P: pressure 100 MPa and S_zz = 50 MPa
  // press (-50 MPa); S_zz = 150 MPa pulls (+50 MPa). Only a particle that pulls and moves away lets go.
  const Sym3d presses{0, 0, 50e6, 0, 0, 0}, pulls{-20e6, 0, 150e6, 30e6, 0, 0};
  const Vec3d leaving{0, 0, 1.0}, arriving{5.0, 0, -1.0}, at_rest{0, 0, 0};
  EXPECT_TRUE(lets_go_of_wall(pulls, 100e6, leaving, 2, 1.0));
  EXPECT_FALSE(lets_go_of_wall(pulls, 100e6, arriving, 2, 1.0));
  EXPECT_FALSE(lets_go_of_wall(pulls, 100e6, at_rest, 2, 1.0));
  EXPECT_FALSE(lets_go_of_wall(presses, 100e6, leaving, 2, 1.0));
  // The model below the wall (side -1): leaving is moving along -z.
  EXPECT_TRUE(lets_go_of_wall(pulls, 100e6, Vec3d{0, 0, -1.0}, 2, -1.0));
  EXPECT_FALSE(lets_go_of_wall(pulls, 100e6, leaving, 2, -1.0));
  // The normal stress is the wall's own: S_xx = -20 MPa presses on a wall normal to x; zero still presses.
  EXPECT_FALSE(lets_go_of_wall(pulls, 100e6, Vec3d{1.0, 0, 0}, 0, 1.0));
  EXPECT_FALSE(lets_go_of_wall(Sym3d{100e6, 0, 0, 0, 0, 0}, 100e6, Vec3d{1.0, 0, 0}, 0, 1.0));
}

}  // namespace
}  // namespace impactsph
