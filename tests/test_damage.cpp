// Unit tests of common/damage.hpp: Johnson-Cook failure strain (F eq 4.7) with the minimum failure strain
// of X eq 33, the damage increment of each damage model (F eqs 4.8-4.9, X eq 32), the failed-particle
// rule (no deviatoric stress, no tension), the damaged pair factor (F eq 4.10) and its use in the pass 1
// gradient sums and the delta-SPH term.
//
// F Table 2 gives no Johnson-Cook failure constants for Weldox 460 E (F uses the critical plastic strain,
// eps_c = 0.3 target, 0.5 projectile). The failure-strain hand values use the tungsten alloy of X Table 2
// (D1 = 0, D2 = 0.33, D3 = -1.50, D4 = D5 = 0) and, for the rate and temperature factors, a made-up set
// (D1 = 0.05, D2 = 0.5, D3 = -1.2, D4 = 0.02, D5 = 0.6). Hand values: 30-digit arithmetic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "common/damage.hpp"
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
  d.d1 = Real(0);
  d.d2 = Real(0.33);
  d.d3 = Real(-1.5);
  d.d4 = Real(0);
  d.d5 = Real(0);
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
  d.min_failure_strain = Real(0.25);
  EXPECT_EQ(ef(1.0 / 3), 0.25);      // bound active
  EXPECT_EQ(ef(1), 0.25);            // bound active
  EXPECT_NEAR(ef(0), 0.33, tol);     // bound inactive
  EXPECT_NEAR(ef(-0.5), 0.698610005482182641, tol);
  // Huge compression (sigma_eq -> 0 with P > 0): finite, and no 0 x inf when D2 = 0.
  EXPECT_TRUE(std::isfinite(ef(-1e9)));
  d.d2 = 0;
  d.d1 = Real(0.4);
  EXPECT_EQ(ef(-1e9), Real(0.4));
}

