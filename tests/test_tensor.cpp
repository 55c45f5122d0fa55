// Unit tests of common/tensor.hpp: inverse and determinant against Eigen, deviator, von Mises.
// Run for Real = float and double. Tolerances are multiples of the machine epsilon of Real times the
// condition number of the matrices used (kept below ~10 by construction).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <random>

#include "common/tensor.hpp"

namespace {

using namespace impactsph;

template <class Real>
class TensorTyped : public ::testing::Test {};
using TensorReals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(TensorTyped, TensorReals);

// A random well-conditioned matrix: 2 I + a random matrix with entries in [-0.5, 0.5] (Gershgorin: every
// eigenvalue lies within 1.5 of 2, so the matrix is far from singular), then scaled by a random factor
// to exercise the 1/det scaling.
template <class Real>
Mat3<Real> random_well_conditioned(std::mt19937& gen) {
  std::uniform_real_distribution<double> u(-0.5, 0.5), scale(0.01, 100.0);
  const double s = scale(gen);
  Mat3<Real> a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a.m[r][c] = Real(s * ((r == c ? 2.0 : 0.0) + u(gen)));
  return a;
}

template <class Real>
Eigen::Matrix3d to_eigen(const Mat3<Real>& a) {
  Eigen::Matrix3d e;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) e(r, c) = double(a.m[r][c]);
  return e;
}

TYPED_TEST(TensorTyped, InverseAndDeterminantMatchEigen) {
  using Real = TypeParam;
  // Cofactor inverse: each entry is a 2x2 minor (2 roundings) times 1/det (3 more); relative error a few
  // eps times the condition number (< ~10 here). 200 eps leaves a wide margin and still catches any wrong
  // cofactor sign or index, which gives O(1) errors.
  const double tol = 200.0 * std::numeric_limits<Real>::epsilon();
  std::mt19937 gen(12345);
  for (int trial = 0; trial < 200; ++trial) {
    const Mat3<Real> a = random_well_conditioned<Real>(gen);
    const Eigen::Matrix3d ea = to_eigen(a);  // exact copy of the Real entries, in double
    const double det_ref = ea.determinant();
    const Real det = determinant(a);
    ASSERT_NEAR(double(det), det_ref, tol * std::abs(det_ref)) << "trial " << trial;
    const Mat3<Real> inv = inverse(a, det);
    const Eigen::Matrix3d einv = ea.inverse();
    const double scale = einv.norm();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(double(inv.m[r][c]), einv(r, c), tol * scale) << r << c << " trial " << trial;
    // And the definition: A A^-1 = I.
    const Mat3<Real> id = a * inv;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(double(id.m[r][c]), r == c ? 1.0 : 0.0, tol) << r << c;
  }
}

TYPED_TEST(TensorTyped, DeterminantClosedForms) {
  using Real = TypeParam;
  // diag(2, 3, 5): 30; a permutation (one swap) of it: -30; a shear (unit upper-triangular): 1. All exact in
  // binary floating point.
  const Mat3<Real> d = {{{2, 0, 0}, {0, 3, 0}, {0, 0, 5}}};
  EXPECT_EQ(determinant(d), Real(30));
  const Mat3<Real> p = {{{0, 3, 0}, {2, 0, 0}, {0, 0, 5}}};
  EXPECT_EQ(determinant(p), Real(-30));
  const Mat3<Real> s = {{{1, 7, -4}, {0, 1, 9}, {0, 0, 1}}};
  EXPECT_EQ(determinant(s), Real(1));
  // Rank 2 (third row = first + second): exactly zero with small integers.
  const Mat3<Real> sing = {{{1, 2, 3}, {4, 5, 6}, {5, 7, 9}}};
  EXPECT_EQ(determinant(sing), Real(0));
}

