// Unit tests of common/eos.hpp against closed forms and finite differences:
// - Mie-Grueneisen (F eqs 3.2-3.4, density restored): on the linear Us-up Hugoniot of 4340 steel it
//   reproduces the Rankine-Hugoniot pressure up to the truncation of the cubic expansion, whose size and
//   order (mu^4) are derived below; tension branch; partial derivatives; sound speed.
// - Grueneisen with cubic Us-up (X eqs 30-31): exact on its own Hugoniot (algebra below); derivatives in
//   compression and tension; continuity at mu = 0.
// - Polynomial and Linear; sound speed at rest and its floor.
// Reference data: Steinberg's LLNL equation-of-state compilation (constants; Hugoniot table).
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <type_traits>

#include "common/eos.hpp"

namespace {

using namespace impactsph;

template <class Real>
class EosTyped : public ::testing::Test {};
using EosReals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(EosTyped, EosReals);

// 4340 steel RC38 (Steinberg): rho0 7810, c0 4578, s 1.33, Gamma0 1.67.
template <class Real>
EosParams<Real> steel_4340_mg() {
  EosParams<Real> p;
  p.kind = EosKind::MieGruneisen;
  p.rho0 = Real(7810);
  p.c0 = Real(4578);
  p.s1 = Real(1.33);
  p.gamma0 = Real(1.67);
  return p;
}

// Tungsten heavy alloy of X Table 2: rho 17162, c0 4029, S1 1.23, S2 = S3 = 0, gamma0 1.54.
template <class Real>
EosParams<Real> tungsten_gruneisen() {
  EosParams<Real> p;
  p.kind = EosKind::GruneisenCubic;
  p.rho0 = Real(17162);
  p.c0 = Real(4029);
  p.s1 = Real(1.23);
  p.gamma0 = Real(1.54);
  return p;
}

struct HugoniotState {
  double Us, rho, e, P, mu;
};
// Linear Us-up Rankine-Hugoniot state (validation.md): Us = c0 + s up, rho0 Us = rho (Us - up),
// e = up^2/2, P = rho0 Us up; mu = rho/rho0 - 1 = up/(Us - up).
HugoniotState linear_hugoniot(double rho0, double c0, double s, double up) {
  HugoniotState h;
  h.Us = c0 + s * up;
  h.rho = rho0 * h.Us / (h.Us - up);
  h.e = 0.5 * up * up;
  h.P = rho0 * h.Us * up;
  h.mu = up / (h.Us - up);
  return h;
}

// Table of validation.md: 4340 on 4340 at 500 and 1000 m/s (up = 250, 500): Us 4910.5 and 5243 m/s,
// P 9.59 and 20.47 GPa, rho 8229 and 8633 kg/m^3 (given to the digits printed).
TEST(EosHugoniot, LinearUsUpStatesMatchValidationTable) {
  const auto a = linear_hugoniot(7810, 4578, 1.33, 250), b = linear_hugoniot(7810, 4578, 1.33, 500);
  EXPECT_NEAR(a.Us, 4910.5, 1e-9);
  EXPECT_NEAR(a.P, 9.59e9, 0.005e9);
  EXPECT_NEAR(a.rho, 8229, 0.5);
  EXPECT_NEAR(b.Us, 5243, 1e-9);
  EXPECT_NEAR(b.P, 20.47e9, 0.005e9);
  EXPECT_NEAR(b.rho, 8633, 0.5);
}

// Mie-Grueneisen on the linear Us-up Hugoniot.
// Algebra. With k = s - 1 the exact Hugoniot in mu is P_H = rho0 c0^2 eta/(1 - s eta)^2, eta = mu/(1+mu),
// i.e. P_H = C1 mu (1+mu)/(1 - k mu)^2 = C1 mu [1 + (1+2k) mu + (2k+3k^2) mu^2 + (3k^2+4k^3) mu^3 + ...]
// (coefficient of mu^n inside the bracket: (n+1) k^n + n k^(n-1)); C2, C3 of F 3.4 are its first terms.
// On the Hugoniot e = up^2/2 = P_H mu/(2 rho) (Rankine-Hugoniot energy jump), so the energy term gives
// Gamma0 rho e = Gamma0 mu P_H / 2 and the EOS returns
//   P = (1 - Gamma0 mu/2) P3 + Gamma0 mu P_H/2,   P3 = the cubic,
//   P - P_H = (1 - Gamma0 mu/2) (P3 - P_H)                       (exact),
//   P3 - P_H = -C1 (3k^2 + 4k^3) mu^4 (1 + O(mu))                 (the truncation error).
// For k = 0.33: 3k^2 + 4k^3 = 0.4704; mu = 0.0536 (up 250) and 0.1054 (up 500): relative errors
// ~0.47 mu^3 / (1 + 1.66 mu) = 6.8e-5 and 4.6e-4 (< 0.5%). The absolute error scales like mu^4, its ratio
// between the two speeds (0.0536/0.1054)^4 = 0.067 up to the O(mu) corrections (a few percent).
TYPED_TEST(EosTyped, MieGruneisenOnLinearHugoniotOf4340Steel) {
  using Real = TypeParam;
  const auto p = steel_4340_mg<Real>();
  // Evaluate the reference with the Real-rounded state and constants, so that only the EOS arithmetic is
  // tested. Float: mu = rho/rho0 - 1 loses ~ eps (1+mu)/mu ~ 20 eps relative by cancellation, and the
  // polynomial a few eps more: 2e-5 relative to P bounds it (the truncation error is 7e-5 and 5e-4, so
  // the sign/size of the truncation is still resolved). double: 1e-9 relative (actual ~1e-14).
  const double tol = std::is_same<Real, double>::value ? 1e-9 : 2e-5;
  const double rho0 = p.rho0, c0 = p.c0, s = p.s1, g0 = p.gamma0, k = s - 1, C1 = rho0 * c0 * c0;
  double err_abs[2], mu_of[2];
  const double ups[2] = {250, 500};
  for (int n = 0; n < 2; ++n) {
    const auto hs = linear_hugoniot(rho0, c0, s, ups[n]);
    const Real rho = Real(hs.rho), e = Real(hs.e);
    const double mu = double(rho) / rho0 - 1;  // mu of the rounded density
    const double PH = C1 * mu * (1 + mu) / ((1 - k * mu) * (1 - k * mu));  // exact Hugoniot at that mu
    const double e_d = double(e);
    // Exact EOS value at (rho, e) from the algebra above, without the Hugoniot energy assumption:
    const double P3 = C1 * mu * (1 + (1 + 2 * k) * mu + (2 * k + 3 * k * k) * mu * mu);
    const double P_expected = (1 - 0.5 * g0 * mu) * P3 + g0 * double(rho) * e_d;
    Real dpr = 0, dpe = 0, c = 0;
    const Real P = mie_gruneisen_pressure(p, rho, e, dpr, dpe);
    EXPECT_NEAR(double(P), P_expected, tol * P_expected) << "up " << ups[n];
    EXPECT_EQ(eos_pressure(p, rho, e, c), P);  // the dispatcher returns the same pressure
    // Against the exact Rankine-Hugoniot pressure rho0 Us up: within the truncation error.
    const double rel = (double(P) - hs.P) / hs.P;
    EXPECT_LT(std::abs(rel), 5e-3) << "up " << ups[n];
    EXPECT_LT(rel, 0.0) << "the truncated series (positive coefficients) underestimates P_H";
    // ... and equal to the closed-form error (1 - Gamma0 mu/2)(P3 - P_H) (e on the Hugoniot exactly
    // when rho is; in float rho and e are rounded separately, hence the tolerance).
    const double err_closed = (1 - 0.5 * g0 * mu) * (P3 - PH);
    EXPECT_NEAR(double(P) - PH, err_closed, tol * hs.P + g0 * double(rho) * std::abs(e_d - hs.e)) << "up " << ups[n];
    err_abs[n] = double(P) - PH;
    mu_of[n] = mu;
    if (std::is_same<Real, double>::value) {
      // Leading term -C1 (3k^2+4k^3) mu^4 within its O(mu) correction (< 15% at mu = 0.105).
      const double lead = -C1 * (3 * k * k + 4 * k * k * k) * std::pow(mu, 4);
      EXPECT_NEAR(err_abs[n] / lead, 1.0, 0.15) << "up " << ups[n];
    }
  }
  if (std::is_same<Real, double>::value) {
    // The error shrinks like mu^4 from up = 500 to up = 250 (ratio 0.067), within 10% (O(mu) terms).
    const double ratio = err_abs[0] / err_abs[1], mu4 = std::pow(mu_of[0] / mu_of[1], 4);
    EXPECT_NEAR(ratio / mu4, 1.0, 0.10);
    EXPECT_GT(ratio / mu4, 0.0);
  }
}

// Tension (mu < 0): P_H = C1 mu, and F eq 3.2 applies the factor (1 - Gamma0 mu/2) to P_H in both branches:
//   P = (1 - Gamma0 mu/2) C1 mu + Gamma0 rho e.
// (That factor is what makes the Hugoniot-referenced form consistent: it removes Gamma0 rho e_H of the
// reference curve; physics-notes keeps F's form.) In compression near mu = 0 both branches agree to first
// order, so P is continuous at mu = 0.
TYPED_TEST(EosTyped, MieGruneisenTensionBranch) {
  using Real = TypeParam;
  const double tol = 20 * std::numeric_limits<Real>::epsilon() / 0.02;  // mu cancellation, as above
  const auto p = steel_4340_mg<Real>();
  const double rho0 = p.rho0, C1 = rho0 * double(p.c0) * double(p.c0), g0 = p.gamma0;
  for (double mu_t : {-0.02, -0.08}) {
    for (double e_t : {0.0, 3e4}) {
      const Real rho = Real(rho0 * (1 + mu_t)), e = Real(e_t);
      const double mu = double(rho) / rho0 - 1;
      const double expected = (1 - 0.5 * g0 * mu) * C1 * mu + g0 * double(rho) * e_t;
      Real dpr, dpe;
      const double P = mie_gruneisen_pressure(p, rho, e, dpr, dpe);
      EXPECT_NEAR(P, expected, tol * C1 * std::abs(mu)) << "mu " << mu << " e " << e_t;
    }
  }
  // Continuity at mu = 0 (P ~ C1 mu on both sides): within C1 * 2 mu^2 for |mu| = 1e-4 (double only, the
  // float density cannot resolve mu = 1e-4 well enough to say more than the branch tests above).
  if (std::is_same<Real, double>::value) {
    Real d1, d2;
    const double dm = 1e-4;
    const double Pp = mie_gruneisen_pressure(p, Real(rho0 * (1 + dm)), Real(0), d1, d2);
    const double Pm = mie_gruneisen_pressure(p, Real(rho0 * (1 - dm)), Real(0), d1, d2);
    EXPECT_NEAR(Pp, C1 * dm, 2 * C1 * dm * dm);
    EXPECT_NEAR(Pm, -C1 * dm, 2 * C1 * dm * dm);
  }
}

// The pressure cutoff (min_pressure, LS-DYNA's PC): the EOS pressure is held at or above it, the sound
// speed is the EOS's, compression is untouched, and without a cutoff the tension is the EOS's.
TYPED_TEST(EosTyped, PressureCutoffBoundsTension) {
  using Real = TypeParam;
  auto p = steel_4340_mg<Real>();
  const Real rho = Real(double(p.rho0) * 0.9), e = Real(0);
  Real c_free = 0, c_cut = 0;
  const Real free_tension = eos_pressure(p, rho, e, c_free);
  ASSERT_LT(free_tension, Real(-1e9));  // mu = -0.1 of steel: about -15 GPa
  p.min_pressure = Real(-1.2e9);
  EXPECT_EQ(eos_pressure(p, rho, e, c_cut), Real(-1.2e9));
  EXPECT_EQ(c_cut, c_free);
  const Real rho_c = Real(double(p.rho0) * 1.05);
  Real c1 = 0;
  auto q = p;
  q.min_pressure = Real(-1e30);
  EXPECT_EQ(eos_pressure(p, rho_c, e, c1), eos_pressure(q, rho_c, e, c1));
  // A NaN state stays NaN (the divergence check must still see it).
  EXPECT_TRUE(std::isnan(double(eos_pressure(p, Real(NAN), e, c1))));
}

// Central finite differences of P in rho (at fixed e) and in e (at fixed rho). double; step 1e-6 relative:
// truncation ~ (1e-6)^2 relative, rounding ~ eps P/(delta dP) ~ 1e-11 relative: 1e-7 relative tolerance.
// States stay away from the kink at mu = 0.
template <class F>
void check_derivatives(F eos, double rho, double e, const char* what) {
  double dpr = 0, dpe = 0;
  eos(rho, e, dpr, dpe);
  double d1, d2;
  const double hr = 1e-6 * rho, he = 1e-6 * std::max(std::abs(e), 1e4);
  const double fd_rho = (eos(rho + hr, e, d1, d2) - eos(rho - hr, e, d1, d2)) / (2 * hr);
  const double fd_e = (eos(rho, e + he, d1, d2) - eos(rho, e - he, d1, d2)) / (2 * he);
  EXPECT_NEAR(dpr, fd_rho, 1e-7 * std::abs(fd_rho)) << what << " dP/drho at rho " << rho << " e " << e;
  EXPECT_NEAR(dpe, fd_e, 1e-7 * std::abs(fd_e) + 1e-12) << what << " dP/de at rho " << rho << " e " << e;
}

TEST(EosDerivatives, MieGruneisenMatchesFiniteDifferences) {
  const auto p = steel_4340_mg<double>();
  auto eos = [&p](double rho, double e, double& a, double& b) { return mie_gruneisen_pressure(p, rho, e, a, b); };
  for (double mu : {0.01, 0.08, 0.3, -0.01, -0.05})
    for (double e : {0.0, 2e5, 1e6}) check_derivatives(eos, 7810 * (1 + mu), e, "MieGruneisen");
}

TEST(EosDerivatives, GruneisenCubicMatchesFiniteDifferences) {
  // Non-zero S2, S3 and a, so that every term of X eq 30 and its derivative is exercised (values are
  // test values, not a material).
  auto p = tungsten_gruneisen<double>();
  p.s2 = 0.35;
  p.s3 = -0.4;
  p.a = 0.45;
  auto eos = [&p](double rho, double e, double& a, double& b) { return gruneisen_cubic_pressure(p, rho, e, a, b); };
  for (double mu : {0.01, 0.08, 0.3, -0.01, -0.05, -0.2})
    for (double e : {0.0, 2e5, 1e6}) check_derivatives(eos, 17162 * (1 + mu), e, "GruneisenCubic");
}

TEST(EosDerivatives, PolynomialMatchesFiniteDifferences) {
  EosParams<double> p;
  p.kind = EosKind::Polynomial;
  p.rho0 = 3890;  // alumina of X Table 1
  p.k1 = 130.95e9;
  p.k2 = 250e9;  // test values with both higher-order terms non-zero
  p.k3 = -100e9;
  auto eos = [&p](double rho, double, double& a, double& b) {
    b = 0;
    return polynomial_pressure(p, rho, a);
  };
  for (double mu : {0.01, 0.08, 0.3, -0.01, -0.05}) check_derivatives(eos, 3890 * (1 + mu), 0.0, "Polynomial");
}

// Grueneisen with cubic Us-up on its own Hugoniot.
// Algebra. Let eta = mu/(1+mu) = up/Us and D = 1 - S1 eta - S2 eta^2 - S3 eta^3. The LS-DYNA Hugoniot
// Us = c0 + S1 up + S2 up^2/Us + S3 up^3/Us^2 gives Us D = c0, so P_H = rho0 Us up = rho0 c0^2 eta/D^2 =
// C1 mu/((1+mu) D^2). The denominator of X eq 30 is den = 1 - (S1-1) mu - S2 mu^2/(mu+1) - S3 mu^3/(mu+1)^2
// = (1+mu) D (divide by 1+mu and use 1/(1+mu) = 1 - eta). On the Hugoniot E = rho0 e = rho0 up^2/2
// = P_H mu/(2(1+mu)). Hence
//   P = C1 mu [(1+mu) - gamma0 mu/2 - a mu^2/2] / ((1+mu)^2 D^2) + (gamma0 + a mu) mu P_H/(2(1+mu))
//     = P_H [1 - (gamma0 mu + a mu^2)/(2(1+mu))] + P_H (gamma0 mu + a mu^2)/(2(1+mu)) = P_H,
// exactly, for any S1, S2, S3, gamma0 and a. So the check is an identity to rounding: 1e-9 relative in
// double (the brief's S2 = S3 = a = 0 case is the linear Us-up Hugoniot; the general case is also exact).
TEST(EosHugoniot, GruneisenCubicIsExactOnItsHugoniotDouble) {
  struct Case {
    const char* name;
    EosParams<double> p;
  };
  auto steel = steel_4340_mg<double>();
  steel.kind = EosKind::GruneisenCubic;
  auto cubic = tungsten_gruneisen<double>();
  cubic.s2 = 0.35;
  cubic.s3 = -0.4;
  cubic.a = 0.45;
  const Case cases[] = {{"4340 steel, linear Us-up", steel}, {"tungsten alloy (X Table 2)", tungsten_gruneisen<double>()},
                        {"cubic Us-up with a != 0", cubic}};
  for (const auto& c : cases) {
    for (double up : {50.0, 250.0, 500.0, 1000.0}) {
      // Us from Us = c0 + S1 up + S2 up^2/Us + S3 up^3/Us^2 by fixed-point iteration (a contraction for
      // these small S2, S3; converged to rounding after 60 steps).
      double Us = c.p.c0 + c.p.s1 * up;
      for (int it = 0; it < 60; ++it) Us = c.p.c0 + c.p.s1 * up + c.p.s2 * up * up / Us + c.p.s3 * up * up * up / (Us * Us);
      const double rho = c.p.rho0 * Us / (Us - up), e = 0.5 * up * up, P_H = c.p.rho0 * Us * up;
      double dpr, dpe, snd;
      const double P = gruneisen_cubic_pressure(c.p, rho, e, dpr, dpe);
      EXPECT_NEAR(P, P_H, 1e-9 * P_H) << c.name << " up " << up;
      EXPECT_EQ(eos_pressure(c.p, rho, e, snd), P);
    }
  }
  // The brief's linear case against the validation table: 4340 at up = 250 m/s gives 9.59 GPa.
  double dpr, dpe;
  const auto hs = linear_hugoniot(7810, 4578, 1.33, 250);
  EXPECT_NEAR(gruneisen_cubic_pressure(steel, hs.rho, hs.e, dpr, dpe), 9.59e9, 0.005e9);
}

// Float version of the Hugoniot identity (the device precision): mu's cancellation costs ~20 eps, the
// rational expression a few eps more: 2e-5 relative.
TEST(EosHugoniot, GruneisenCubicOnHugoniotFloat) {
  const auto pd = tungsten_gruneisen<double>();
  const auto pf = tungsten_gruneisen<float>();
  for (double up : {250.0, 500.0, 1000.0}) {
    const auto hs = linear_hugoniot(pd.rho0, double(pf.c0), double(pf.s1), up);
    float dpr, dpe;
    const float P = gruneisen_cubic_pressure(pf, float(hs.rho), float(hs.e), dpr, dpe);
    EXPECT_NEAR(double(P), hs.P, 2e-5 * hs.P) << "up " << up;
  }
}

// Tension branch (X eq 31): P = rho0 c0^2 mu + (gamma0 + a mu) rho0 e; continuous at mu = 0.
TYPED_TEST(EosTyped, GruneisenCubicTensionAndContinuity) {
  using Real = TypeParam;
  auto p = tungsten_gruneisen<Real>();
  p.a = Real(0.45);
  const double rho0 = p.rho0, C1 = rho0 * double(p.c0) * double(p.c0), g0 = p.gamma0, a = p.a;
  const double tol = 20 * std::numeric_limits<Real>::epsilon() / 0.02;
  for (double mu_t : {-0.02, -0.1})
    for (double e : {0.0, 5e4}) {
      const Real rho = Real(rho0 * (1 + mu_t));
      const double mu = double(rho) / rho0 - 1;
      Real dpr, dpe;
      const double P = gruneisen_cubic_pressure(p, rho, Real(e), dpr, dpe);
      const double expected = C1 * mu + (g0 + a * mu) * rho0 * e;
      EXPECT_NEAR(P, expected, tol * (C1 * std::abs(mu) + g0 * rho0 * e)) << "mu " << mu << " e " << e;
      EXPECT_NEAR(double(dpe), (g0 + a * mu) * rho0, 1e-6 * g0 * rho0);
    }
  if (std::is_same<Real, double>::value) {
    Real d1, d2;
    const double dm = 1e-5, e = 1e5;
    const double Pp = gruneisen_cubic_pressure(p, Real(rho0 * (1 + dm)), Real(e), d1, d2);
    const double Pm = gruneisen_cubic_pressure(p, Real(rho0 * (1 - dm)), Real(e), d1, d2);
    const double P0 = g0 * rho0 * e;  // both branches at mu = 0
    EXPECT_NEAR(0.5 * (Pp + Pm), P0, 2 * C1 * dm * dm + 1e-9 * P0);
  }
}

// Polynomial: K1 mu + K2 mu^2 + K3 mu^3 in compression, K1 mu in tension (alumina of X Table 1:
// K1 130.95 GPa, K2 0, K3 0; K2, K3 set to test values so every term counts).
TYPED_TEST(EosTyped, PolynomialClosedForm) {
  using Real = TypeParam;
  EosParams<Real> p;
  p.kind = EosKind::Polynomial;
  p.rho0 = Real(3890);
  p.k1 = Real(130.95e9);
  p.k2 = Real(250e9);
  p.k3 = Real(-100e9);
  const double tol = 20 * std::numeric_limits<Real>::epsilon() / 0.02;
  for (double mu_t : {0.02, 0.15, -0.02, -0.1}) {
    const Real rho = Real(3890 * (1 + mu_t));
    const double mu = double(rho) / 3890 - 1;
    const double expected = mu > 0 ? mu * (130.95e9 + mu * (250e9 - 100e9 * mu)) : 130.95e9 * mu;
    Real dpr = 0, c = 0;
    const double P = polynomial_pressure(p, rho, dpr);
    EXPECT_NEAR(P, expected, tol * std::abs(expected)) << "mu " << mu;
    // The energy plays no part.
    EXPECT_EQ(eos_pressure(p, rho, Real(0), c), eos_pressure(p, rho, Real(1e6), c));
  }
  Real c = 0;
  eos_pressure(p, p.rho0, Real(0), c);
  EXPECT_NEAR(double(c), std::sqrt(130.95e9 / 3890), 4 * std::numeric_limits<Real>::epsilon() * 5802);
}

// Linear: P = K mu; c = sqrt(K/rho0) at rest, and everywhere (dP/drho = K/rho0, dP/de = 0). Weldox 460 E
// bulk modulus K = E/(3(1 - 2 nu)) with E 200 GPa, nu 0.33: 196.08 GPa; bulk speed 4998 m/s
// (validation.md), within 1 m/s.
TYPED_TEST(EosTyped, LinearClosedFormAndSoundSpeed) {
  using Real = TypeParam;
  EosParams<Real> p;
  p.kind = EosKind::Linear;
  p.rho0 = Real(7850);
  const double K = 200e9 / (3 * (1 - 2 * 0.33));
  p.k1 = Real(K);
  const double eps = std::numeric_limits<Real>::epsilon();
  for (double mu_t : {0.0, 1e-3, -1e-3, 0.05}) {
    const Real rho = Real(7850 * (1 + mu_t));
    const double mu = double(rho) / 7850 - 1;
    Real c = 0;
    const double P = eos_pressure(p, rho, Real(123.0), c);
    EXPECT_NEAR(P, K * mu, 4 * eps * K);  // cancellation in mu bounded by eps (1+mu) absolute
    EXPECT_NEAR(double(c), std::sqrt(K / 7850), 4 * eps * 5000) << "mu " << mu;
  }
  Real c = 0;
  eos_pressure(p, p.rho0, Real(0), c);
  EXPECT_NEAR(double(c), 4998.0, 1.0);
}

// Sound speed at rest: c0 for both Grueneisen forms (C1/rho0 = c0^2, P = 0). Float: sqrt of a few-eps
// quantity: 4 eps relative.
TYPED_TEST(EosTyped, SoundSpeedAtRestIsC0) {
  using Real = TypeParam;
  const double eps = std::numeric_limits<Real>::epsilon();
  Real c = 0;
  const auto mg = steel_4340_mg<Real>();
  EXPECT_EQ(eos_pressure(mg, mg.rho0, Real(0), c), Real(0));
  EXPECT_NEAR(double(c), 4578.0, 4 * eps * 4578);
  const auto gc = tungsten_gruneisen<Real>();
  EXPECT_EQ(eos_pressure(gc, gc.rho0, Real(0), c), Real(0));
  EXPECT_NEAR(double(c), 4029.0, 4 * eps * 4029);
  EXPECT_NEAR(double(eos_reference_sound_speed2(mg)), 4578.0 * 4578.0, 4 * eps * 4578.0 * 4578.0);
}

// Away from rest the sound speed is the isentropic one, c^2 = dP/drho|_s: check against a central
// difference along the isentrope de = P/rho^2 drho (second order in the step; the O(delta^2) energy
// terms cancel in the difference). Step 1e-4 relative: error ~1e-8 relative; tolerance 1e-6 relative.
TEST(EosSoundSpeed, IsentropicDerivativeDouble) {
  auto cubic = tungsten_gruneisen<double>();
  cubic.s2 = 0.35;
  cubic.s3 = -0.4;
  cubic.a = 0.45;
  const EosParams<double> eoses[] = {steel_4340_mg<double>(), cubic};
  for (const auto& p : eoses)
    for (double mu : {0.05, 0.2, -0.02})
      for (double e : {1e4, 3e5}) {
        const double rho = p.rho0 * (1 + mu), d = 1e-4 * rho;
        double c = 0, cc;
        const double P = eos_pressure(p, rho, e, c);
        const double Pp = eos_pressure(p, rho + d, e + P / (rho * rho) * d, cc);
        const double Pm = eos_pressure(p, rho - d, e - P / (rho * rho) * d, cc);
        const double c2_fd = (Pp - Pm) / (2 * d);
        EXPECT_NEAR(c * c, c2_fd, 1e-6 * c2_fd) << "kind " << int(p.kind) << " mu " << mu << " e " << e;
      }
}

// The floor: far in tension the isentropic c^2 of the cubic Grueneisen form turns negative (c^2 =
// c0^2 (1 + gamma0 mu/(1+mu)^2) at e = 0 and a = 0: negative at mu = -0.5); eos_pressure then returns
// the documented floor, half the reference sound speed.
TEST(EosSoundSpeed, FloorInStrongTension) {
  const auto p = tungsten_gruneisen<double>();
  double c = 0;
  eos_pressure(p, 0.5 * p.rho0, 0.0, c);
  EXPECT_DOUBLE_EQ(c, 0.5 * 4029.0);
  // Not floored where c^2 is well above the floor: mu = -0.05, c^2 = c0^2 (1 - 1.54 * 0.05/0.9025).
  eos_pressure(p, 0.95 * p.rho0, 0.0, c);
  EXPECT_NEAR(c * c, 4029.0 * 4029.0 * (1 - 1.54 * 0.05 / 0.9025), 1e-9 * 4029.0 * 4029.0);
}

}  // namespace