// Rate and temperature factors: (D1 + D2 exp(D3 s))(1 + D4 ln eps*)(1 + D5 T*), made-up constants, at
// s = -0.2, eps* = 1e4, T* = 0.4: 1.00678239867388747. eps* below 1 reads as 1; T* is clamped to [0, 1].
TYPED_TEST(DamageTyped, FailureStrainRateAndTemperature) {
  using Real = TypeParam;
  DamageParams<Real> d;
  d.kind = DamageKind::JohnsonCook;
  d.d1 = Real(0.05);
  d.d2 = Real(0.5);
  d.d3 = Real(-1.2);
  d.d4 = Real(0.02);
  d.d5 = Real(0.6);
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
  EXPECT_EQ(damage_increment(m, Real(0.5), Real(5), Real(-1e9), Real(1e8), Real(1e4), Real(293)), Real(0));
  // Critical plastic strain, Weldox target eps_c = 0.3 (F Table 2): D jumps to 1 at eps_p >= eps_c.
  m.damage.kind = DamageKind::CriticalPlasticStrain;
  m.damage.critical_plastic_strain = Real(0.3);
  EXPECT_EQ(damage_increment(m, Real(0.01), Real(0.29), Real(0), Real(5e8), Real(1e3), Real(293)), Real(0));
  EXPECT_EQ(damage_increment(m, Real(0.01), Real(0.3), Real(0), Real(5e8), Real(1e3), Real(293)), Real(1));
  EXPECT_EQ(damage_increment(m, Real(0.01), Real(0.31), Real(0), Real(5e8), Real(1e3), Real(293)), Real(1));
  // Johnson-Cook, tungsten (X Table 2): d_eps_p / eps_f; at sigma* = 1/3 (P = -100 MPa, sigma_eq = 300 MPa)
  // an increment of 0.01 gives 0.01/0.200155117705169 = 0.0499612506272766.
  m.damage = tungsten_failure<Real>();
  m.strength.reference_strain_rate = Real(1);
  EXPECT_NEAR(double(damage_increment(m, Real(0.01), Real(0.2), Real(-100e6), Real(300e6), Real(1e3), Real(293))),
              0.0499612506272766105, 10 * rel_tol<Real>());
  EXPECT_EQ(damage_increment(m, Real(0), Real(0.2), Real(-100e6), Real(300e6), Real(1e3), Real(293)), Real(0));
  // Rate and temperature reach the failure strain through the material (made-up constants as above):
  // eps_dot = 5 1/s over eps_dot0 = 5e-4 gives eps* = 1e4; T = 293 + 0.4 x 1507 K gives T* = 0.4.
  m.damage.d1 = Real(0.05);
  m.damage.d2 = Real(0.5);
  m.damage.d3 = Real(-1.2);
  m.damage.d4 = Real(0.02);
  m.damage.d5 = Real(0.6);
  m.strength.reference_strain_rate = Real(5e-4);
  m.strength.melt_temperature = Real(1800);
  EXPECT_NEAR(double(damage_increment(m, Real(0.01), Real(0.2), Real(0.2 * 300e6), Real(300e6), Real(5),
                                      Real(293 + 0.4 * 1507))),
              0.01 / 1.00678239867388747, 100 * rel_tol<Real>());
  // Unphysical constants with no minimum: eps_f <= 0 fails the particle at its first plastic step.
  m.damage.d1 = Real(-1);
  m.damage.d2 = Real(0);
  EXPECT_EQ(damage_increment(m, Real(1e-6), Real(1e-6), Real(0), Real(1e8), Real(1), Real(293)), Real(1));
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
    D = std::min(1.0, D + damage_increment(m, dep, eps_p, -100e6, 300e6, 1e3, 293.0));
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
// gradient sums scales with 1 - D_ij, its share of the correction matrix does not (so that L^-1 does not
// undo the scaling). A failed pair (factor 0) adds to L only.
TYPED_TEST(DamageTyped, GradientPairScalesWithDamageFactor) {
  using Real = TypeParam;
  const Real vol = Real(1.25e-9);
  const Vec3<Real> gw{Real(3.0e5), Real(-1.0e5), Real(2.0e5)}, xij{Real(-1.0e-3), Real(0.5e-3), Real(-0.25e-3)};
  const Vec3<Real> vji{Real(12), Real(-4), Real(7)};
  const Real drho = Real(35);
  GradientSums<Real> intact = GradientSums<Real>::zero(), half = GradientSums<Real>::zero(),
                     failed = GradientSums<Real>::zero();
  add_gradient_pair(intact, vol, gw, xij, vji, drho, Real(0), Real(0));
  add_gradient_pair(half, vol, gw, xij, vji, drho, Real(1), Real(0));
  add_gradient_pair(failed, vol, gw, xij, vji, drho, Real(1), Real(1));
  const double tol = rel_tol<Real>();
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      EXPECT_EQ(half.L.m[a][b], intact.L.m[a][b]);
      EXPECT_EQ(failed.L.m[a][b], intact.L.m[a][b]);
      EXPECT_NE(intact.G.m[a][b], Real(0));
      EXPECT_NEAR(half.G.m[a][b], Real(0.5) * intact.G.m[a][b], tol * std::abs(intact.G.m[a][b]));
      EXPECT_EQ(failed.G.m[a][b], Real(0));
    }
    EXPECT_NEAR(half.grad_rho[a], Real(0.5) * intact.grad_rho[a], tol * std::abs(intact.grad_rho[a]));
    EXPECT_EQ(failed.grad_rho[a], Real(0));
  }
  // The intact pair: G = V (v_j - v_i) (x) gw, grad_rho = V (rho_j - rho_i) gw (pair_terms.hpp).
  EXPECT_NEAR(intact.G.m[0][2], vol * vji.x * gw.z, tol * std::abs(vol * vji.x * gw.z));
  EXPECT_NEAR(intact.grad_rho.y, vol * drho * gw.y, tol * std::abs(vol * drho * gw.y));
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