TYPED_TEST(TensorTyped, MatrixProductTransposeOuterMatchEigen) {
  using Real = TypeParam;
  std::mt19937 gen(7);
  const double tol = 50.0 * std::numeric_limits<Real>::epsilon();
  const Mat3<Real> a = random_well_conditioned<Real>(gen), b = random_well_conditioned<Real>(gen);
  const Eigen::Matrix3d ref = to_eigen(a) * to_eigen(b);
  const Mat3<Real> ab = a * b;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(double(ab.m[r][c]), ref(r, c), tol * ref.norm());
  const Mat3<Real> at = a.transpose();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(at.m[r][c], a.m[c][r]);
  // outer(u, v)_rc = u_r v_c (the order correction.hpp relies on).
  const Vec3<Real> u{Real(1), Real(2), Real(3)}, v{Real(-1), Real(0.5), Real(4)};
  const Mat3<Real> o = outer(u, v);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(o.m[r][c], u[r] * v[c]);
  // Matrix-vector product.
  const Vec3<Real> av = a * u;
  const Eigen::Vector3d ev = to_eigen(a) * Eigen::Vector3d(1, 2, 3);
  for (int r = 0; r < 3; ++r) EXPECT_NEAR(double(av[r]), ev(r), tol * ev.norm());
}

TYPED_TEST(TensorTyped, DeviatorIsTraceFreeAndDdotMatchesFullTensor) {
  using Real = TypeParam;
  std::mt19937 gen(99);
  std::uniform_real_distribution<double> u(-1e9, 1e9);  // stresses in Pa
  for (int trial = 0; trial < 100; ++trial) {
    const Sym3<Real> a{Real(u(gen)), Real(u(gen)), Real(u(gen)), Real(u(gen)), Real(u(gen)), Real(u(gen))};
    const Sym3<Real> s = deviator(a);
    // Trace of the deviator: the mean (trace/3, error ~ eps 1e9) is subtracted three times and the
    // results summed; each step rounds at ~ eps 1e9, so 20 eps 1e9 bounds it.
    const double mag = 1e9;
    EXPECT_NEAR(double(s.trace()), 0.0, 20.0 * std::numeric_limits<Real>::epsilon() * mag);
    EXPECT_EQ(s.xy, a.xy);
    EXPECT_EQ(s.yz, a.yz);
    EXPECT_EQ(s.zx, a.zx);
    // ddot of the six-component form equals the full-tensor contraction (off-diagonals counted twice).
    const double full = double(ddot(a.full(), a.full()));
    EXPECT_NEAR(double(ddot(a, a)), full, 20.0 * std::numeric_limits<Real>::epsilon() * full);
    // from(full()) is the identity on symmetric tensors.
    const Sym3<Real> back = Sym3<Real>::from(a.full());
    EXPECT_EQ(back.xx, a.xx);
    EXPECT_EQ(back.xy, a.xy);
    EXPECT_EQ(back.yz, a.yz);
    EXPECT_EQ(back.zx, a.zx);
  }
}

TYPED_TEST(TensorTyped, VonMisesOfUniaxialAndPureShear) {
  using Real = TypeParam;
  // Uniaxial stress sigma along each axis: von Mises of its deviator equals |sigma|.
  // Pure shear tau: sqrt(3) |tau|. A few roundings: 10 eps relative.
  const double tol = 10.0 * std::numeric_limits<Real>::epsilon();
  for (double sigma : {350e6, -1.2e9, 1.0}) {
    for (int axis = 0; axis < 3; ++axis) {
      Sym3<Real> a = Sym3<Real>::zero();
      (axis == 0 ? a.xx : axis == 1 ? a.yy : a.zz) = Real(sigma);
      EXPECT_NEAR(double(von_mises(deviator(a))), std::abs(sigma), tol * std::abs(sigma));
    }
    Sym3<Real> shear = Sym3<Real>::zero();
    shear.yz = Real(sigma);
    EXPECT_NEAR(double(von_mises(shear)), std::sqrt(3.0) * std::abs(sigma), tol * std::abs(sigma));
  }
  // A hydrostatic state has no deviator and zero von Mises stress.
  const Sym3<Real> hyd{Real(5e8), Real(5e8), Real(5e8), 0, 0, 0};
  EXPECT_EQ(von_mises(deviator(hyd)), Real(0));
}

}  // namespace
