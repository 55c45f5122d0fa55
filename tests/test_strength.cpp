// Unit tests of common/strength.hpp (F eqs 3.5-3.11 as corrected in physics-notes) and of the strength
// dispatch in common/material.hpp: Hooke rate 2 G d, the Jaumann rotation terms (sign checked by hand and
// by objectivity under a rigid spin integrated with RK4), and the von Mises radial return.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "common/material.hpp"
#include "common/strength.hpp"

namespace {

using namespace impactsph;

template <class Real>
class StrengthTyped : public ::testing::Test {};
using StrengthReals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(StrengthTyped, StrengthReals);

template <class Real>
void expect_sym_near(Sym3<Real> a, Sym3<double> b, double tol, const char* what) {
  EXPECT_NEAR(double(a.xx), b.xx, tol) << what << " xx";
  EXPECT_NEAR(double(a.yy), b.yy, tol) << what << " yy";
  EXPECT_NEAR(double(a.zz), b.zz, tol) << what << " zz";
  EXPECT_NEAR(double(a.xy), b.xy, tol) << what << " xy";
  EXPECT_NEAR(double(a.yz), b.yz, tol) << what << " yz";
  EXPECT_NEAR(double(a.zx), b.zx, tol) << what << " zx";
}

// Pure shear strain rate (symmetric grad v, no spin): dS/dt = 2 G d whatever S is. Volumetric parts are
// removed: grad v = diag(a, 0, 0) gives 2 G (2a/3, -a/3, -a/3). A few roundings: 10 eps relative.
TYPED_TEST(StrengthTyped, HookeRateForPureShearAndUniaxialStrainRate) {
  using Real = TypeParam;
  const double G = 80e9, g = 1e3, tol = 10 * std::numeric_limits<Real>::epsilon() * 2 * G * g;
  const Mat3<Real> pure_shear = {{{0, Real(g), 0}, {Real(g), 0, 0}, {0, 0, 0}}};  // d_xy = g, w = 0
  const Sym3<Real> S{Real(2e8), Real(-1e8), Real(-1e8), Real(5e7), Real(-3e7), Real(1e7)};
  for (const Sym3<Real>& s0 : {Sym3<Real>::zero(), S}) {
    const Sym3<Real> rate = jaumann_stress_rate(s0, pure_shear, Real(G));
    expect_sym_near(rate, Sym3<double>{0, 0, 0, 2 * G * g, 0, 0}, tol, "pure shear");
  }
  const Mat3<Real> uniaxial = {{{Real(g), 0, 0}, {0, 0, 0}, {0, 0, 0}}};
  expect_sym_near(jaumann_stress_rate(Sym3<Real>::zero(), uniaxial, Real(G)),
                  Sym3<double>{2 * G * 2 * g / 3, -2 * G * g / 3, -2 * G * g / 3, 0, 0, 0}, tol, "uniaxial strain rate");
  // A purely volumetric rate produces no deviatoric stress.
  const Mat3<Real> vol = {{{Real(g), 0, 0}, {0, Real(g), 0}, {0, 0, Real(g)}}};
  expect_sym_near(jaumann_stress_rate(Sym3<Real>::zero(), vol, Real(G)), Sym3<double>{0, 0, 0, 0, 0, 0}, tol, "volumetric");
}

// Simple shear v_x = g y (grad v(0,1) = g): d_xy = g/2, spin w = [[0, g/2, 0], [-g/2, 0, 0], 0]. With
// S = diag(s, -s, 0): w S - S w has xy = -g s, so dS_xy/dt = G g - g s. Sign check by hand: the flow rotates
// material clockwise at g/2 (angle phi = -g t / 2); a rotated diag(s, -s) gets S_xy = 2 s phi = -g s t.
TYPED_TEST(StrengthTyped, JaumannRotationTermsInSimpleShearByHand) {
  using Real = TypeParam;
  const double G = 80e9, g = 1e3, s = 3e8;
  const Mat3<Real> simple_shear = {{{0, Real(g), 0}, {0, 0, 0}, {0, 0, 0}}};
  const Sym3<Real> S{Real(s), Real(-s), 0, 0, 0, 0};
  const Sym3<Real> rate = jaumann_stress_rate(S, simple_shear, Real(G));
  const double tol = 10 * std::numeric_limits<Real>::epsilon() * G * g;
  expect_sym_near(rate, Sym3<double>{0, 0, 0, G * g - g * s, 0, 0}, tol, "simple shear");
  // Decomposition helpers: strain rate and spin of this grad v.
  const Sym3<Real> d = strain_rate(simple_shear);
  expect_sym_near(d, Sym3<double>{0, 0, 0, g / 2, 0, 0}, 0.0, "strain rate");
  const Mat3<Real> w = spin(simple_shear);
  EXPECT_EQ(w.m[0][1], Real(g / 2));
  EXPECT_EQ(w.m[1][0], Real(-g / 2));
  EXPECT_EQ(w.m[0][0], Real(0));
}

// Rotation matrix exp(theta K), K = [n]x (K x = n cross x), by Rodrigues.
Mat3<double> rodrigues(Vec3<double> n, double theta) {
  const Mat3<double> K = {{{0, -n.z, n.y}, {n.z, 0, -n.x}, {-n.y, n.x, 0}}};
  return Mat3<double>::identity() + std::sin(theta) * K + (1 - std::cos(theta)) * (K * K);
}

// Objectivity: a rigid spin v = W x (grad v = W antisymmetric) only rotates the stress. Integrating
// dS/dt = W S - S W (the Jaumann rate with d = 0) through an angle theta must give R S0 R^T with
// R = exp(W t). RK4 with 400 steps over 2 rad: local error ~ (dtheta)^5/120 per step, global ~ 1e-12 of
// |S|. The invariants tr(S^2) and det(S) are then preserved to 1e-8 (asked) in double; float to 1e-4
// (400 steps of ~eps rounding each, random-walk and drift: ~1e-5).
template <class Real>
void run_rigid_spin(double tol_rot, double tol_inv) {
  const double G = 80e9;
  const Vec3<double> axis_raw{0.3, -0.5, 0.8};
  const Vec3<double> n = (1.0 / norm(axis_raw)) * axis_raw;
  const double omega = 2e4;  // rad/s
  const Mat3<double> Wd = {{{0, -omega * n.z, omega * n.y}, {omega * n.z, 0, -omega * n.x}, {-omega * n.y, omega * n.x, 0}}};
  Mat3<Real> W;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) W.m[r][c] = Real(Wd.m[r][c]);
  const Sym3<double> S0d{2.0e8, -0.5e8, -1.5e8, 0.8e8, -0.3e8, 0.6e8};  // a deviator, Pa
  const Sym3<Real> S0{Real(S0d.xx), Real(S0d.yy), Real(S0d.zz), Real(S0d.xy), Real(S0d.yz), Real(S0d.zx)};
  const double theta = 2.0, t_end = theta / omega;
  const int steps = 400;
  const Real dt = Real(t_end / steps);
  Sym3<Real> S = S0;
  auto f = [&](Sym3<Real> s) { return jaumann_stress_rate(s, W, Real(G)); };
  for (int k = 0; k < steps; ++k) {
    const Sym3<Real> k1 = f(S);
    const Sym3<Real> k2 = f(S + (Real(0.5) * dt) * k1);
    const Sym3<Real> k3 = f(S + (Real(0.5) * dt) * k2);
    const Sym3<Real> k4 = f(S + dt * k3);
    S = S + (dt / Real(6)) * (k1 + Real(2) * k2 + Real(2) * k3 + k4);
  }
  // Exact: R S0 R^T.
  const Mat3<double> R = rodrigues(n, theta);
  const Mat3<double> Sx = R * S0d.full() * R.transpose();
  const double scale = std::sqrt(ddot(S0d, S0d));
  const Mat3<Real> Sf = S.full();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(double(Sf.m[r][c]), Sx.m[r][c], tol_rot * scale) << r << c;
  // The stress really turned (otherwise the comparison above would be trivial).
  EXPECT_GT(std::abs(double(S.xx) - S0d.xx), 0.1 * scale);
  // Invariants: tr S (stays 0), tr(S^2) = S:S, det S.
  Sym3<double> Sd{double(S.xx), double(S.yy), double(S.zz), double(S.xy), double(S.yz), double(S.zx)};
  EXPECT_NEAR(Sd.trace(), 0.0, tol_inv * scale);
  EXPECT_NEAR(ddot(Sd, Sd), ddot(S0d, S0d), tol_inv * ddot(S0d, S0d));
  const double det0 = determinant(S0d.full());
  EXPECT_NEAR(determinant(Sd.full()), det0, tol_inv * scale * scale * scale);
  EXPECT_NEAR(von_mises(Sd), von_mises(S0d), tol_inv * von_mises(S0d));
}

