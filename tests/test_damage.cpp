// Unit tests of common/damage.hpp and common/models/damage_*.hpp: Johnson-Cook failure strain (F eq 4.7)
// with the minimum failure strain of X eq 33, the damage increment of each damage model (F eqs 4.8-4.9, X
// eq 32), the failed-particle rule (no deviatoric stress, no tension), the damaged pair factor (F eq 4.10)
// and its use in the pass 1 gradient sums and the delta-SPH term.
//
// F Table 2 gives no Johnson-Cook failure constants for Weldox 460 E (F uses the critical plastic strain,
// eps_c = 0.3 target, 0.5 projectile). The failure-strain hand values use the tungsten alloy of X Table 2
// (D1 = 0, D2 = 0.33, D3 = -1.50, D4 = D5 = 0) and, for the rate and temperature factors, a made-up set (D1
// = 0.05, D2 = 0.5, D3 = -1.2, D4 = 0.02, D5 = 0.6). Hand values: 30-digit arithmetic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "common/damage.hpp"
#include "common/kernels.hpp"
#include "common/material.hpp"
#include "common/pair_terms.hpp"

namespace {

using namespace impactsph;

template <class Real>
class DamageTyped : public ::testing::Test {};
using DamageReals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(DamageTyped, DamageReals);

template <class Real> double rel_tol() { return std::is_same<Real, double>::value ? 1e-13 : 1e-6; }

template <class Real>
DamageParams<Real> tungsten_failure() {  // X Table 2
  DamageParams<Real> d;
  d.kind = DamageKind::JohnsonCook;
  d.johnson_cook.d1 = Real(0);
  d.johnson_cook.d2 = Real(0.33);
  d.johnson_cook.d3 = Real(-1.5);
  d.johnson_cook.d4 = Real(0);
  d.johnson_cook.d5 = Real(0);
  return d;
}

// sigma* = sigma_m / sigma_eq = -P / sigma_eq; 0 when sigma_eq is 0.
TYPED_TEST(DamageTyped, Triaxiality) {
  using Real = TypeParam;
  EXPECT_NEAR(double(stress_triaxiality(Real(-100e6), Real(300e6))), 1.0 / 3, rel_tol<Real>());  // uniaxial tension
  EXPECT_NEAR(double(stress_triaxiality(Real(100e6), Real(300e6))), -1.0 / 3, rel_tol<Real>());  // compression
  EXPECT_EQ(stress_triaxiality(Real(5e8), Real(0)), Real(0));
  EXPECT_EQ(stress_triaxiality(Real(0), Real(1e8)), Real(0));
}

// X Table 2 tungsten: eps_f = 0.33 exp(-1.5 sigma*): 0.33 at sigma* = 0, 0.200155117705169 at 1/3,
// 0.698610005482183 at -1/2, 0.0736329528489818 at 1. The minimum failure strain is a lower bound.
TYPED_TEST(DamageTyped, FailureStrainHandValuesAndMinimum) {
  using Real = TypeParam;
  const double tol = rel_tol<Real>();
  DamageParams<Real> d = tungsten_failure<Real>();
  auto ef = [&](double s) { return double(johnson_cook_failure_strain(d, Real(s), Real(1), Real(0))); };
  EXPECT_NEAR(ef(0), 0.33, tol);
  EXPECT_NEAR(ef(1.0 / 3), 0.200155117705169030, tol);
  EXPECT_NEAR(ef(-0.5), 0.698610005482182641, tol);
  EXPECT_NEAR(ef(1), 0.0736329528489818435, tol);
  // Decreasing with triaxiality (D3 < 0): tension fails sooner.
  EXPECT_GT(ef(-0.2), ef(0.2));
  d.johnson_cook.min_failure_strain = Real(0.25);
  EXPECT_EQ(ef(1.0 / 3), 0.25);      // bound active
  EXPECT_EQ(ef(1), 0.25);            // bound active
  EXPECT_NEAR(ef(0), 0.33, tol);     // bound inactive
  EXPECT_NEAR(ef(-0.5), 0.698610005482182641, tol);
  // Huge compression (sigma_eq -> 0 with P > 0): finite, and no 0 x inf when D2 = 0.
  EXPECT_TRUE(std::isfinite(ef(-1e9)));
  d.johnson_cook.d2 = 0;
  d.johnson_cook.d1 = Real(0.4);
  EXPECT_EQ(ef(-1e9), Real(0.4));
}

// Rate and temperature factors: (D1 + D2 exp(D3 s))(1 + D4 ln eps*)(1 + D5 T*), made-up constants, at
// s = -0.2, eps* = 1e4, T* = 0.4: 1.00678239867388747. eps* below 1 reads as 1; T* is clamped to [0, 1].
TYPED_TEST(DamageTyped, FailureStrainRateAndTemperature) {
  using Real = TypeParam;
  DamageParams<Real> d;
  d.kind = DamageKind::JohnsonCook;
  d.johnson_cook.d1 = Real(0.05);
  d.johnson_cook.d2 = Real(0.5);
  d.johnson_cook.d3 = Real(-1.2);
  d.johnson_cook.d4 = Real(0.02);
  d.johnson_cook.d5 = Real(0.6);
  EXPECT_NEAR(double(johnson_cook_failure_strain(d, Real(-0.2), Real(1e4), Real(0.4))), 1.00678239867388747,
              10 * rel_tol<Real>());
  const Real at1 = johnson_cook_failure_strain(d, Real(-0.2), Real(1), Real(0));
  EXPECT_EQ(johnson_cook_failure_strain(d, Real(-0.2), Real(0.01), Real(0)), at1);
  EXPECT_EQ(johnson_cook_failure_strain(d, Real(-0.2), Real(0), Real(0)), at1);
  EXPECT_EQ(johnson_cook_failure_strain(d, Real(-0.2), Real(1), Real(-0.5)), at1);
  EXPECT_EQ(johnson_cook_failure_strain(d, Real(-0.2), Real(1), Real(3)),
            johnson_cook_failure_strain(d, Real(-0.2), Real(1), Real(1)));
}

// Damage increments per model.
TYPED_TEST(DamageTyped, DamageIncrementPerModel) {
  using Real = TypeParam;
  MaterialParams<Real> m;
  m.room_temperature = Real(293);
  // None: never.
  m.damage.kind = DamageKind::None;
  EXPECT_EQ(damage_increment(m, Real(0.5), Real(5), Real(0), Real(-1e9), Real(1e8), Real(1e4), Real(293)), Real(0));
  // Critical plastic strain, Weldox target eps_c = 0.3 (F Table 2): D jumps to 1 at eps_p >= eps_c.
  m.damage.kind = DamageKind::CriticalPlasticStrain;
  m.damage.critical_plastic_strain.strain = Real(0.3);
  EXPECT_EQ(damage_increment(m, Real(0.01), Real(0.29), Real(0), Real(0), Real(5e8), Real(1e3), Real(293)), Real(0));
  EXPECT_EQ(damage_increment(m, Real(0.01), Real(0.3), Real(0), Real(0), Real(5e8), Real(1e3), Real(293)), Real(1));
  EXPECT_EQ(damage_increment(m, Real(0.01), Real(0.31), Real(0), Real(0), Real(5e8), Real(1e3), Real(293)), Real(1));
  // Johnson-Cook, tungsten (X Table 2): d_eps_p / eps_f; at sigma* = 1/3 (P = -100 MPa, sigma_eq = 300 MPa)
  // an increment of 0.01 gives 0.01/0.200155117705169 = 0.0499612506272766.
  m.damage = tungsten_failure<Real>();
  m.strength.reference_strain_rate = Real(1);
  EXPECT_NEAR(double(damage_increment(m, Real(0.01), Real(0.2), Real(0), Real(-100e6), Real(300e6), Real(1e3), Real(293))),
              0.0499612506272766105, 10 * rel_tol<Real>());
  EXPECT_EQ(damage_increment(m, Real(0), Real(0.2), Real(0), Real(-100e6), Real(300e6), Real(1e3), Real(293)), Real(0));
  // Rate and temperature reach the failure strain through the material (made-up constants as above):
  // eps_dot = 5 1/s over eps_dot0 = 5e-4 gives eps* = 1e4; T = 293 + 0.4 x 1507 K gives T* = 0.4.
  m.damage.johnson_cook.d1 = Real(0.05);
  m.damage.johnson_cook.d2 = Real(0.5);
  m.damage.johnson_cook.d3 = Real(-1.2);
  m.damage.johnson_cook.d4 = Real(0.02);
  m.damage.johnson_cook.d5 = Real(0.6);
  m.strength.reference_strain_rate = Real(5e-4);
  m.strength.melt_temperature = Real(1800);
  EXPECT_NEAR(double(damage_increment(m, Real(0.01), Real(0.2), Real(0), Real(0.2 * 300e6), Real(300e6), Real(5),
                                      Real(293 + 0.4 * 1507))),
              0.01 / 1.00678239867388747, 100 * rel_tol<Real>());
  // Unphysical constants with no minimum: eps_f <= 0 fails the particle at its first plastic step.
  m.damage.johnson_cook.d1 = Real(-1);
  m.damage.johnson_cook.d2 = Real(0);
  EXPECT_EQ(damage_increment(m, Real(1e-6), Real(1e-6), Real(0), Real(0), Real(1e8), Real(1), Real(293)), Real(1));
}

// Under a constant triaxiality (proportional loading) the Johnson-Cook damage reaches 1 when the plastic
// strain reaches eps_f: accumulate 1000 equal increments.
TEST(Damage, JohnsonCookDamageReachesOneAtFailureStrain) {
  MaterialParams<double> m;
  m.damage = tungsten_failure<double>();
  const double ef = 0.33 * std::exp(-1.5 / 3);
  const double dep = ef / 1000;
  double D = 0, eps_p = 0;
  int k = 0;
  for (; k < 2000 && D < 1 - 1e-9; ++k) {
    eps_p += dep;
    D = std::min(1.0, D + damage_increment(m, dep, eps_p, 0.0, -100e6, 300e6, 1e3, 293.0));
  }
  EXPECT_EQ(k, 1000);
  EXPECT_NEAR(eps_p, ef, 1e-12);
}

// A failed particle (D >= 1) carries no deviatoric stress and no tension; compression stays; D < 1 is
// untouched to the bit.
TYPED_TEST(DamageTyped, ApplyFailure) {
  using Real = TypeParam;
  const Sym3<Real> S0{Real(3e8), Real(-1e8), Real(-2e8), Real(5e7), Real(-4e7), Real(1e7)};
  Sym3<Real> S = S0;
  Real P = Real(-2e8);  // tension
  apply_failure(S, P, Real(1));
  EXPECT_EQ(ddot(S, S), Real(0));
  EXPECT_EQ(P, Real(0));
  S = S0;
  P = Real(3e9);  // compression
  apply_failure(S, P, Real(1));
  EXPECT_EQ(S.xx, Real(0));
  EXPECT_EQ(S.xy, Real(0));
  EXPECT_EQ(P, Real(3e9));
  S = S0;
  P = Real(-2e8);
  apply_failure(S, P, Real(0.999));
  EXPECT_EQ(S.xx, S0.xx);
  EXPECT_EQ(S.yz, S0.yz);
  EXPECT_EQ(P, Real(-2e8));
}

// 1 - (D_i + D_j)/2 clamped to [0, 1], symmetric.
TYPED_TEST(DamageTyped, DamagedPairFactor) {
  using Real = TypeParam;
  EXPECT_EQ(damaged_pair_factor(Real(0), Real(0)), Real(1));
  EXPECT_EQ(damaged_pair_factor(Real(1), Real(1)), Real(0));
  EXPECT_EQ(damaged_pair_factor(Real(1), Real(0)), Real(0.5));
  EXPECT_EQ(damaged_pair_factor(Real(0.5), Real(0.25)), Real(0.625));
  EXPECT_EQ(damaged_pair_factor(Real(0.25), Real(0.5)), Real(0.625));
  EXPECT_EQ(damaged_pair_factor(Real(1.5), Real(1.5)), Real(0));
  EXPECT_EQ(damaged_pair_factor(Real(-0.5), Real(-0.5)), Real(1));
}

// F 4.10 scales the kernel gradient of every interaction: a pair's share of the velocity and density
// gradient sums scales with 1 - D_ij, and so does its share of the damaged correction matrix that corrects
// them; its share of L (for pass 2, so that L^-1 does not undo the scaling there) does not. A failed pair
// (factor 0) adds to L only.
TYPED_TEST(DamageTyped, GradientPairScalesWithDamageFactor) {
  using Real = TypeParam;
  const Real vol = Real(1.25e-9);
  const Vec3<Real> gw{Real(3.0e5), Real(-1.0e5), Real(2.0e5)}, xij{Real(-1.0e-3), Real(0.5e-3), Real(-0.25e-3)};
  const Vec3<Real> vji{Real(12), Real(-4), Real(7)};
  const Real drho = Real(35);
  GradientSums<Real> intact = GradientSums<Real>::zero(), half = GradientSums<Real>::zero(),
                     failed = GradientSums<Real>::zero();
  add_gradient_pair(intact, vol, gw, xij, vji, drho, Real(0), Real(0), false);
  add_gradient_pair(half, vol, gw, xij, vji, drho, Real(1), Real(0), false);
  add_gradient_pair(failed, vol, gw, xij, vji, drho, Real(1), Real(1), false);
  const double tol = rel_tol<Real>();
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      EXPECT_EQ(half.L.m[a][b], intact.L.m[a][b]);
      EXPECT_EQ(failed.L.m[a][b], intact.L.m[a][b]);
      EXPECT_NE(intact.G.m[a][b], Real(0));
      EXPECT_NEAR(half.G.m[a][b], Real(0.5) * intact.G.m[a][b], tol * std::abs(intact.G.m[a][b]));
      EXPECT_EQ(failed.G.m[a][b], Real(0));
      EXPECT_EQ(intact.damaged_L().m[a][b], intact.L.m[a][b]);
      EXPECT_NEAR(half.damaged_L().m[a][b], Real(0.5) * intact.L.m[a][b], tol * std::abs(intact.L.m[a][b]));
      EXPECT_EQ(failed.damaged_L().m[a][b], Real(0));
    }
    EXPECT_NEAR(half.grad_rho[a], Real(0.5) * intact.grad_rho[a], tol * std::abs(intact.grad_rho[a]));
    EXPECT_EQ(failed.grad_rho[a], Real(0));
  }
  // The intact pair: G = V (v_j - v_i) (x) gw, grad_rho = V (rho_j - rho_i) gw (pair_terms.hpp).
  EXPECT_NEAR(intact.G.m[0][2], vol * vji.x * gw.z, tol * std::abs(vol * vji.x * gw.z));
  EXPECT_NEAR(intact.grad_rho.y, vol * drho * gw.y, tol * std::abs(vol * drho * gw.y));
}

