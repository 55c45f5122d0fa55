// Unit tests of common/artificial_stress.hpp (Gray, Monaghan and Swift 2001) and of its pair term in
// common/pair_terms.hpp: the eigen-decomposition, R from the tensile principal stresses only, the pair
// factor f^n = (W(r)/W(dp))^n, and a pair that stays equal and opposite and conserves energy.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/artificial_stress.hpp"
#include "common/pair_terms.hpp"

namespace {

using namespace impactsph;

template <class Real>
class ArtificialStressTyped : public ::testing::Test {};
using ArtificialStressReals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(ArtificialStressTyped, ArtificialStressReals);

template <class Real>
Mat3<Real> rotation(Real ax, Real ay, Real az) {  // Rz(az) Ry(ay) Rx(ax)
  const Mat3<Real> rx{{{1, 0, 0}, {0, std::cos(ax), -std::sin(ax)}, {0, std::sin(ax), std::cos(ax)}}};
  const Mat3<Real> ry{{{std::cos(ay), 0, std::sin(ay)}, {0, 1, 0}, {-std::sin(ay), 0, std::cos(ay)}}};
  const Mat3<Real> rz{{{std::cos(az), -std::sin(az), 0}, {std::sin(az), std::cos(az), 0}, {0, 0, 1}}};
  return rz * ry * rx;
}

template <class Real>
Mat3<Real> diag(Real a, Real b, Real c) {
  Mat3<Real> d = Mat3<Real>::zero();
  d.m[0][0] = a; d.m[1][1] = b; d.m[2][2] = c;
  return d;
}

template <class Real>
Real max_abs_difference(const Mat3<Real>& a, const Mat3<Real>& b) {
  Real e = 0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) e = std::max(e, std::abs(a.m[r][c] - b.m[r][c]));
  return e;
}

// V diag(s) V^T gives the matrix back and V is orthonormal, for random symmetric matrices, repeated
// eigenvalues and a diagonal one.
TYPED_TEST(ArtificialStressTyped, EigenDecompositionReconstructs) {
  using Real = TypeParam;
  const Real tol = sizeof(Real) == 4 ? Real(2e-6) : Real(1e-13);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Sym3<Real>> cases = {Sym3<Real>{2, 2, -1, 0, 0, 0}, Sym3<Real>{1, 1, 1, 0, 0, 0},
                                   Sym3<Real>::from(rotation<Real>(0.3, -0.7, 1.1) * diag<Real>(3, 3, -2) *
                                                    rotation<Real>(0.3, -0.7, 1.1).transpose())};
  for (int k = 0; k < 50; ++k)
    cases.push_back(Sym3<Real>{Real(u(rng)), Real(u(rng)), Real(u(rng)), Real(u(rng)), Real(u(rng)), Real(u(rng))});
  for (const Sym3<Real>& a : cases) {
    Real s[3];
    Mat3<Real> V;
    symmetric_eigen(a, s, V);
    EXPECT_LT(max_abs_difference(V * diag(s[0], s[1], s[2]) * V.transpose(), a.full()), tol);
    EXPECT_LT(max_abs_difference(V.transpose() * V, Mat3<Real>::identity()), tol);
  }
}

// Uniaxial tension sigma_xx = T > 0: R = -epsilon T e_x (x) e_x. Pure compression: R = 0.
TYPED_TEST(ArtificialStressTyped, OnlyTensilePrincipalStressesRepel) {
  using Real = TypeParam;
  const ArtificialStressParams<Real> p = make_artificial_stress<Real>(Real(0.3), 4, KernelKind::WendlandC2, Real(1.2), ArtificialStressOf::Total);
  const Sym3<Real> R = artificial_stress(p, Sym3<Real>{Real(2), Real(0), Real(0), 0, 0, 0});
  EXPECT_NEAR(R.xx, Real(-0.6), Real(1e-6));
  EXPECT_EQ(R.yy, Real(0));
  EXPECT_EQ(R.zz, Real(0));
  EXPECT_EQ(R.xy, Real(0));
  const Sym3<Real> none = artificial_stress(p, Sym3<Real>{Real(-1), Real(-2), Real(-0.5), Real(0.1), 0, 0});
  EXPECT_EQ(ddot(none, none), Real(0));
  // Mixed: principal (4, -3, 0) rotated; only the 4 is kept, in its own direction.
  const Mat3<Real> Q = rotation<Real>(Real(0.4), Real(1.0), Real(-0.6));
  const Sym3<Real> A = Sym3<Real>::from(Q * diag<Real>(4, -3, 0) * Q.transpose());
  const Mat3<Real> expected = Q * diag<Real>(Real(-1.2), 0, 0) * Q.transpose();
  EXPECT_LT(max_abs_difference(artificial_stress(p, A).full(), expected), sizeof(Real) == 4 ? Real(2e-5) : Real(1e-12));
}

