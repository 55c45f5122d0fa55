// Unit tests of common/viscosity.hpp (Monaghan, F eqs 2.16-2.17 / X eqs 11-12), common/timestep.hpp
// (F eq 5.1), common/delta_sph.hpp (Marrone et al. 2011 as corrected in physics-notes) and the signal
// speed of common/material.hpp (longitudinal wave speed of Weldox 460 E, validation.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <type_traits>
#include <random>
#include <vector>

#include "common/delta_sph.hpp"
#include "common/kernels.hpp"
#include "common/material.hpp"
#include "common/timestep.hpp"
#include "common/viscosity.hpp"

namespace {

using namespace impactsph;

template <class Real>
class ViscosityTyped : public ::testing::Test {};
using ViscosityReals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(ViscosityTyped, ViscosityReals);

// ---- Artificial viscosity ----

// Separating or sliding pairs get no viscosity (F 2.16: zero unless x_ij . u_ij < 0).
TYPED_TEST(ViscosityTyped, ZeroForSeparatingAndTangentialPairs) {
  using Real = TypeParam;
  const ViscosityParams<Real> p{Real(1.0), Real(2.0)};
  // Binary fractions (2^-10 m etc.), so that the tangential case has x.u = 0 exactly in float too.
  const Vec3<Real> xij{Real(0.0009765625), Real(0.00048828125), Real(-0.000244140625)};
  const Real h = Real(1.2e-3), c = Real(5000), rho = Real(7850);
  EXPECT_EQ(monaghan_viscosity(p, xij, Vec3<Real>{Real(100), 0, 0}, h, c, rho), Real(0));      // separating
  EXPECT_EQ(monaghan_viscosity(p, xij, Vec3<Real>{0, 0, 0}, h, c, rho), Real(0));                // at rest
  EXPECT_EQ(monaghan_viscosity(p, xij, Vec3<Real>{Real(-0.5), Real(1), Real(0)}, h, c, rho), Real(0));  // tangential: v.x = 0
}

// Approaching pair by hand: x_ij = (1 mm, 0, 0), u_ij = (-100 m/s, 0, 0), h = 1.2 mm, c = 5000 m/s,
// rho = 7850 kg/m^3. phi = h x.u/(r^2 + 0.01 h^2) = 1.2e-3 (-0.1)/(1e-6 + 1.44e-8) = -118.2965 m/s;
// linear term -kappa1 c phi/rho = 75.3481 (m^5 kg^-1 s^-2 = Pa/(kg/m^3)^2), quadratic phi^2/rho = 1.782684.
// Float: ~10 roundings, 1e-6 relative.
TYPED_TEST(ViscosityTyped, ApproachingPairByHand) {
  using Real = TypeParam;
  const double tol = std::is_same<Real, double>::value ? 1e-12 : 1e-6;
  const Vec3<Real> xij{Real(1e-3), 0, 0}, uij{Real(-100), 0, 0};
  const Real h = Real(1.2e-3), c = Real(5000), rho = Real(7850);
  const double lin = 75.34810826016195, quad = 1.782683949372917;
  EXPECT_NEAR(double(monaghan_viscosity(ViscosityParams<Real>{Real(1), Real(0)}, xij, uij, h, c, rho)), lin, tol * lin);
  EXPECT_NEAR(double(monaghan_viscosity(ViscosityParams<Real>{Real(0), Real(1)}, xij, uij, h, c, rho)), quad, tol * quad);
  // F Table 3 style coefficients (kappa1 = 1.5, kappa2 = 2.5 as test values): the sum of the two terms.
  EXPECT_NEAR(double(monaghan_viscosity(ViscosityParams<Real>{Real(1.5), Real(2.5)}, xij, uij, h, c, rho)),
              1.5 * lin + 2.5 * quad, tol * lin * 2);
  // Symmetric in the pair (x_ij and u_ij both change sign) and positive (repulsive).
  EXPECT_EQ(monaghan_viscosity(ViscosityParams<Real>{Real(1), Real(1)}, -xij, -uij, h, c, rho),
            monaghan_viscosity(ViscosityParams<Real>{Real(1), Real(1)}, xij, uij, h, c, rho));
  EXPECT_GT(monaghan_viscosity(ViscosityParams<Real>{Real(1), Real(1)}, xij, uij, h, c, rho), Real(0));
}

// Bulk viscosity q = rho h (quadratic h div^2 - linear c div) in compression, by hand: div v = -1e4 /s,
// rho = 8960 kg/m^3, c = 3940 m/s, h = 0.6 mm: the linear term 8960 * 6e-4 * 3940 * 1e4 = 2.118144e8 Pa, the
// quadratic 8960 * 6e-4 * 6e-4 * 1e8 = 3.2256e5 Pa. Zero in expansion and in isochoric flow (div v = 0),
// whatever the shear: it is what separates it from the pairwise Monaghan term.
TYPED_TEST(ViscosityTyped, BulkViscosityByHand) {
  using Real = TypeParam;
  const double tol = std::is_same<Real, double>::value ? 1e-12 : 1e-6;
  const Real rho = Real(8960), c = Real(3940), h = Real(6e-4);
  const double lin = 2.118144e8, quad = 3.2256e5;
  EXPECT_NEAR(double(bulk_viscosity(BulkViscosityParams<Real>{Real(1), Real(0)}, Real(-1e4), rho, c, h)), lin, tol * lin);
  EXPECT_NEAR(double(bulk_viscosity(BulkViscosityParams<Real>{Real(0), Real(1)}, Real(-1e4), rho, c, h)), quad, tol * quad);
  EXPECT_NEAR(double(bulk_viscosity(BulkViscosityParams<Real>{Real(0.5), Real(1.5)}, Real(-1e4), rho, c, h)),
              0.5 * lin + 1.5 * quad, tol * lin);
  EXPECT_NEAR(double(bulk_viscosity_over_rho2(BulkViscosityParams<Real>{Real(1), Real(0)}, Real(-1e4), rho, c, h)),
              lin / (8960.0 * 8960.0), tol * lin / (8960.0 * 8960.0));
  const BulkViscosityParams<Real> on{Real(1), Real(1)};
  EXPECT_EQ(bulk_viscosity(on, Real(1e4), rho, c, h), Real(0));  // expansion
  EXPECT_EQ(bulk_viscosity(on, Real(0), rho, c, h), Real(0));    // isochoric flow, e.g. pure shear
  EXPECT_EQ(bulk_viscosity(BulkViscosityParams<Real>{}, Real(-1e4), rho, c, h), Real(0));  // off by default
  // Into A = (S - P I)/rho^2 as a pressure: the diagonal less q/rho^2, the shear terms untouched.
  Sym3<Real> a{Real(1), Real(2), Real(3), Real(4), Real(5), Real(6)};
  add_bulk_viscosity(BulkViscosityParams<Real>{Real(1), Real(0)}, Real(-1e4), rho, c, h, a);
  const double q = lin / (8960.0 * 8960.0);
  EXPECT_NEAR(double(a.xx), 1 - q, tol * q);
  EXPECT_NEAR(double(a.yy), 2 - q, tol * q);
  EXPECT_NEAR(double(a.zz), 3 - q, tol * q);
  EXPECT_EQ(a.xy, Real(4));
  EXPECT_EQ(a.yz, Real(5));
  EXPECT_EQ(a.zx, Real(6));
}

// Naming (physics-notes): `linear` is F's kappa1 and X's Q2, the coefficient of the term LINEAR in the
// velocity jump, which multiplies the sound speed; `quadratic` (F's kappa2, X's Q1) does not involve c.
TYPED_TEST(ViscosityTyped, LinearCoefficientMultipliesSoundSpeed) {
  using Real = TypeParam;
  const double tol = 4 * std::numeric_limits<Real>::epsilon();
  const Vec3<Real> xij{Real(0.6e-3), Real(-0.8e-3), Real(0.3e-3)}, uij{Real(-30), Real(50), Real(10)};
  const Real h = Real(1.2e-3), rho = Real(7850);
  const ViscosityParams<Real> lin{Real(1), Real(0)}, quad{Real(0), Real(1)};
  const double l1 = monaghan_viscosity(lin, xij, uij, h, Real(4000), rho);
  const double l2 = monaghan_viscosity(lin, xij, uij, h, Real(8000), rho);
  EXPECT_NEAR(l2, 2 * l1, tol * l2);  // linear term proportional to c
  const double l3 = monaghan_viscosity(lin, xij, Real(2) * uij, h, Real(4000), rho);
  EXPECT_NEAR(l3, 2 * l1, tol * l3);  // ... and to the velocity jump
  const double q1 = monaghan_viscosity(quad, xij, uij, h, Real(4000), rho);
  const double q2 = monaghan_viscosity(quad, xij, uij, h, Real(8000), rho);
  EXPECT_EQ(q1, q2);  // quadratic term independent of c
  const double q3 = monaghan_viscosity(quad, xij, Real(2) * uij, h, Real(4000), rho);
  EXPECT_NEAR(q3, 4 * q1, tol * q3);  // ... and quadratic in the velocity jump
  // Default parameters are 1 and 1.
  const ViscosityParams<Real> def{};
  EXPECT_EQ(def.linear, Real(1));
  EXPECT_EQ(def.quadratic, Real(1));
}

// ---- Time step ----

TYPED_TEST(ViscosityTyped, CflTimeStepFormula) {
  using Real = TypeParam;
  // dt = C h/(c + |u|): 0.05 * 1.2e-3/(6144 + 300) s.
  const double expected = 0.05 * 1.2e-3 / 6444.0;
  EXPECT_NEAR(double(cfl_time_step(Real(0.05), Real(1.2e-3), Real(6144), Real(300))), expected,
              4 * std::numeric_limits<Real>::epsilon() * expected);
  // Linear in C and h, decreasing in c and |u|.
  EXPECT_NEAR(double(cfl_time_step(Real(0.1), Real(1.2e-3), Real(6144), Real(300))), 2 * expected,
              8 * std::numeric_limits<Real>::epsilon() * expected);
  EXPECT_LT(cfl_time_step(Real(0.05), Real(1.2e-3), Real(6144), Real(600)),
            cfl_time_step(Real(0.05), Real(1.2e-3), Real(6144), Real(300)));
  // At rest: C h / c.
  EXPECT_NEAR(double(cfl_time_step(Real(0.05), Real(1e-3), Real(5000), Real(0))), 1e-8,
              4 * std::numeric_limits<Real>::epsilon() * 1e-8);
}

// ---- delta-SPH ----

// Uniform density with zero gradients: no diffusion.
TYPED_TEST(ViscosityTyped, DeltaSphZeroForUniformDensity) {
  using Real = TypeParam;
  const Real h = Real(1.2e-3), V = Real(1e-9), rho = Real(7850);
  const Vec3<Real> zero{0, 0, 0};
  for (Vec3<Real> xij : {Vec3<Real>{Real(1e-3), 0, 0}, Vec3<Real>{Real(0.3e-3), Real(-0.9e-3), Real(0.5e-3)}}) {
    const Vec3<Real> g = kernel_grad(KernelKind::WendlandC2, xij, h);
    EXPECT_EQ(delta_sph_term(V, rho, rho, xij, zero, zero, g), Real(0));
  }
  // A coincident pair contributes nothing (and no NaN).
  EXPECT_EQ(delta_sph_term(V, rho, Real(8000), zero, zero, zero, zero), Real(0));
}

// A linear density field with its exact gradient is not diffused: psi . x_ji = 2 (rho_j - rho_i)
// - (g_i + g_j) . x_ji = 0 (the point of the renormalised-gradient correction; a wrong sign in either
// term would give 4 (rho_j - rho_i)). double: cancellation of terms of size ~ |g| r ~ 1e3, 1e-10 relative.
TEST(DeltaSph, ZeroForLinearDensityWithExactGradient) {
  const double h = 1.2e-3, V = 1e-9;
  const Vec3<double> g{2e5, -1e5, 3e5};  // kg/m^4
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-1.2e-3, 1.2e-3);
  for (int t = 0; t < 100; ++t) {
    const Vec3<double> xi{u(gen), u(gen), u(gen)}, xj{u(gen), u(gen), u(gen)};
    const Vec3<double> xij = xi - xj;
    const double rho_i = 7850 + dot(g, xi), rho_j = 7850 + dot(g, xj);
    const Vec3<double> gw = kernel_grad(KernelKind::WendlandC2, xij, h);
    const double term = delta_sph_term(V, rho_i, rho_j, xij, g, g, gw);
    // Scale of one half of psi . grad W: V 2 |rho_j - rho_i| |grad W| / r.
    const double scale = V * 2 * std::abs(dot(g, xij)) * std::abs(kernel_grad_factor(KernelKind::WendlandC2, norm(xij), h));
    EXPECT_NEAR(term, 0.0, 1e-10 * scale + 1e-300) << t;
  }
}