// L_damaged is summed apart only from the first pair whose weight differs from L's (pair_terms.hpp). A
// row of intact pairs, then a half-damaged one, then intact ones again must give the same bits as summing
// both matrices over every pair: here summed by hand with accumulate_correction.
TYPED_TEST(DamageTyped, DamagedCorrectionSummedApartFromTheFirstScaledPair) {
  using Real = TypeParam;
  const Vec3<Real> vji{Real(1), Real(2), Real(3)};
  GradientSums<Real> sums = GradientSums<Real>::zero();
  Mat3<Real> L = Mat3<Real>::zero(), L_damaged = Mat3<Real>::zero();
  const Real damage_j[] = {Real(0), Real(0), Real(0.5), Real(0), Real(0.25)};
  for (int k = 0; k < 5; ++k) {
    const Real vol = Real(1.0e-9) * Real(1 + k);
    const Vec3<Real> gw{Real(3.0e5) - Real(1.0e4 * k), Real(-1.0e5), Real(2.0e5) + Real(3.0e3 * k)};
    const Vec3<Real> xij{Real(-1.0e-3), Real(0.5e-3) + Real(1.0e-5 * k), Real(-0.25e-3)};
    add_gradient_pair(sums, vol, gw, xij, vji, Real(0), Real(0), damage_j[k], false);
    accumulate_correction(L, vol, gw, xij);
    accumulate_correction(L_damaged, damaged_pair_factor(Real(0), damage_j[k]) * vol, gw, xij);
    EXPECT_EQ(sums.apart, k >= 2) << "pair " << k;
  }
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      EXPECT_EQ(sums.L.m[a][b], L.m[a][b]);
      EXPECT_EQ(sums.damaged_L().m[a][b], L_damaged.m[a][b]);
      EXPECT_NE(sums.damaged_L().m[a][b], sums.L.m[a][b]);
    }
}