// The deviatoric form (the default): R from the tensile principal components of the deviator of A, so a
// hydrostatic tension carries none and uniaxial tension T gives -epsilon (2T/3) e_x (x) e_x.
TYPED_TEST(ArtificialStressTyped, DeviatoricFormIgnoresTheMeanStress) {
  using Real = TypeParam;
  const ArtificialStressParams<Real> p = make_artificial_stress<Real>(Real(0.3), 4, KernelKind::WendlandC2, Real(1.2), ArtificialStressOf::Deviatoric);
  const Sym3<Real> hydrostatic = artificial_stress(p, Sym3<Real>{Real(2), Real(2), Real(2), 0, 0, 0});
  EXPECT_EQ(ddot(hydrostatic, hydrostatic), Real(0));
  const Sym3<Real> R = artificial_stress(p, Sym3<Real>{Real(3), Real(0), Real(0), 0, 0, 0});
  EXPECT_NEAR(R.xx, Real(-0.6), Real(1e-6));
  EXPECT_NEAR(R.yy, Real(0), Real(1e-6));
  EXPECT_NEAR(R.zz, Real(0), Real(1e-6));
  // The same deviator under any pressure gives the same R.
  const Sym3<Real> shear{Real(0.5), Real(-0.2), Real(-0.3), Real(0.4), Real(0.1), Real(-0.2)};
  const Sym3<Real> pressed{shear.xx - 5, shear.yy - 5, shear.zz - 5, shear.xy, shear.yz, shear.zx};
  EXPECT_LT(max_abs_difference(artificial_stress(p, shear).full(), artificial_stress(p, pressed).full()), Real(1e-5));
}

// The bounded whole-stress form: Gray et al.'s R wherever the mean tension is at most the von Mises stress
// (shear, uniaxial and equibiaxial tension), and no more than the shear allows in hydrostatic tension.
TYPED_TEST(ArtificialStressTyped, BoundedFormCapsOnlyTheMeanTension) {
  using Real = TypeParam;
  const auto make = [](ArtificialStressOf of) {
    return make_artificial_stress<Real>(Real(0.3), 4, KernelKind::WendlandC2, Real(1.2), of);
  };
  const ArtificialStressParams<Real> total = make(ArtificialStressOf::Total), bounded = make(ArtificialStressOf::TotalBounded);
  const Real tol = sizeof(Real) == 4 ? Real(2e-5) : Real(1e-12);
  // Equibiaxial tension T (triaxiality 2/3): the whole-stress R, -epsilon T on both stretched axes, three
  // times the deviatoric form's.
  const Sym3<Real> biaxial{Real(3), Real(3), Real(0), 0, 0, 0};
  const Sym3<Real> R = artificial_stress(bounded, biaxial);
  EXPECT_LT(max_abs_difference(R.full(), artificial_stress(total, biaxial).full()), tol);
  EXPECT_NEAR(R.xx, Real(-0.9), Real(1e-5));
  EXPECT_NEAR(R.yy, Real(-0.9), Real(1e-5));
  EXPECT_NEAR(R.zz, Real(0), Real(1e-5));
  EXPECT_NEAR(artificial_stress(make(ArtificialStressOf::Deviatoric), biaxial).xx, Real(-0.3), Real(1e-5));
  // Uniaxial tension and a mixed state with compression: unchanged.
  for (const Sym3<Real>& A : {Sym3<Real>{Real(3), 0, 0, 0, 0, 0},
                              Sym3<Real>{Real(0.5), Real(-2), Real(0.1), Real(0.7), Real(0.2), Real(-0.4)}})
    EXPECT_LT(max_abs_difference(artificial_stress(bounded, A).full(), artificial_stress(total, A).full()), tol);
  // Hydrostatic tension: none (its von Mises stress is zero), where the whole-stress form repels.
  const Sym3<Real> hydrostatic{Real(2), Real(2), Real(2), 0, 0, 0};
  EXPECT_EQ(ddot(artificial_stress(bounded, hydrostatic), artificial_stress(bounded, hydrostatic)), Real(0));
  EXPECT_NEAR(artificial_stress(total, hydrostatic).xx, Real(-0.6), Real(1e-5));
  // Uniaxial strain in tension (principal 1, 0.49, 0.49: triaxiality 1.30): the mean is cut to the von
  // Mises stress 0.51, so the largest principal value is 0.34 + 0.51 and R_xx = -0.3 x 0.85.
  const Sym3<Real> strain{Real(1), Real(0.49), Real(0.49), 0, 0, 0};
  EXPECT_NEAR(artificial_stress(bounded, strain).xx, Real(-0.3) * Real(0.34 + 0.51), Real(1e-5));
  EXPECT_NEAR(artificial_stress(bounded, strain).yy, Real(-0.3) * Real(-0.17 + 0.51), Real(1e-5));
}