// Pair term by hand, and its sign: with zero gradients, i denser than j, the term is
// V 2 (rho_i - rho_j)/r^2 x_ij . F x_ij = 2 V F (rho_i - rho_j) < 0 (F < 0): density diffuses from i to j.
TYPED_TEST(ViscosityTyped, DeltaSphPairByHandAndDiffusiveSign) {
  using Real = TypeParam;
  const Real h = Real(1.2e-3), V = Real(1e-9);
  const Vec3<Real> xij{Real(0.6e-3), Real(0.8e-3), 0}, zero{0, 0, 0};
  const Real F = kernel_grad_factor(KernelKind::WendlandC2, norm(xij), h);
  const Vec3<Real> gw = F * xij;
  const Real t = delta_sph_term(V, Real(7900), Real(7850), xij, zero, zero, gw);
  const double expected = 2.0 * double(V) * double(F) * 50.0;
  EXPECT_NEAR(double(t), expected, 10 * std::numeric_limits<Real>::epsilon() * std::abs(expected) * 7900 / 50);
  EXPECT_LT(t, Real(0));
  // With gradients: psi = 2 (rho_j - rho_i)(x_j - x_i)/r^2 - (g_i + g_j); the gradient part adds
  // -V (g_i + g_j) . grad W.
  const Vec3<Real> gi{Real(1e5), Real(-2e5), Real(3e4)}, gj{Real(-4e4), Real(1e5), Real(2e5)};
  const Real t2 = delta_sph_term(V, Real(7900), Real(7850), xij, gi, gj, gw);
  const double extra = -double(V) * double(dot(gi + gj, gw));
  EXPECT_NEAR(double(t2), expected + extra, 1e-5 * (std::abs(expected) + std::abs(extra)));
}