// The delta-SPH share takes the same factor: half for an intact-failed pair, none for a failed pair.
TYPED_TEST(DamageTyped, DeltaSphPairScalesWithDamageFactor) {
  using Real = TypeParam;
  const Vec3<Real> gw{Real(3.0e5), Real(-1.0e5), Real(2.0e5)}, xij{Real(-1.0e-3), Real(0.5e-3), Real(-0.25e-3)};
  const Vec3<Real> gi{Real(1.0e4), Real(0), Real(-2.0e4)}, gj{Real(0), Real(3.0e4), Real(1.0e4)};
  const Real vol = Real(1.25e-9), ri = Real(7900), rj = Real(7850);
  const Real intact = delta_sph_term(vol, ri, rj, xij, gi, gj, gw);
  ASSERT_NE(intact, Real(0));
  EXPECT_EQ(damaged_delta_sph_term(Real(0), Real(0), vol, ri, rj, xij, gi, gj, gw), intact);
  EXPECT_NEAR(damaged_delta_sph_term(Real(0), Real(1), vol, ri, rj, xij, gi, gj, gw), Real(0.5) * intact,
              rel_tol<Real>() * std::abs(intact));
  EXPECT_EQ(damaged_delta_sph_term(Real(1), Real(1), vol, ri, rj, xij, gi, gj, gw), Real(0));
}

}  // namespace