// Objectivity: R of a rotated stress is the rotated R.
TYPED_TEST(ArtificialStressTyped, RotatesWithTheStress) {
  using Real = TypeParam;
  const ArtificialStressParams<Real> p = make_artificial_stress<Real>(Real(0.3), 4, KernelKind::WendlandC2, Real(1.2), ArtificialStressOf::Total);
  const Sym3<Real> A{Real(1.5), Real(-0.4), Real(0.7), Real(0.9), Real(-0.3), Real(0.2)};
  const Mat3<Real> Q = rotation<Real>(Real(-0.8), Real(0.5), Real(2.0));
  const Mat3<Real> rotated_R = Q * artificial_stress(p, A).full() * Q.transpose();
  const Mat3<Real> R_rotated = artificial_stress(p, Sym3<Real>::from(Q * A.full() * Q.transpose())).full();
  EXPECT_LT(max_abs_difference(rotated_R, R_rotated), sizeof(Real) == 4 ? Real(2e-5) : Real(1e-12));
}

// f^n = (W(r)/W(dp))^n: 1 at the spacing dp = h / h_factor, above 1 closer in, below beyond, 0 outside
// the support; for both kernels.
TYPED_TEST(ArtificialStressTyped, PairFactorIsOneAtTheSpacing) {
  using Real = TypeParam;
  for (KernelKind k : {KernelKind::WendlandC2, KernelKind::CubicSpline}) {
    const Real h_factor = Real(1.2), h = Real(1.3e-3), dp = h / h_factor;
    const ArtificialStressParams<Real> p = make_artificial_stress<Real>(Real(0.3), 4, k, h_factor, ArtificialStressOf::Total);
    EXPECT_NEAR(artificial_stress_pair_factor(p, k, dp, h), Real(1), Real(1e-5));
    EXPECT_GT(artificial_stress_pair_factor(p, k, Real(0.8) * dp, h), Real(1));
    EXPECT_LT(artificial_stress_pair_factor(p, k, Real(1.2) * dp, h), Real(1));
    EXPECT_EQ(artificial_stress_pair_factor(p, k, Real(2.01) * h, h), Real(0));
    const Real f1 = make_artificial_stress<Real>(Real(0.3), 1, k, h_factor, ArtificialStressOf::Total).inverse_w_spacing * kernel_w(k, Real(1.5) * dp / h, Real(1));
    EXPECT_NEAR(artificial_stress_pair_factor(p, k, Real(1.5) * dp, h), f1 * f1 * f1 * f1, Real(1e-6));
    const ArtificialStressParams<Real> off = make_artificial_stress<Real>(Real(0), 4, k, h_factor, ArtificialStressOf::Total);
    EXPECT_EQ(artificial_stress_pair_factor(off, k, Real(0.8) * dp, h), Real(0));  // off: no pair term
  }
}