// Antisymmetry. The vector psi_ij of F 2.18 / Marrone is symmetric in (i, j): both
// (rho_j - rho_i)(x_j - x_i) and (g_i + g_j) are unchanged by the swap. What is antisymmetric, and what
// conserves mass, is the pair term psi_ij . grad_i W_ij, because grad_j W_ji = -grad_i W_ij: the term of j
// from i is exactly minus the term of i from j (equal volumes). Bitwise in both precisions (negation and
// commutative additions are exact).
TYPED_TEST(ViscosityTyped, DeltaSphPairTermIsAntisymmetric) {
  using Real = TypeParam;
  const Real h = Real(1.2e-3), V = Real(1e-9);
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1.2e-3, 1.2e-3), r(7700, 8000), g(-3e5, 3e5);
  for (int t = 0; t < 50; ++t) {
    const Vec3<Real> xij{Real(u(gen)), Real(u(gen)), Real(u(gen))};
    const Vec3<Real> gi{Real(g(gen)), Real(g(gen)), Real(g(gen))}, gj{Real(g(gen)), Real(g(gen)), Real(g(gen))};
    const Real ri = Real(r(gen)), rj = Real(r(gen));
    const Vec3<Real> gw_ij = kernel_grad(KernelKind::WendlandC2, xij, h);
    const Vec3<Real> gw_ji = kernel_grad(KernelKind::WendlandC2, -xij, h);
    EXPECT_EQ(gw_ji.x, -gw_ij.x);
    EXPECT_EQ(delta_sph_term(V, rj, ri, -xij, gj, gi, gw_ji), -delta_sph_term(V, ri, rj, xij, gi, gj, gw_ij)) << t;
  }
}