// A particle beside a failed layer (pair_terms.hpp, add_gradient_pair): on a cubic lattice (spacing dx,
// h = 1.2 dx, Wendland C2) the particles at z >= dx above particle i have failed (D = 1), so its pairs with
// them count half. Corrected with the damaged correction matrix, the gradient of a linear velocity field
// v = A x + b is A, and a rigid rotation (A = [omega]x) has no strain rate. The unscaled L, which corrected
// the gradient before, gives the rotation a deviatoric rate of several percent of omega: the test checks
// that this configuration does expose it.
namespace {
struct LatticeGradients {
  Mat3<double> consistent, unscaled;
};
// slide: a velocity the failed layer has on top of the field (sliding past i); crack_faces: the failed
// layer is a crack face (crack_faces = "compression"), whose pairs leave the scaled sums.
LatticeGradients gradient_beside_failed_layer(const Mat3<double>& A, int failed_from_layer, Vec3<double> slide = {0, 0, 0},
                                              bool crack_faces = false) {
  const double dx = 1e-3, h = 1.2 * dx, vol = dx * dx * dx;
  const Vec3<double> b{3.0, -2.0, 1.0};
  const auto velocity = [&](Vec3<double> x) { return A * x + b; };
  const Vec3<double> xi{0.1 * dx, -0.2 * dx, 0.05 * dx};  // off the lattice's symmetry
  GradientSums<double> sums = GradientSums<double>::zero();
  for (int a = -3; a <= 3; ++a)
    for (int c = -3; c <= 3; ++c)
      for (int k = -3; k <= 3; ++k) {
        if (a == 0 && c == 0 && k == 0) continue;
        const Vec3<double> xj = xi + Vec3<double>{a * dx, c * dx, k * dx};
        const Vec3<double> xij = xi - xj;
        const double r = norm(xij);
        if (!(r < kernel_support(h))) continue;
        const Vec3<double> gw = kernel_grad_factor_of<KernelKind::WendlandC2>(r, h) * xij;
        const double dj = k >= failed_from_layer ? 1.0 : 0.0;
        const Vec3<double> vj = dj >= 1.0 ? velocity(xj) + slide : velocity(xj);
        add_gradient_pair(sums, vol, gw, xij, vj - velocity(xi), 0.0, 0.0, dj, crack_faces && dj >= 1.0);
      }
  LatticeGradients g;
  g.consistent = corrected_gradients(sums, CorrectionParams<double>{}).grad_v;
  bool fell_back = true;
  g.unscaled = sums.G * correction_inverse(sums.L, CorrectionParams<double>{}, fell_back).transpose();
  EXPECT_FALSE(fell_back);
  return g;
}
double deviatoric_rate_norm(const Mat3<double>& grad_v) {
  const Mat3<double> d = 0.5 * (grad_v + grad_v.transpose());
  const double m = d.trace() / 3;
  double s = 0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const double e = d.m[r][c] - (r == c ? m : 0.0);
      s += e * e;
    }
  return std::sqrt(s);
}
}  // namespace