// A pair with artificial stress on both sides: equal and opposite forces, and the work of the pair force
// is what the two internal energies lose (m_i de_i + m_j de_j + m_i a_i.v_i + m_j a_j.v_j = 0).
TEST(ArtificialStressPair, EqualOppositeAndEnergyConserving) {
  const double rho = 7850, h = 1.2e-3, mi = 7.85e-3, mj = 8.2e-3;
  const ArtificialStressParams<double> p = make_artificial_stress(0.3, 4, KernelKind::WendlandC2, 1.2, ArtificialStressOf::Total);
  const Sym3<double> Ai{3e8 / (rho * rho), -1e8 / (rho * rho), 5e7 / (rho * rho), 1e8 / (rho * rho), 0, 2e7 / (rho * rho)};
  const Sym3<double> Aj{1e8 / (rho * rho), 2e8 / (rho * rho), -3e8 / (rho * rho), 0, 4e7 / (rho * rho), 0};
  const PairSide<double> i{Ai.full(), Mat3<double>::identity(), 0.0, 1, 5000, rho, false, artificial_stress(p, Ai).full()};
  const PairSide<double> j{Aj.full(), Mat3<double>::identity(), 0.0, 1, 5000, rho, false, artificial_stress(p, Aj).full()};
  const Vec3<double> xi{0, 0, 0}, xj{0.7e-3, 0.3e-3, -0.1e-3}, vi{10, -3, 2}, vj{-4, 5, 1};
  const Vec3<double> xij = xi - xj, vij = vi - vj;
  const double r = norm(xij);
  const Vec3<double> gw = kernel_grad(KernelKind::WendlandC2, xij, h);
  const double fn = artificial_stress_pair_factor(p, KernelKind::WendlandC2, r, h);
  ASSERT_GT(fn, 1.0);  // closer than the spacing: the term is at work
  const ViscosityParams<double> no_visc{0, 0};
  Vec3<double> ai{0, 0, 0}, aj{0, 0, 0}, ai_off{0, 0, 0};
  double dei = 0, dej = 0, de_off = 0;
  add_momentum_energy_pair(i, j, no_visc, gw, xij, vij, h, mj, fn, ai, dei);
  add_momentum_energy_pair(j, i, no_visc, -1.0 * gw, -1.0 * xij, -1.0 * vij, h, mi, fn, aj, dej);
  add_momentum_energy_pair(i, j, no_visc, gw, xij, vij, h, mj, 0.0, ai_off, de_off);
  EXPECT_GT(norm(ai - ai_off), 1e-3 * norm(ai_off));  // the artificial stress changed the pair force
  const Vec3<double> momentum = mi * ai + mj * aj;
  EXPECT_LT(norm(momentum), 1e-12 * mi * norm(ai));
  const double power = mi * dot(ai, vi) + mj * dot(aj, vj) + mi * dei + mj * dej;
  EXPECT_LT(std::abs(power), 1e-12 * mi * norm(ai) * norm(vij));
}

// Off (stress_factor 0) gives the bits of a pair without R; a crack-face pair carries none of it.
TEST(ArtificialStressPair, OffAndAtCrackFacesLeavesThePairAlone) {
  const double rho = 7850, h = 1.2e-3, m = 7.85e-3;
  const ArtificialStressParams<double> p = make_artificial_stress(0.3, 4, KernelKind::WendlandC2, 1.2, ArtificialStressOf::Total);
  const Sym3<double> A{3e8 / (rho * rho), -1e8 / (rho * rho), 5e7 / (rho * rho), 1e8 / (rho * rho), 0, 0};
  const PairSide<double> bare{A.full(), Mat3<double>::identity(), 0.0, 1, 5000, rho, false, Mat3<double>::zero()};
  const PairSide<double> with_r{A.full(), Mat3<double>::identity(), 0.0, 1, 5000, rho, false, artificial_stress(p, A).full()};
  const Vec3<double> xij{-0.8e-3, 0.2e-3, 0}, vij{3, 1, 0};
  const Vec3<double> gw = kernel_grad(KernelKind::WendlandC2, xij, h);
  const ViscosityParams<double> visc{1, 1};
  Vec3<double> a{0, 0, 0}, b{0, 0, 0};
  double da = 0, db = 0;
  add_momentum_energy_pair(bare, bare, visc, gw, xij, vij, h, m, 0.0, a, da);
  add_momentum_energy_pair(with_r, with_r, visc, gw, xij, vij, h, m, 0.0, b, db);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(da, db);
  PairSide<double> face = with_r;
  face.crack_face = true;
  face.damage = 1.0;
  PairSide<double> face_bare = bare;
  face_bare.crack_face = true;
  face_bare.damage = 1.0;
  a = b = Vec3<double>{0, 0, 0};
  add_momentum_energy_pair(with_r, face, visc, gw, xij, vij, h, m, 2.0, a, da);
  add_momentum_energy_pair(bare, face_bare, visc, gw, xij, vij, h, m, 0.0, b, db);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
}

}  // namespace