// Hence the diffusion conserves mass: on a small lattice with random densities and gradients, the total
// sum_i V_i sum_j V_j psi_ij . grad_i W_ij vanishes to rounding.
TEST(DeltaSph, LatticeSumConservesMass) {
  const double dx = 1e-3, h = 1.2 * dx, V = dx * dx * dx;
  std::mt19937 gen(17);
  std::uniform_real_distribution<double> r(7700, 8000), g(-3e5, 3e5);
  std::vector<Vec3<double>> x, grad;
  std::vector<double> rho;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        x.push_back({i * dx, j * dx, k * dx});
        rho.push_back(r(gen));
        grad.push_back({g(gen), g(gen), g(gen)});
      }
  double total = 0, magnitude = 0;
  for (size_t i = 0; i < x.size(); ++i)
    for (size_t j = 0; j < x.size(); ++j) {
      if (i == j) continue;
      const Vec3<double> xij = x[i] - x[j];
      const double t = V * delta_sph_term(V, rho[i], rho[j], xij, grad[i], grad[j], kernel_grad(KernelKind::WendlandC2, xij, h));
      total += t;
      magnitude += std::abs(t);
    }
  EXPECT_GT(magnitude, 0.0);
  EXPECT_NEAR(total, 0.0, 1e-13 * magnitude);
}