TEST(DamagedGradient, IntactParticleDoesNotStrainWithASlidingCrackFace) {
  const double omega = 1e4;  // 1/s
  Mat3<double> A = Mat3<double>::zero();
  A.m[0][1] = -omega; A.m[1][0] = omega;
  A.m[0][0] = 0.3 * omega;
  const Vec3<double> slide{50.0, 0.0, 0.0};  // m/s, the failed layer above i slides along x
  const LatticeGradients faces = gradient_beside_failed_layer(A, 1, slide, true);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(faces.consistent.m[r][c], A.m[r][c], 1e-10 * omega);
  // Under F 4.10 the half-weight pairs make i shear with the sliding layer: dv_x/dz of order slide / dx.
  const LatticeGradients scaled = gradient_beside_failed_layer(A, 1, slide, false);
  EXPECT_GT(std::abs(scaled.consistent.m[0][2]), 0.1 * 50.0 / 1e-3);
}

TEST(DamagedGradient, RigidRotationBesideFailedLayerHasNoStrainRate) {
  const double omega = 1e4;  // 1/s, about z and x
  Mat3<double> A = Mat3<double>::zero();
  A.m[0][1] = -omega; A.m[1][0] = omega;
  A.m[1][2] = -0.5 * omega; A.m[2][1] = 0.5 * omega;
  const LatticeGradients g = gradient_beside_failed_layer(A, 1);
  EXPECT_LT(deviatoric_rate_norm(g.consistent), 1e-10 * omega);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(g.consistent.m[r][c], A.m[r][c], 1e-10 * omega);
  EXPECT_GT(deviatoric_rate_norm(g.unscaled), 0.01 * omega);
}