namespace {

using namespace impactsph;

// The limited viscosity in the pair term: off, it is the bits of the plain Monaghan term; on, a pair in a
// linear field gets none; an opening pair gets none whatever its reconstruction says; the pair stays equal
// and opposite, and its viscous heat is non-negative.
TEST(LimitedViscosityPair, LinearFieldOpeningPairsAndConservation) {
  const double rho = 8900, h = 1.2e-3, mi = 7.85e-3, mj = 8.2e-3;
  const Sym3<double> A{-1e9 / (rho * rho), -1e9 / (rho * rho), -1e9 / (rho * rho), 0, 0, 0};
  const Mat3<double> G{{{-2e4, 3e4, 0}, {5e3, 1.5e4, 0}, {0, 0, 5e3}}};
  PairSide<double> i{A.full(), Mat3<double>::identity(), 0.0, 1, 4000, rho, false, Mat3<double>::zero(), G};
  PairSide<double> j = i;
  const ViscosityParams<double> plain = limited_viscosity_params(1.0, 1.0, false, 1.2);
  const ViscosityParams<double> lim = limited_viscosity_params(1.0, 1.0, true, 1.2);
  const ViscosityParams<double> none{0, 0};
  const Vec3<double> xij{1e-3, 0.2e-3, 0};
  const Vec3<double> gw = kernel_grad(KernelKind::WendlandC2, xij, h);
  auto pair = [&](const PairSide<double>& a, const PairSide<double>& b, const ViscosityParams<double>& v, Vec3<double> x,
                  Vec3<double> g, Vec3<double> u, double m, Vec3<double>& acc, double& de) {
    acc = Vec3<double>{0, 0, 0};
    de = 0;
    add_momentum_energy_pair(a, b, v, g, x, u, h, m, 0.0, acc, de);
  };
  Vec3<double> a_plain, a_lim, a_none;
  double d_plain, d_lim, d_none;
  const Vec3<double> vlin = G * xij;  // closing: x . G x < 0
  ASSERT_LT(dot(vlin, xij), 0.0);
  pair(i, j, plain, xij, gw, vlin, mj, a_plain, d_plain);
  pair(i, j, lim, xij, gw, vlin, mj, a_lim, d_lim);
  pair(i, j, none, xij, gw, vlin, mj, a_none, d_none);
  EXPECT_GT(norm(a_plain - a_none), 1e-3 * norm(a_none));  // the plain term resists the linear flow
  EXPECT_LT(norm(a_lim - a_none), 1e-9 * norm(a_none));     // the limited one does not
  // plain bits when off, whatever grad v the sides carry
  PairSide<double> i0 = i, j0 = j;
  i0.grad_v = j0.grad_v = Mat3<double>::zero();
  Vec3<double> a0;
  double d0;
  pair(i0, j0, plain, xij, gw, vlin, mj, a0, d0);
  EXPECT_EQ(a0.x, a_plain.x);
  EXPECT_EQ(d0, d_plain);
  // opening pair (v . x > 0) whose gradients would reconstruct a closing jump: no viscosity
  PairSide<double> ic = i, jc = j;
  ic.grad_v = jc.grad_v = Mat3<double>{{{2e5, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
  const Vec3<double> opening{5, 0, 0};
  pair(ic, jc, lim, xij, gw, opening, mj, a_lim, d_lim);
  pair(ic, jc, none, xij, gw, opening, mj, a_none, d_none);
  EXPECT_EQ(a_lim.x, a_none.x);
  // a non-affine closing pair: equal and opposite, energy conserved, heat non-negative
  const Vec3<double> vij{-40, 7, 3}, vi{-10, 2, 1};
  const Vec3<double> vj = vi - vij;
  Vec3<double> ai, aj;
  double dei, dej;
  pair(i, j, lim, xij, gw, vij, mj, ai, dei);
  pair(j, i, lim, -1.0 * xij, -1.0 * gw, -1.0 * vij, mi, aj, dej);
  EXPECT_LT(norm(mi * ai + mj * aj), 1e-12 * mi * norm(ai));
  EXPECT_LT(std::abs(mi * dot(ai, vi) + mj * dot(aj, vj) + mi * dei + mj * dej), 1e-12 * mi * norm(ai) * norm(vij));
  Vec3<double> ai_none, aj_none;
  double dei_none, dej_none;
  pair(i, j, none, xij, gw, vij, mj, ai_none, dei_none);
  pair(j, i, none, -1.0 * xij, -1.0 * gw, -1.0 * vij, mi, aj_none, dej_none);
  EXPECT_GT(mi * (dei - dei_none) + mj * (dej - dej_none), 0.0);  // the viscosity heats
}

}  // namespace