// ---- Signal speed (material.hpp) ----

// Weldox 460 E (validation.md): E 200 GPa, nu 0.33, rho 7850: K = E/(3(1 - 2 nu)) = 196.08 GPa,
// G = E/(2(1 + nu)) = 75.19 GPa. The elastic signal speed is the longitudinal c_L = sqrt((K + 4G/3)/rho)
// = 6144 m/s; a hydrodynamic material gets the bulk speed 4998 m/s; shear speed sqrt(G/rho) = 3095 m/s.
// Within 1 m/s (validation.md gives whole m/s).
TYPED_TEST(ViscosityTyped, SignalSpeedIsLongitudinalWaveSpeedForWeldox) {
  using Real = TypeParam;
  const double E = 200e9, nu = 0.33, rho0 = 7850;
  const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  MaterialParams<Real> m;
  m.eos.kind = EosKind::Linear;
  m.eos.rho0 = Real(rho0);
  m.eos.k1 = Real(K);
  m.strength.kind = StrengthKind::Elastic;
  m.strength.shear_modulus = Real(G);
  Real c_bulk = 0;
  eos_pressure(m.eos, m.eos.rho0, Real(0), c_bulk);
  EXPECT_NEAR(double(c_bulk), 4998.0, 1.0);
  EXPECT_NEAR(double(signal_speed(m, c_bulk, m.eos.rho0)), 6144.0, 1.0);
  EXPECT_NEAR(double(signal_speed(m, c_bulk, m.eos.rho0)), std::sqrt((K + 4 * G / 3) / rho0),
              1e-5 * 6144);  // the closed form itself, at float precision
  EXPECT_NEAR(std::sqrt(G / rho0), 3095.0, 1.0);
  m.strength.kind = StrengthKind::PerfectlyPlastic;
  EXPECT_NEAR(double(signal_speed(m, c_bulk, m.eos.rho0)), 6144.0, 1.0);
  m.strength.kind = StrengthKind::Hydrodynamic;
  EXPECT_EQ(signal_speed(m, c_bulk, m.eos.rho0), c_bulk);
}

}  // namespace

namespace {

// Balsara (1995) limiter: 1 in pure compression, 0 in rigid rotation, small in simple shear.
TEST(BalsaraFactor, CompressionRotationAndShear) {
  using impactsph::Mat3;
  const double c = 5000.0, h = 1e-3;  // the floor term 1e-4 c/h = 500 1/s
  const Mat3<double> compression{{{-1e5, 0, 0}, {0, -1e5, 0}, {0, 0, -1e5}}};
  const Mat3<double> rotation{{{0, -1e5, 0}, {1e5, 0, 0}, {0, 0, 0}}};
  const Mat3<double> shear{{{0, 1e5, 0}, {0, 0, 0}, {0, 0, 0}}};
  EXPECT_NEAR(impactsph::balsara_factor(compression, c, h), 3e5 / (3e5 + 500.0), 1e-15);
  EXPECT_NEAR(impactsph::balsara_factor(rotation, c, h), 0.0, 1e-15);
  EXPECT_NEAR(impactsph::balsara_factor(shear, c, h), 0.0, 1e-15);  // isochoric: no divergence
  const Mat3<double> mixed{{{-1e5, 1e5, 0}, {0, 0, 0}, {0, 0, 0}}};     // |div| = |curl| = 1e5
  EXPECT_NEAR(impactsph::balsara_factor(mixed, c, h), 1e5 / (2e5 + 500.0), 1e-15);
}

}  // namespace