TEST(DamagedGradient, LinearFieldExactAtIntactParticleBesideFailedLayer) {
  Mat3<double> A = Mat3<double>::zero();
  const double rows[3][3] = {{2e3, -5e2, 7e2}, {1e2, -3e3, 4e2}, {-6e2, 8e2, 1.5e3}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) A.m[r][c] = rows[r][c];
  for (int layer : {1, 2, 4}) {  // 4: no neighbour has failed (the support is 2.4 dx)
    const LatticeGradients g = gradient_beside_failed_layer(A, layer);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(g.consistent.m[r][c], A.m[r][c], 1e-10 * 3e3) << "layer " << layer;
  }
}

// Crack-band criterion (common/models/damage_fracture_energy.hpp): W_c = Gamma / (k h0), and D jumps to 1 once rho0 w_p reaches it.
TEST(FractureEnergy, FailsAtCriticalWorkOfBandWidth) {
  MaterialParams<double> m;
  m.eos.rho0 = 7850;
  m.damage.kind = DamageKind::FractureEnergy;
  m.damage.fracture_energy.gamma = 2.0e5;   // J/m^2
  m.damage.fracture_energy.band_width_factor = 2.0;   // band of 2 h0
  const double h0 = 1.2e-3;
  m.damage.fracture_energy.critical_work = fracture_energy_critical_work(m.damage, h0);
  EXPECT_NEAR(m.damage.fracture_energy.critical_work, 2.0e5 / (2.0 * 1.2e-3), 1e-6);
  const double w_c = m.damage.fracture_energy.critical_work / m.eos.rho0;  // J/kg
  EXPECT_EQ(damage_increment(m, 0.01, 0.5, 0.999 * w_c, 0.0, 5e8, 1e3, 293.0), 0.0);
  EXPECT_EQ(damage_increment(m, 0.01, 0.5, w_c, 0.0, 5e8, 1e3, 293.0), 1.0);
  // No failure on an elastic step, nor while W_c is unset (a material the scene has not sized).
  EXPECT_EQ(damage_increment(m, 0.0, 0.5, w_c, 0.0, 5e8, 1e3, 293.0), 0.0);
  MaterialParams<double> unsized = m;
  unsized.damage.fracture_energy.critical_work = 0;
  EXPECT_EQ(damage_increment(unsized, 0.01, 0.0, 0.0, 0.0, 5e8, 1e3, 293.0), 0.0);
  // Halving h0 doubles the work density at failure: the energy per unit area, W_c k h0, stays Gamma.
  EXPECT_NEAR(fracture_energy_critical_work(m.damage, 0.5 * h0) * m.damage.fracture_energy.band_width_factor * 0.5 * h0, 2.0e5, 1e-6);
}