TEST(StrengthObjectivity, RigidSpinRotatesStressDouble) { run_rigid_spin<double>(1e-9, 1e-8); }
TEST(StrengthObjectivity, RigidSpinRotatesStressFloat) { run_rigid_spin<float>(1e-4, 1e-4); }

// Radial return above yield: the trial stress is scaled onto the yield surface, von_mises == sigma_y
// (double 1e-12 relative, float 10 eps), the direction is unchanged (every component scaled by the same
// factor sigma_y/seq), and the plastic strain increment is (seq - sigma_y)/(3 G).
TYPED_TEST(StrengthTyped, RadialReturnAboveYield) {
  using Real = TypeParam;
  const double tol = std::is_same<Real, double>::value ? 1e-12 : 10 * std::numeric_limits<Real>::epsilon();
  const double G = 80e9, sy = 4.9e8;  // Weldox-like yield stress
  const Sym3<Real> trial{Real(6e8), Real(-2.5e8), Real(-3.5e8), Real(1.2e8), Real(-0.7e8), Real(2.2e8)};
  const double seq = std::sqrt(1.5 * ddot(Sym3<double>{double(trial.xx), double(trial.yy), double(trial.zz),
                                                       double(trial.xy), double(trial.yz), double(trial.zx)},
                                          Sym3<double>{double(trial.xx), double(trial.yy), double(trial.zz),
                                                       double(trial.xy), double(trial.yz), double(trial.zx)}));
  ASSERT_GT(seq, 1.5 * sy);  // well beyond yield
  Sym3<Real> S = trial;
  const Real dep = radial_return(S, Real(sy), Real(G));
  EXPECT_NEAR(double(von_mises(S)), sy, tol * sy);
  const double c = sy / seq;
  EXPECT_NEAR(double(S.xx), c * double(trial.xx), tol * sy);
  EXPECT_NEAR(double(S.yy), c * double(trial.yy), tol * sy);
  EXPECT_NEAR(double(S.zz), c * double(trial.zz), tol * sy);
  EXPECT_NEAR(double(S.xy), c * double(trial.xy), tol * sy);
  EXPECT_NEAR(double(S.yz), c * double(trial.yz), tol * sy);
  EXPECT_NEAR(double(S.zx), c * double(trial.zx), tol * sy);
  EXPECT_NEAR(double(dep), (seq - sy) / (3 * G), tol * (seq - sy) / (3 * G) * 10);
  // Equivalently (1 - c_y)/(3 G) sqrt(3/2 S:S) of physics-notes.
  EXPECT_NEAR(double(dep), (1 - c) / (3 * G) * seq, 10 * tol * seq / (3 * G));
  // Uniaxial case by hand: sigma = 600 MPa along x, deviator (400, -200, -200) MPa, seq = 600 MPa.
  Sym3<Real> u = deviator(Sym3<Real>{Real(6e8), 0, 0, 0, 0, 0});
  const Real dep_u = radial_return(u, Real(sy), Real(G));
  EXPECT_NEAR(double(dep_u), (6e8 - sy) / (3 * G), 1e-5 * (6e8 - sy) / (3 * G));
  EXPECT_NEAR(double(u.xx), 4e8 * sy / 6e8, tol * sy * 10);
}