// ---- Limited midpoint reconstruction of the viscosity's jump (viscosity.hpp, limited_midpoint_jump) ----
namespace {

using impactsph::Mat3;
using impactsph::Vec3;
using impactsph::ViscosityParams;

ViscosityParams<double> limited(double h_factor = 1.2) {
  return impactsph::limited_viscosity_params(1.0, 1.0, true, h_factor);
}

TEST(VanLeerLimiter, OneWhereSlopesAgreeZeroWhereTheyDisagree) {
  EXPECT_EQ(impactsph::van_leer_limiter(1.0), 1.0);
  EXPECT_EQ(impactsph::van_leer_limiter(0.0), 0.0);
  EXPECT_EQ(impactsph::van_leer_limiter(-2.0), 0.0);
  EXPECT_NEAR(impactsph::van_leer_limiter(3.0), 0.75, 1e-15);  // 4 * 3 / 16
  EXPECT_NEAR(impactsph::van_leer_limiter(1.0 / 3.0), 0.75, 1e-15);
}

// In a linear velocity field v = G x (uniform compression, shear, rotation: what plastic flow looks like
// over one kernel), both sides carry G, and the jump reconstructed to the midpoint is zero: the Monaghan
// term then leaves the flow alone, while on the raw jump it resists it.
TEST(LimitedMidpointJump, VanishesInALinearVelocityField) {
  const double h = 1.2e-3;
  const Mat3<double> G{{{-2e4, 3e4, 1e3}, {5e3, 1.5e4, -2e3}, {0, 4e3, 5e3}}};  // 1/s, compressive along x
  const ViscosityParams<double> p = limited();
  // pairs at one spacing (1 mm) or farther, where the close-approach fold does not act
  for (const Vec3<double> xij : {Vec3<double>{1e-3, 0, 0}, Vec3<double>{0.9e-3, 0.6e-3, 0},
                                 Vec3<double>{-0.5e-3, 0.4e-3, 0.8e-3}}) {
    const Vec3<double> vij = G * xij;
    const Vec3<double> jump = impactsph::limited_midpoint_jump(p, xij, vij, G, G, h);
    EXPECT_LT(impactsph::norm(jump), 1e-12 * impactsph::norm(vij));
    EXPECT_EQ(impactsph::monaghan_viscosity(p, xij, jump, h, 4000.0, 8900.0), 0.0);
  }
  // the raw jump of the first pair closes, and the unlimited term resists the flow
  EXPECT_GT(impactsph::monaghan_viscosity(p, Vec3<double>{1e-3, 0, 0}, G * Vec3<double>{1e-3, 0, 0}, h, 4000.0, 8900.0),
            0.0);
}

// What the gradient does not register keeps its jump: a pair closing with no gradient on either side (a
// particle sliding past its neighbours), and slopes of opposite signs (an extremum between the two: a
// shock front) give the raw jump back.
TEST(LimitedMidpointJump, KeepsTheNonAffineJumpAndShocks) {
  const double h = 1.2e-3;
  const ViscosityParams<double> p = limited();
  const Vec3<double> xij{1e-3, 0, 0}, vij{-50, 10, 0};
  const Vec3<double> still = impactsph::limited_midpoint_jump(p, xij, vij, Mat3<double>::zero(), Mat3<double>::zero(), h);
  EXPECT_EQ(still.x, vij.x);
  EXPECT_EQ(still.y, vij.y);
  const Mat3<double> squeeze{{{-1e5, 0, 0}, {0, 0, 0}, {0, 0, 0}}}, stretch{{{1e5, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
  const Vec3<double> shock = impactsph::limited_midpoint_jump(p, xij, vij, squeeze, stretch, h);
  EXPECT_EQ(shock.x, vij.x);
  // slopes of one sign but 3:1 apart: phi = 0.75 of the mean slope is taken off
  const Mat3<double> third{{{-1e5 / 3, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
  const Vec3<double> partial = impactsph::limited_midpoint_jump(p, xij, vij, squeeze, third, h);
  EXPECT_NEAR(partial.x, -50 - 0.5 * 0.75 * (-100 - 100.0 / 3), 1e-12);
}

// Closer than one spacing (h / h_factor) the reconstruction folds out over 0.2 spacings: a pair being
// crushed meets the full viscosity.
TEST(LimitedMidpointJump, FadesOutAtCloseApproach) {
  const double h = 1.2e-3, dx = 1e-3;
  const ViscosityParams<double> p = limited(1.2);
  const Mat3<double> G{{{-1e5, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
  auto jump_at = [&](double r) {
    const Vec3<double> xij{r, 0, 0};
    return impactsph::limited_midpoint_jump(p, xij, G * xij, G, G, h).x / (G * xij).x;  // share of the raw jump
  };
  EXPECT_NEAR(jump_at(1.0 * dx), 0.0, 1e-12);
  EXPECT_NEAR(jump_at(0.8 * dx), 1 - std::exp(-1.0), 1e-12);
  EXPECT_NEAR(jump_at(0.5 * dx), 1 - std::exp(-6.25), 1e-12);
}

// The jump the term acts on (viscous_jump): a pair in shear has v_ij . x_ij = 0 to round-off. On a pair
// whose two sides stretch along x_ij the reconstruction closes it by 2 m/s; gated on the raw jump alone, a
// finite Pi then switched on at v_ij . x_ij = -1e-12 and off at +1e-12. The raw jump caps it instead, so
// both sides of the gate give (next to) nothing.
TEST(ViscousJump, ContinuousWhereAPairInShearStopsClosing) {
  const double h = 2e-3;
  const ViscosityParams<double> p = limited(2.0);
  const Vec3<double> xij{1e-3, 0, 0};
  const Mat3<double> stretch{{{2e3, 0, 0}, {0, 0, 0}, {0, 0, 0}}};  // 1/s: each side's slope x . G x = 2e-3 m^2/s
  const double scale = impactsph::monaghan_viscosity(p, xij, Vec3<double>{-2, 0, 0}, h, 4000.0, 8900.0);
  ASSERT_GT(scale, 0.0);
  for (const double vx : {-1e-9, -1e-12, 0.0, 1e-12, 1e-9}) {
    const Vec3<double> vij{vx, 50, 0};
    const Vec3<double> jump = impactsph::viscous_jump(p, xij, vij, stretch, stretch, h);
    EXPECT_LT(impactsph::monaghan_viscosity(p, xij, jump, h, 4000.0, 8900.0), 1e-6 * scale) << vx;
  }
  // the reconstruction on its own would close this pair at 2 m/s
  const Vec3<double> alone = impactsph::limited_midpoint_jump(p, xij, Vec3<double>{-1e-12, 50, 0}, stretch, stretch, h);
  EXPECT_NEAR(impactsph::dot(alone, xij) / 1e-3, -2.0, 1e-6);
}

// Over closing pairs with gradients of every kind, the limited term is at most the term on the raw jump; an
// opening pair gets none; with the limiter off the raw jump is taken as it is.
TEST(ViscousJump, NeverMoreThanTheTermOnTheRawJump) {
  const double h = 2e-3, c = 4000.0, rho = 8900.0;
  const ViscosityParams<double> p = limited(2.0);
  ViscosityParams<double> off = p;
  off.limited = false;
  std::uint64_t state = 12345;
  auto uniform = [&state]() {  // in [-1, 1), a fixed sequence
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-52 - 1.0;
  };
  int capped = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vec3<double> xij{1.5e-3 * uniform(), 1.5e-3 * uniform(), 1.5e-3 * uniform()};
    const Vec3<double> vij{20 * uniform(), 20 * uniform(), 20 * uniform()};
    Mat3<double> gi, gj;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        gi.m[a][b] = 2e4 * uniform();
        gj.m[a][b] = 2e4 * uniform();
      }
    const Vec3<double> jump = impactsph::viscous_jump(p, xij, vij, gi, gj, h);
    const double raw = impactsph::monaghan_viscosity(p, xij, vij, h, c, rho);
    const double lim = impactsph::monaghan_viscosity(p, xij, jump, h, c, rho);
    EXPECT_LE(lim, raw) << n;
    if (impactsph::dot(vij, xij) >= 0) EXPECT_EQ(lim, 0.0) << n;
    const Vec3<double> recon = impactsph::limited_midpoint_jump(p, xij, vij, gi, gj, h);
    if (impactsph::dot(vij, xij) < 0 && impactsph::dot(recon, xij) < impactsph::dot(vij, xij)) ++capped;
    const Vec3<double> as_is = impactsph::viscous_jump(off, xij, vij, gi, gj, h);
    EXPECT_EQ(as_is.x, vij.x);
    EXPECT_EQ(as_is.z, vij.z);
  }
  EXPECT_GT(capped, 100) << "the sample must hold pairs that the reconstruction closes harder than the raw jump";
}

}  // namespace