// At the spacing where Gamma = W_p(eps_c) k h0, the fracture-energy criterion fails a particle on the same
// step as the critical plastic strain eps_c = 0.3 (F 4.9): Weldox 460 E (F Table 2) in uniaxial-like
// straining at 1e4 /s, elastic predictor and radial return of plastic_update, finish_step's sums.
TEST(FractureEnergy, ReducesToCriticalPlasticStrainAtTheMatchingGamma) {
  MaterialParams<double> m;
  m.eos.kind = EosKind::MieGruneisen;
  m.eos.rho0 = 7850; m.eos.c0 = 5047.6; m.eos.s1 = 1.5; m.eos.gamma0 = 2.0;
  m.strength.kind = StrengthKind::JohnsonCook;
  m.strength.shear_modulus = 200e9 / (2 * 1.33);
  m.strength.johnson_cook.a = 490e6; m.strength.johnson_cook.b = 807e6; m.strength.johnson_cook.n = 0.73; m.strength.johnson_cook.c = 0.0114;
  m.strength.reference_strain_rate = 5e-4;
  const double rate = 1e4, dt = 2e-8;
  // One strain path, returning the step on which each model fails and the work at eps_p = 0.3.
  const auto first_failure = [&](const MaterialParams<double>& mat, double& w_at_eps_c) {
    Sym3<double> S = Sym3<double>::zero();
    double eps_p = 0, w_p = 0, D = 0;
    w_at_eps_c = 0;
    for (int step = 1; step < 200000; ++step) {
      Sym3<double> dS = Sym3<double>::zero();
      dS.xx = 2 * mat.strength.shear_modulus * rate * dt * (2.0 / 3.0);
      dS.yy = dS.zz = -0.5 * dS.xx;
      S = S + dS;
      const PlasticResult<double> pr = plastic_update(mat, S, eps_p, rate, 293.0, m.eos.rho0, D, 0.0);
      eps_p += pr.d_eps_p;
      w_p += pr.plastic_work;
      if (w_at_eps_c == 0 && eps_p >= 0.3) w_at_eps_c = w_p;
      D = std::min(1.0, D + damage_increment(mat, pr.d_eps_p, eps_p, w_p, 0.0, von_mises(S), rate, 293.0));
      if (D >= 1) return step;
    }
    return -1;
  };
  MaterialParams<double> critical = m;
  critical.damage.kind = DamageKind::CriticalPlasticStrain;
  critical.damage.critical_plastic_strain.strain = 0.3;
  double w_c = 0;
  const int step_critical = first_failure(critical, w_c);
  ASSERT_GT(step_critical, 0);
  ASSERT_GT(w_c, 0);
  const double h0_2mm = 1.2 * 2e-3;
  MaterialParams<double> band = m;
  band.damage.kind = DamageKind::FractureEnergy;
  band.damage.fracture_energy.band_width_factor = 2.0;
  band.damage.fracture_energy.gamma = m.eos.rho0 * w_c * band.damage.fracture_energy.band_width_factor * h0_2mm;
  band.damage.fracture_energy.critical_work = fracture_energy_critical_work(band.damage, h0_2mm);
  double unused = 0;
  EXPECT_EQ(first_failure(band, unused), step_critical);
  // At 1 mm the same Gamma asks for twice the work: the particle fails later, at a larger plastic strain.
  band.damage.fracture_energy.critical_work = fracture_energy_critical_work(band.damage, 0.5 * h0_2mm);
  EXPECT_GT(first_failure(band, unused), step_critical);
}