// At or below yield nothing changes (bitwise) and no plastic strain is returned.
TYPED_TEST(StrengthTyped, RadialReturnBelowYieldIsIdentity) {
  using Real = TypeParam;
  const Real G = Real(80e9);
  const Sym3<Real> trial{Real(2e8), Real(-0.5e8), Real(-1.5e8), Real(0.5e8), Real(0), Real(-0.2e8)};
  const Real seq = von_mises(trial);
  for (Real sy : {Real(1.01) * seq, Real(3) * seq, seq}) {
    Sym3<Real> S = trial;
    EXPECT_EQ(radial_return(S, sy, G), Real(0));
    EXPECT_EQ(S.xx, trial.xx);
    EXPECT_EQ(S.yy, trial.yy);
    EXPECT_EQ(S.zz, trial.zz);
    EXPECT_EQ(S.xy, trial.xy);
    EXPECT_EQ(S.yz, trial.yz);
    EXPECT_EQ(S.zx, trial.zx);
  }
}

// Zero yield stress (a fully damaged particle carries no deviatoric stress): S -> 0, increment seq/(3G).
TYPED_TEST(StrengthTyped, RadialReturnZeroYieldRemovesDeviator) {
  using Real = TypeParam;
  Sym3<Real> S{Real(2e8), Real(-0.5e8), Real(-1.5e8), Real(0.5e8), Real(0), Real(-0.2e8)};
  const Real seq = von_mises(S);
  const Real dep = radial_return(S, Real(0), Real(80e9));
  EXPECT_EQ(von_mises(S), Real(0));
  EXPECT_NEAR(double(dep), double(seq) / (3 * 80e9), 4 * std::numeric_limits<Real>::epsilon() * double(seq) / (3 * 80e9));
}

