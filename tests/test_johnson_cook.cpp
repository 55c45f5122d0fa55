// Unit tests of the Johnson-Cook flow stress (F eqs 3.12-3.13, X eq 29;
// common/models/strength_johnson_cook.hpp), of equivalent_strain_rate, and of the plastic step
// plastic_update (radial return F eqs 3.8-3.11 as corrected in physics-notes, adiabatic heating F eq 3.14).
//
// Weldox 460 E constants: A = 490 MPa, B = 807 MPa, n = 0.73, C = 0.0114 from F Table 2. F Table 2 gives
// neither the reference strain rate nor the thermal constants (F neglects thermal effects); the values used
// here, eps_dot0 = 5e-4 1/s, m = 0.94, T_melt = 1800 K, T_room = 293 K, c_p = 452 J/(kg K), are those of
// Borvik et al. (2001) for the same steel. Hand values below were computed with 30-digit arithmetic.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <type_traits>

#include "common/material.hpp"
#include "common/strength.hpp"

namespace {

using namespace impactsph;

template <class Real>
class JohnsonCookTyped : public ::testing::Test {};
using JohnsonCookReals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(JohnsonCookTyped, JohnsonCookReals);

// Relative tolerance of a few roundings: 1e-12 in double (as asked), 1e-5 in float.
template <class Real> double rel_tol() { return std::is_same<Real, double>::value ? 1e-12 : 1e-5; }

constexpr double kRoom = 293.0;

template <class Real>
StrengthParams<Real> weldox_strength() {
  StrengthParams<Real> p;
  p.kind = StrengthKind::JohnsonCook;
  p.shear_modulus = Real(200e9 / (2 * 1.33));  // E = 200 GPa, nu = 0.33 (F Table 2)
  p.johnson_cook.a = Real(490e6);
  p.johnson_cook.b = Real(807e6);
  p.johnson_cook.n = Real(0.73);
  p.johnson_cook.c = Real(0.0114);
  p.johnson_cook.m = Real(0.94);
  p.reference_strain_rate = Real(5e-4);
  p.melt_temperature = Real(1800);
  p.taylor_quinney = Real(0.9);
  return p;
}

template <class Real>
MaterialParams<Real> weldox_material() {
  MaterialParams<Real> m;
  m.eos.rho0 = Real(7850);
  m.strength = weldox_strength<Real>();
  m.specific_heat = Real(452);
  m.room_temperature = Real(kRoom);
  return m;
}

// At eps_p = 0, the reference rate and room temperature every factor is 1: the flow stress is A, exactly.
TYPED_TEST(JohnsonCookTyped, InitialYieldIsA) {
  using Real = TypeParam;
  const StrengthParams<Real> p = weldox_strength<Real>();
  EXPECT_EQ(johnson_cook_yield(p, Real(0), p.reference_strain_rate, Real(kRoom), Real(kRoom)), p.johnson_cook.a);
  // No NaN from pow(0, n) or log(0): zero rate and zero plastic strain.
  EXPECT_EQ(johnson_cook_yield(p, Real(0), Real(0), Real(kRoom), Real(kRoom)), p.johnson_cook.a);
  // A negative plastic strain (never produced, but not a NaN either) reads as 0.
  EXPECT_EQ(johnson_cook_yield(p, Real(-1e-3), Real(0), Real(kRoom), Real(kRoom)), p.johnson_cook.a);
  // n = 0: eps_p^0 = 1 for every eps_p >= 0, including its limit at 0 (A + B throughout, no jump).
  StrengthParams<Real> flat = p;
  flat.johnson_cook.n = 0;
  EXPECT_EQ(johnson_cook_yield(flat, Real(0), Real(0), Real(kRoom), Real(kRoom)), p.johnson_cook.a + p.johnson_cook.b);
  EXPECT_EQ(johnson_cook_yield(flat, Real(0.3), Real(0), Real(kRoom), Real(kRoom)), p.johnson_cook.a + p.johnson_cook.b);
}

// Hand values for Weldox 460 E (F Table 2 constants, see the file comment):
//   eps_p = 0.1, rate 1000 1/s, T = room: (490 + 807 0.1^0.73)(1 + 0.0114 ln 2e6) MPa = 746.170327877929 MPa;
//   same at T = 600 K: times 1 - ((600-293)/(1800-293))^0.94, 578.937478032938 MPa;
//   eps_p = 0.25 at the reference rate, room T: 490 + 807 0.25^0.73 MPa = 783.338955369373 MPa.
TYPED_TEST(JohnsonCookTyped, WeldoxHandValues) {
  using Real = TypeParam;
  const StrengthParams<Real> p = weldox_strength<Real>();
  const double tol = rel_tol<Real>();
  EXPECT_NEAR(double(johnson_cook_yield(p, Real(0.1), Real(1000), Real(kRoom), Real(kRoom))), 746.170327877928898e6,
              tol * 746e6);
  EXPECT_NEAR(double(johnson_cook_yield(p, Real(0.1), Real(1000), Real(600), Real(kRoom))), 578.937478032937935e6,
              tol * 579e6);
  EXPECT_NEAR(double(johnson_cook_yield(p, Real(0.25), Real(5e-4), Real(kRoom), Real(kRoom))), 783.338955369372653e6,
              tol * 783e6);
}

// Strain hardening: strictly increasing in eps_p (B > 0, n > 0); rate hardening: non-decreasing in the rate,
// strictly above the reference; thermal softening: strictly decreasing between room and melt.
TYPED_TEST(JohnsonCookTyped, MonotoneInStrainRateAndTemperature) {
  using Real = TypeParam;
  const StrengthParams<Real> p = weldox_strength<Real>();
  Real prev = johnson_cook_yield(p, Real(0), Real(1), Real(kRoom), Real(kRoom));
  for (int k = 1; k <= 400; ++k) {
    const Real eps = Real(k) * Real(0.005);
    const Real s = johnson_cook_yield(p, eps, Real(1), Real(kRoom), Real(kRoom));
    EXPECT_GT(s, prev) << "eps_p " << eps;
    prev = s;
  }
  prev = johnson_cook_yield(p, Real(0.1), Real(5e-4), Real(kRoom), Real(kRoom));
  for (double rate = 1e-3; rate < 1e7; rate *= 10) {
    const Real s = johnson_cook_yield(p, Real(0.1), Real(rate), Real(kRoom), Real(kRoom));
    EXPECT_GT(s, prev) << "rate " << rate;
    prev = s;
  }
  prev = johnson_cook_yield(p, Real(0.1), Real(1), Real(kRoom), Real(kRoom));
  for (double T = kRoom + 50; T < 1800; T += 50) {
    const Real s = johnson_cook_yield(p, Real(0.1), Real(1), Real(T), Real(kRoom));
    EXPECT_LT(s, prev) << "T " << T;
    prev = s;
  }
}

// T* clamped to [0, 1]: zero strength at and above the melt; no extra strength below room temperature;
// melt_temperature = 0 turns thermal softening off.
TYPED_TEST(JohnsonCookTyped, TemperatureClampAndMelt) {
  using Real = TypeParam;
  StrengthParams<Real> p = weldox_strength<Real>();
  EXPECT_EQ(johnson_cook_yield(p, Real(0.2), Real(100), Real(1800), Real(kRoom)), Real(0));
  EXPECT_EQ(johnson_cook_yield(p, Real(0.2), Real(100), Real(2500), Real(kRoom)), Real(0));
  const Real at_room = johnson_cook_yield(p, Real(0.2), Real(100), Real(kRoom), Real(kRoom));
  EXPECT_GT(at_room, Real(0));
  EXPECT_EQ(johnson_cook_yield(p, Real(0.2), Real(100), Real(77), Real(kRoom)), at_room);
  EXPECT_EQ(homologous_temperature(Real(1046.5), Real(kRoom), Real(1800)), Real(0.5));
  EXPECT_EQ(homologous_temperature(Real(77), Real(kRoom), Real(1800)), Real(0));
  EXPECT_EQ(homologous_temperature(Real(2500), Real(kRoom), Real(1800)), Real(1));
  p.melt_temperature = 0;
  EXPECT_EQ(johnson_cook_yield(p, Real(0.2), Real(100), Real(1500), Real(kRoom)), at_room);
  EXPECT_EQ(homologous_temperature(Real(1500), Real(kRoom), Real(0)), Real(0));
}

// eps_dot* = max(eps_rate/eps_dot0, 1): any rate at or below the reference gives the reference value.
TYPED_TEST(JohnsonCookTyped, NoRateSofteningBelowReference) {
  using Real = TypeParam;
  const StrengthParams<Real> p = weldox_strength<Real>();
  const Real at_ref = johnson_cook_yield(p, Real(0.1), Real(5e-4), Real(kRoom), Real(kRoom));
  for (double rate : {0.0, 1e-9, 1e-5, 4.9e-4, 5e-4})
    EXPECT_EQ(johnson_cook_yield(p, Real(0.1), Real(rate), Real(kRoom), Real(kRoom)), at_ref) << rate;
  EXPECT_GT(johnson_cook_yield(p, Real(0.1), Real(1e-3), Real(kRoom), Real(kRoom)), at_ref);
  EXPECT_EQ(johnson_cook_rate_ratio(Real(1e-6), Real(5e-4)), Real(1));
  EXPECT_EQ(johnson_cook_rate_ratio(Real(5e-2), Real(5e-4)), Real(5e-2) / Real(5e-4));
}

// sqrt(2/3 d':d'): an incompressible uniaxial stretch d = r diag(1, -1/2, -1/2) reads r; uniaxial strain
// grad v = diag(r, 0, 0) reads 2r/3; simple shear v_x = g y reads g/sqrt(3); rigid spin and pure
// dilatation read 0.
TYPED_TEST(JohnsonCookTyped, EquivalentStrainRate) {
  using Real = TypeParam;
  const double tol = 4 * std::numeric_limits<Real>::epsilon();
  const Real r = Real(1e3);
  const Mat3<Real> uniaxial_stress = {{{r, 0, 0}, {0, -r / 2, 0}, {0, 0, -r / 2}}};
  EXPECT_NEAR(double(equivalent_strain_rate(uniaxial_stress)), 1e3, tol * 1e3);
  const Mat3<Real> uniaxial_strain = {{{r, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
  EXPECT_NEAR(double(equivalent_strain_rate(uniaxial_strain)), 2e3 / 3, tol * 1e3);
  const Mat3<Real> simple_shear = {{{0, r, 0}, {0, 0, 0}, {0, 0, 0}}};
  EXPECT_NEAR(double(equivalent_strain_rate(simple_shear)), 1e3 / std::sqrt(3.0), tol * 1e3);
  const Mat3<Real> spin_only = {{{0, r, -2 * r}, {-r, 0, 3 * r}, {2 * r, -3 * r, 0}}};
  EXPECT_EQ(equivalent_strain_rate(spin_only), Real(0));
  const Mat3<Real> dilatation = {{{r, 0, 0}, {0, r, 0}, {0, 0, r}}};
  EXPECT_EQ(equivalent_strain_rate(dilatation), Real(0));
}

// One plastic step of a Johnson-Cook material from a trial stress well above the flow stress: after the
// return von_mises(S) is the flow stress at the start of the increment (explicit), the direction is kept,
// d_eps_p = (seq_trial - sigma_y)/(3 G), the plastic work is sigma_y d_eps_p / rho and the heating is
// 0.9 sigma_y d_eps_p / (rho c_p).
TYPED_TEST(JohnsonCookTyped, PlasticUpdateReturnsToFlowStress) {
  using Real = TypeParam;
  const double tol = rel_tol<Real>();
  const MaterialParams<Real> m = weldox_material<Real>();
  const Real eps_p = Real(0.05), rate = Real(2e3), T = Real(450), rho = Real(7900);
  const double sy = double(johnson_cook_yield(m.strength, eps_p, rate, T, m.room_temperature));
  const Sym3<Real> trial{Real(9e8), Real(-4e8), Real(-5e8), Real(2e8), Real(-1e8), Real(1.5e8)};
  const double seq = double(von_mises(trial));
  ASSERT_GT(seq, 1.3 * sy);
  Sym3<Real> S = trial;
  const PlasticResult<Real> r = plastic_update(m, S, eps_p, rate, T, rho, Real(0), Real(0));
  EXPECT_NEAR(double(von_mises(S)), sy, tol * sy);
  EXPECT_NEAR(double(S.xy) / double(trial.xy), sy / seq, tol);
  EXPECT_NEAR(double(S.zz) / double(trial.zz), sy / seq, tol);
  const double G = double(m.strength.shear_modulus), dep = (seq - sy) / (3 * G);
  EXPECT_NEAR(double(r.d_eps_p), dep, 10 * tol * dep);
  EXPECT_NEAR(double(r.plastic_work), sy * dep / double(rho), 10 * tol * sy * dep / double(rho));
  EXPECT_NEAR(double(r.d_T), 0.9 * sy * dep / (double(rho) * 452.0), 10 * tol * sy * dep / (double(rho) * 452.0));
  EXPECT_GT(r.d_T, Real(0));
  // Without a specific heat the temperature is not tracked: no heating, same return and work.
  MaterialParams<Real> cold = m;
  cold.specific_heat = 0;
  Sym3<Real> S2 = trial;
  const PlasticResult<Real> r2 = plastic_update(cold, S2, eps_p, rate, T, rho, Real(0), Real(0));
  EXPECT_EQ(r2.d_T, Real(0));
  EXPECT_EQ(r2.d_eps_p, r.d_eps_p);
  EXPECT_EQ(r2.plastic_work, r.plastic_work);
  EXPECT_EQ(S2.xx, S.xx);
}

// Elastic and hydrodynamic materials never yield; a stress below the flow stress is untouched (bitwise);
// a fully failed particle (D >= 1) loses its deviator without plastic strain or heat; a partly damaged one
// returns as an intact one.
TYPED_TEST(JohnsonCookTyped, PlasticUpdateLeavesElasticAndBelowYieldAlone) {
  using Real = TypeParam;
  const Sym3<Real> trial{Real(9e8), Real(-4e8), Real(-5e8), Real(2e8), Real(-1e8), Real(1.5e8)};
  auto same = [](Sym3<Real> a, Sym3<Real> b) {
    return a.xx == b.xx && a.yy == b.yy && a.zz == b.zz && a.xy == b.xy && a.yz == b.yz && a.zx == b.zx;
  };
  MaterialParams<Real> m = weldox_material<Real>();
  for (StrengthKind k : {StrengthKind::Elastic, StrengthKind::Hydrodynamic}) {
    m.strength.kind = k;
    Sym3<Real> S = trial;
    const PlasticResult<Real> r = plastic_update(m, S, Real(0.1), Real(1e3), Real(kRoom), Real(7850), Real(0), Real(0));
    EXPECT_TRUE(same(S, trial));
    EXPECT_EQ(r.d_eps_p, Real(0));
    EXPECT_EQ(r.d_T, Real(0));
    EXPECT_EQ(r.plastic_work, Real(0));
  }
  m.strength.kind = StrengthKind::JohnsonCook;
  const Sym3<Real> small = Real(0.3) * trial;  // von Mises ~ 370 MPa < A
  Sym3<Real> S = small;
  EXPECT_EQ(plastic_update(m, S, Real(0), Real(1e3), Real(kRoom), Real(7850), Real(0), Real(0)).d_eps_p, Real(0));
  EXPECT_TRUE(same(S, small));
  Sym3<Real> failed = trial;
  const PlasticResult<Real> rf = plastic_update(m, failed, Real(0.1), Real(1e3), Real(kRoom), Real(7850), Real(1), Real(0));
  EXPECT_TRUE(same(failed, Sym3<Real>::zero()));
  EXPECT_EQ(rf.d_eps_p, Real(0));
  EXPECT_EQ(rf.d_T, Real(0));
  Sym3<Real> partly = trial, intact = trial;
  const Real d1 = plastic_update(m, partly, Real(0.1), Real(1e3), Real(kRoom), Real(7850), Real(0.6), Real(0)).d_eps_p;
  const Real d0 = plastic_update(m, intact, Real(0.1), Real(1e3), Real(kRoom), Real(7850), Real(0), Real(0)).d_eps_p;
  EXPECT_EQ(d1, d0);
  EXPECT_TRUE(same(partly, intact));
  // Melted: zero flow stress, the deviator goes, no work is done.
  Sym3<Real> melted = trial;
  const PlasticResult<Real> rm = plastic_update(m, melted, Real(0.1), Real(1e3), Real(1900), Real(7850), Real(0), Real(0));
  EXPECT_EQ(von_mises(melted), Real(0));
  EXPECT_EQ(rm.plastic_work, Real(0));
}

// A perfectly plastic material returns to its yield stress whatever the plastic strain, rate and
// temperature: plastic_update is then radial_return itself (same bits).
TEST(PlasticUpdate, PerfectlyPlasticIsTheRadialReturnWhateverTheState) {
  MaterialParams<double> m = weldox_material<double>();
  m.strength.kind = StrengthKind::PerfectlyPlastic;
  m.strength.perfectly_plastic.yield_stress = 4.9e8;
  const Sym3<double> trial{9e8, -4e8, -5e8, 2e8, -1e8, 1.5e8};
  Sym3<double> a = trial, b = trial, c = trial;
  const double da = plastic_update(m, a, 0.0, 0.0, m.room_temperature, m.eos.rho0, 0.0, 0.0).d_eps_p;
  const double db = plastic_update(m, b, 0.7, 1e5, 1500.0, 7850.0, 0.0, 0.0).d_eps_p;
  const double dc = radial_return(c, 4.9e8, m.strength.shear_modulus);
  EXPECT_EQ(da, db);
  EXPECT_EQ(da, dc);
  EXPECT_EQ(a.xx, c.xx);
  EXPECT_EQ(a.zx, c.zx);
}

// Uniaxial strain, eps_xx = eps, others 0 (a plate-impact path), integrated in small increments with the
// Jaumann rate and plastic_update of a perfectly plastic material, P = -K eps (linear EOS).
// Elastic: S_xx = 4/3 G eps, S_yy = S_zz = -2/3 G eps, von Mises = 2 G |eps|, so yield at
// |eps_y| = sigma_y/(2G) and the axial stress there (the Hugoniot elastic limit) is
// (K + 4/3 G) eps_y = sigma_y (1 - nu)/(1 - 2 nu). Beyond it S_xx stays at -2/3 sigma_y (compression),
// so sigma_xx - sigma_yy = S_xx - S_yy = -sigma_y (a plateau of the deviator; the axial stress then grows
// with K only), and all further deviatoric strain is plastic: eps_p = 2/3 (|eps| - eps_y); the plastic
// work is sigma_y eps_p / rho. Unloading is elastic until S_xx has changed by 2 x 2/3 sigma_y, i.e. over
// a strain of sigma_y / G, after which reverse yielding starts at S_xx = +2/3 sigma_y.
// The return keeps the direction of the trial deviator, which is fixed along this path, so each step is
// exact up to rounding: the numeric path matches the piecewise-linear solution to 1e-10 (double).
template <class Real>
void run_uniaxial_strain(double tol) {
  const double E = 200e9, nu = 0.33, sy = 490e6, rho = 7850;
  const double G = E / (2 * (1 + nu)), K = E / (3 * (1 - 2 * nu));
  MaterialParams<Real> m;
  m.eos.rho0 = Real(rho);
  m.strength.kind = StrengthKind::PerfectlyPlastic;
  m.strength.shear_modulus = Real(G);
  m.strength.perfectly_plastic.yield_stress = Real(sy);
  const double eps_y = sy / (2 * G), hel = (K + 4 * G / 3) * eps_y;
  EXPECT_NEAR(hel, sy * (1 - nu) / (1 - 2 * nu), 1e-12 * hel);

  const double rate = -1e4, dt = 5e-10;  // 1/s, s: strain increment -5e-6 per step
  const int load_steps = 2000;           // to eps = -1e-2, about 3 eps_y
  Sym3<Real> S = Sym3<Real>::zero();
  double eps = 0, eps_p = 0, work = 0;
  bool yielded = false;
  auto step = [&](double r) {
    const Mat3<Real> gv = {{{Real(r), 0, 0}, {0, 0, 0}, {0, 0, 0}}};
    S = S + Real(dt) * deviatoric_stress_rate(m, S, gv);
    const PlasticResult<Real> res = plastic_update(m, S, Real(eps_p), Real(std::abs(r)), Real(293), Real(rho), Real(0), Real(0));
    eps += r * dt;
    eps_p += double(res.d_eps_p);
    work += double(res.plastic_work);
  };
  for (int k = 0; k < load_steps; ++k) {
    step(rate);
    const double a = std::abs(eps);
    const double sxx = a <= eps_y ? -4.0 / 3 * G * a : -2.0 / 3 * sy;
    const double P = -K * eps;
    ASSERT_NEAR(double(S.xx), sxx, tol * sy) << "loading step " << k;
    ASSERT_NEAR(double(S.yy), -0.5 * sxx, tol * sy) << "loading step " << k;
    EXPECT_NEAR(double(S.zz), double(S.yy), tol * sy);
    ASSERT_NEAR(eps_p, a <= eps_y ? 0.0 : 2.0 / 3 * (a - eps_y), tol * 1e-2) << "loading step " << k;
    if (a > eps_y) {
      yielded = true;
      const double sig_xx = -P + double(S.xx), sig_yy = -P + double(S.yy);
      EXPECT_NEAR(sig_xx - sig_yy, -sy, tol * sy);
      EXPECT_NEAR(sig_xx, (K * eps) - 2.0 / 3 * sy, tol * (K * 1e-2));
    }
  }
  ASSERT_TRUE(yielded);
  EXPECT_NEAR(work, sy * eps_p / rho, 10 * tol * sy * eps_p / rho);
  // Unloading: elastic over a strain of sigma_y / G, then reverse yield.
  const double eps_turn = eps, eps_p_turn = eps_p, reverse = sy / G;
  const int unload_steps = 2 * int(reverse / (std::abs(rate) * dt));
  for (int k = 0; k < unload_steps; ++k) {
    step(-rate);
    const double back = eps - eps_turn;
    const double sxx = back <= reverse ? -2.0 / 3 * sy + 4.0 / 3 * G * back : 2.0 / 3 * sy;
    ASSERT_NEAR(double(S.xx), sxx, tol * sy) << "unloading step " << k;
    ASSERT_NEAR(eps_p, back <= reverse ? eps_p_turn : eps_p_turn + 2.0 / 3 * (back - reverse), tol * 1e-2)
        << "unloading step " << k;
  }
  EXPECT_GT(eps_p, eps_p_turn);
}

TEST(PlasticUpdate, UniaxialStrainElasticPerfectlyPlasticDouble) { run_uniaxial_strain<double>(1e-10); }
TEST(PlasticUpdate, UniaxialStrainElasticPerfectlyPlasticFloat) { run_uniaxial_strain<float>(2e-3); }

// The same path with Johnson-Cook hardening: after every plastic step the von Mises stress equals the
// flow stress at the plastic strain, rate and temperature at the start of that step (1e-12), the
// deviator keeps its uniaxial shape, and the plateau rises with the hardening. Heating is on.
TEST(PlasticUpdate, UniaxialStrainJohnsonCookFollowsFlowStress) {
  const MaterialParams<double> m = weldox_material<double>();
  const double rate = -1e4, dt = 2.5e-9, rho = 7850;  // to eps = -0.1, eps_p ~ 0.065
  Sym3<double> S = Sym3<double>::zero();
  double eps_p = 0, T = kRoom;
  int plastic_steps = 0;
  double first_plateau = 0;
  for (int k = 0; k < 4000; ++k) {
    const Mat3<double> gv = {{{rate, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
    S = S + dt * deviatoric_stress_rate(m, S, gv);
    const double er = equivalent_strain_rate(gv);
    const double sy = johnson_cook_yield(m.strength, eps_p, er, T, m.room_temperature);
    const PlasticResult<double> r = plastic_update(m, S, eps_p, er, T, rho, 0.0, 0.0);
    if (r.d_eps_p > 0) {
      ++plastic_steps;
      ASSERT_NEAR(von_mises(S), sy, 1e-12 * sy) << k;
      EXPECT_NEAR(r.d_T, 0.9 * sy * r.d_eps_p / (rho * 452.0), 1e-12 * r.d_T);
      if (first_plateau == 0) first_plateau = von_mises(S);
    }
    EXPECT_NEAR(S.yy, -0.5 * S.xx, 1e-12 * std::abs(S.xx));
    eps_p += r.d_eps_p;
    T += r.d_T;
  }
  EXPECT_GT(plastic_steps, 2000);
  EXPECT_GT(von_mises(S), first_plateau * 1.15);  // hardened: 807 MPa x 0.065^0.73 ~ 110 MPa on ~580 MPa
  EXPECT_GT(T, kRoom + 5.0);                      // heated: 0.9 x ~600 MPa x 0.065 / (7850 x 452) ~ 10 K
}

}  // namespace