namespace {

using namespace impactsph;

// A pair across a crack face (crack_faces = "compression", pair_terms.hpp): an intact particle i in shear
// and tension beside a failed j. Under F 4.10 the pair carries i's shear at half weight; at a crack face it
// carries only the compressive mean stresses, so a tensile or sheared i exerts nothing on j and a
// compressed i pushes along the pair's own (mean-stress) direction; the pair stays equal and opposite.
TEST(CrackFace, CarriesOnlyCompressionAcrossAFailedParticle) {
  const double rho = 7850;
  Mat3<double> shear_tension = Mat3<double>::zero();  // S_xy = 200 MPa, P = -100 MPa (tension)
  shear_tension.m[0][1] = shear_tension.m[1][0] = 2e8 / (rho * rho);
  for (int d = 0; d < 3; ++d) shear_tension.m[d][d] = 1e8 / (rho * rho);
  Mat3<double> failed_compressed = Mat3<double>::zero();  // P = 50 MPa, no deviator (apply_failure)
  for (int d = 0; d < 3; ++d) failed_compressed.m[d][d] = -5e7 / (rho * rho);
  const ViscosityParams<double> no_visc{0, 0};
  const Vec3<double> xij{-1e-3, 0, 0}, vij{0, 0, 0}, gw{2e6, 0, 0};
  const double h = 1.3e-3, m = 7.85e-3;
  const auto pair = [&](const Mat3<double>& Ai, const Mat3<double>& Aj, bool faces, Vec3<double>& on_i, Vec3<double>& on_j) {
    const PairSide<double> i{Ai, Mat3<double>::identity(), 0.0, 1, 5000, rho, false};
    const PairSide<double> j{Aj, Mat3<double>::identity(), 1.0, 1, 5000, rho, faces};
    double de = 0;
    on_i = Vec3<double>{0, 0, 0};
    on_j = Vec3<double>{0, 0, 0};
    add_momentum_energy_pair(i, j, no_visc, gw, xij, vij, h, m, 0.0, on_i, de);
    add_momentum_energy_pair(j, i, no_visc, -1.0 * gw, -1.0 * xij, -1.0 * vij, h, m, 0.0, on_j, de);
  };
  Vec3<double> on_i, on_j;
  pair(shear_tension, failed_compressed, false, on_i, on_j);
  EXPECT_GT(std::abs(on_i.y), 1.0) << "F 4.10 carries i's shear across the failed particle";
  pair(shear_tension, failed_compressed, true, on_i, on_j);
  EXPECT_EQ(on_i.y, 0.0);
  EXPECT_EQ(on_i.z, 0.0);
  // Only j's 50 MPa pressure remains: m (-P_j / rho^2) gt with gt = (1 - 1/2) gw.
  EXPECT_NEAR(on_i.x, m * (-5e7 / (rho * rho)) * 0.5 * gw.x, 1e-12 * std::abs(on_i.x));
  EXPECT_NEAR(on_i.x + on_j.x, 0.0, 1e-12 * std::abs(on_i.x));
  // Either side may be the face: the same pair seen from j.
  const PairSide<double> i{shear_tension, Mat3<double>::identity(), 0.0, 1, 5000, rho, false};
  const PairSide<double> j{failed_compressed, Mat3<double>::identity(), 1.0, 1, 5000, rho, true};
  Vec3<double> a{0, 0, 0}, b{0, 0, 0};
  double de = 0;
  add_momentum_energy_pair(i, j, no_visc, gw, xij, vij, h, m, 0.0, a, de);
  add_momentum_energy_pair(j, i, no_visc, gw, xij, vij, h, m, 0.0, b, de);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
}

TEST(CrackFace, OnlyFailedParticlesOfMaterialsThatAskForIt) {
  MaterialParams<double> m[2];
  m[0].damage.kind = m[1].damage.kind = DamageKind::FractureEnergy;
  m[1].damage.compressive_crack_faces = true;
  EXPECT_FALSE(compressive_crack_face(m, 0, 1.0));
  EXPECT_TRUE(compressive_crack_face(m, 1, 1.0));
  EXPECT_FALSE(compressive_crack_face(m, 1, 0.999));
  MaterialParams<double> unscaled = m[1];  // pair_factor = false: its pair damage is 0, so never a face
  unscaled.damage.scale_pairs = false;
  EXPECT_FALSE(compressive_crack_face(&unscaled, 0, pair_damage(unscaled, 1.0)));
}

}  // namespace