// The dispatch of material.hpp: a hydrodynamic material has no deviatoric stress rate; an elastic one has
// the Jaumann rate; only PerfectlyPlastic returns to the yield surface.
TEST(StrengthDispatch, MaterialSelectsStrengthModel) {
  MaterialParams<double> m;
  const Mat3<double> gv = {{{1e3, 2e3, 0}, {-5e2, 0, 1e2}, {0, 3e2, -4e2}}};
  const Sym3<double> S{2e8, -1e8, -1e8, 5e7, 0, 0};
  m.strength.kind = StrengthKind::Hydrodynamic;
  m.strength.shear_modulus = 80e9;
  const Sym3<double> r0 = deviatoric_stress_rate(m, S, gv);
  EXPECT_EQ(ddot(r0, r0), 0.0);
  EXPECT_FALSE(has_deviatoric_stress(m));
  m.strength.kind = StrengthKind::Elastic;
  const Sym3<double> r1 = deviatoric_stress_rate(m, S, gv), ref = jaumann_stress_rate(S, gv, 80e9);
  EXPECT_EQ(r1.xx, ref.xx);
  EXPECT_EQ(r1.xy, ref.xy);
  EXPECT_EQ(r1.zx, ref.zx);
  m.strength.perfectly_plastic.yield_stress = 1e6;  // far below von Mises of S, but Elastic never yields
  Sym3<double> s1 = S;
  EXPECT_EQ(plastic_update(m, s1, 0.0, 0.0, m.room_temperature, m.eos.rho0, 0.0, 0.0).d_eps_p, 0.0);
  EXPECT_EQ(s1.xx, S.xx);
  m.strength.kind = StrengthKind::PerfectlyPlastic;
  Sym3<double> s2 = S;
  EXPECT_GT(plastic_update(m, s2, 0.0, 0.0, m.room_temperature, m.eos.rho0, 0.0, 0.0).d_eps_p, 0.0);
  EXPECT_NEAR(von_mises(s2), 1e6, 1e-6);
}

// The registry of material.hpp: the enumerators follow the order of the lists, each names the model with
// that case key, and no key is registered twice.
TEST(MaterialModels, EveryRegisteredModelHasOneKeyThatNamesItBack) {
  const std::vector<std::string> strength = strength_keys(), damage = damage_keys();
  for (std::size_t k = 0; k < strength.size(); ++k) {
    const StrengthKind kind = static_cast<StrengthKind>(k);
    EXPECT_EQ(strength_key(kind), strength[k]);
    EXPECT_EQ(std::count(strength.begin(), strength.end(), strength[k]), 1) << strength[k];
  }
  for (std::size_t k = 0; k < damage.size(); ++k) {
    const DamageKind kind = static_cast<DamageKind>(k);
    EXPECT_EQ(damage_key(kind), damage[k]);
    EXPECT_EQ(std::count(damage.begin(), damage.end(), damage[k]), 1) << damage[k];
  }
  EXPECT_EQ(strength.size(), 5u);
  EXPECT_EQ(damage.size(), 5u);
  // What the dispatch reads of each model's traits.
  MaterialParams<double> m;
  m.strength.kind = StrengthKind::Hydrodynamic;
  EXPECT_FALSE(has_deviatoric_stress(m));
  m.strength.kind = StrengthKind::JohnsonHolmquist2;
  EXPECT_TRUE(has_deviatoric_stress(m));
  EXPECT_TRUE(strength_needs_pressure(m));
  m.strength.kind = StrengthKind::JohnsonCook;
  EXPECT_FALSE(strength_needs_pressure(m));
  EXPECT_FALSE(can_fail(m));
  m.damage.kind = DamageKind::FractureEnergy;
  EXPECT_TRUE(can_fail(m));
}

}  // namespace
