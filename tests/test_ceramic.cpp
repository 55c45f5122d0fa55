// Unit and analytic tests of the JH-2 ceramic model (X eqs 22-28; Johnson and Holmquist 1994) with the
// AD-995 alumina constants of X Table 1, and of the variable smoothing length (X eqs 9-10).
//
// Hand values (Python, double): sigma_HEL = 1.5 (HEL - P_HEL) = 1.995 GPa; T* = 0.2/1.46.
//   intact  sigma_i*(P = P_HEL) = 0.93 (1 + T*)^0.6        = 1.0044679588507313
//           sigma_i*(P = 0.5 GPa)                          = 0.5983152316889153
//           sigma_i*(P = -0.1 GPa)                         = 0.18615351242302738
//   fractured sigma_f*(P = 2 GPa) = 0.31 (2/1.46)^0.6      = 0.3744277065425993
//   flow stress at P = 2 GPa, D = 0.4                      = 1.7224949782415552 GPa
//   eps_f(P = 1 GPa) = 0.005 (1/1.46 + 0.2/1.46)           = 0.00410958904109589
//   bulking at mu = 0.01 (P = K1 mu = 1.3095 GPa), D 0 -> 1, beta = 1:
//     sigma(D=0) = 1.892840438081903 GPa, sigma(D=1) = 0.5793702381643289 GPa,
//     dU = (s0^2 - s1^2)/(6 G) = 6.002615814787598 MJ/m^3, dP = 0.50347416746430016 GPa.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/damage.hpp"
#include "common/integration.hpp"
#include "common/material.hpp"
#include "common/smoothing_length.hpp"

namespace {

using namespace impactsph;

// AD-995 alumina, X Table 1 (Cronin et al. 2003).
MaterialParams<double> alumina() {
  MaterialParams<double> m;
  m.eos.kind = EosKind::Polynomial;
  m.eos.rho0 = 3921;
  m.eos.k1 = 130.95e9;
  m.strength.kind = StrengthKind::JohnsonHolmquist2;
  m.strength.shear_modulus = 90.16e9;
  m.strength.jh2.a = 0.93;
  m.strength.jh2.b = 0.31;
  m.strength.jh2.c = 0.0;
  m.strength.jh2.m = 0.6;
  m.strength.jh2.n = 0.6;
  m.strength.jh2.hel = 2.79e9;
  m.strength.jh2.p_hel = 1.46e9;
  m.strength.jh2.tensile_pressure = 0.2e9;
  m.strength.reference_strain_rate = 1.0;
  m.damage.kind = DamageKind::JohnsonHolmquist2;
  m.damage.jh2.d1 = 0.005;
  m.damage.jh2.d2 = 1.0;
  m.damage.jh2.bulking = 1.0;
  m.damage.scale_pairs = false;
  return m;
}

TEST(Jh2, SigmaHelFromHelAndPressureAtHel) { EXPECT_DOUBLE_EQ(jh2_sigma_hel(alumina().strength), 1.995e9); }

TEST(Jh2, IntactStrengthSurface) {
  const double ts = 0.2 / 1.46;
  EXPECT_NEAR(jh2_intact_strength(0.93, 0.6, 0.0, 1.0, ts, 1.0), 1.0044679588507313, 1e-14);
  EXPECT_NEAR(jh2_intact_strength(0.93, 0.6, 0.0, 0.5 / 1.46, ts, 1.0), 0.5983152316889153, 1e-14);
  EXPECT_NEAR(jh2_intact_strength(0.93, 0.6, 0.0, -0.1 / 1.46, ts, 1.0), 0.18615351242302738, 1e-14);
  // At and beyond the tensile limit P = -T: no strength.
  EXPECT_EQ(jh2_intact_strength(0.93, 0.6, 0.0, -ts, ts, 1.0), 0.0);
  EXPECT_EQ(jh2_intact_strength(0.93, 0.6, 0.0, -2 * ts, ts, 1.0), 0.0);
  // Rate factor 1 + C ln eps_dot*: C = 0.01 at eps_dot* = e^2 multiplies by 1.02.
  EXPECT_NEAR(jh2_intact_strength(0.93, 0.6, 0.01, 1.0, ts, std::exp(2.0)), 1.02 * 1.0044679588507313, 1e-14);
}

TEST(Jh2, FracturedStrengthAndCap) {
  EXPECT_NEAR(jh2_fractured_strength(0.31, 0.6, 0.0, 2.0 / 1.46, 1.0, 1e30), 0.3744277065425993, 1e-14);
  EXPECT_EQ(jh2_fractured_strength(0.31, 0.6, 0.0, 0.0, 1.0, 1e30), 0.0);   // no confinement, no strength
  EXPECT_EQ(jh2_fractured_strength(0.31, 0.6, 0.0, -0.5, 1.0, 1e30), 0.0);
  EXPECT_EQ(jh2_fractured_strength(0.31, 0.6, 0.0, 2.0 / 1.46, 1.0, 0.2), 0.2);  // SFMAX
}

TEST(Jh2, DamagedFlowStress) {
  const MaterialParams<double> m = alumina();
  EXPECT_NEAR(jh2_flow_stress(m.strength, 2e9, 0.0, 0.4), 1.7224949782415552e9, 1e-3);
  EXPECT_NEAR(jh2_flow_stress(m.strength, 2e9, 0.0, 1.0), 1.995e9 * 0.3744277065425993, 1e-3);
  EXPECT_NEAR(jh2_flow_stress(m.strength, 1.46e9, 0.0, 0.0), 1.995e9 * 1.0044679588507313, 1e-3);
}

TEST(Jh2, PlasticUpdateReturnsToTheJh2SurfaceAndKeepsFracturedStrength) {
  const MaterialParams<double> m = alumina();
  // A trial deviator far outside the surface, at P = 2 GPa.
  for (double D : {0.0, 0.4, 1.0}) {
    Sym3<double> S{-4e9, 2e9, 2e9, 0, 0, 0};
    const PlasticResult<double> r = plastic_update(m, S, 0.0, 0.0, 293.0, 3921.0, D, 2e9);
    EXPECT_GT(r.d_eps_p, 0.0);
    EXPECT_NEAR(von_mises(S), jh2_flow_stress(m.strength, 2e9, 0.0, D), 1e-3) << D;
    EXPECT_GT(von_mises(S), 0.0) << "a fully damaged JH-2 particle keeps its fractured strength";
  }
}

TEST(Jh2, FailureStrainAndDamageGrowth) {
  const MaterialParams<double> m = alumina();
  EXPECT_NEAR(jh2_failure_strain(0.005, 1.0, 1.0 / 1.46, 0.2 / 1.46, 0.0), 0.00410958904109589, 1e-17);
  // At the tensile limit eps_f falls to EFMIN: 0 fails at once, a floor holds.
  EXPECT_EQ(jh2_failure_strain(0.005, 1.0, -0.2 / 1.46, 0.2 / 1.46, 0.0), 0.0);
  EXPECT_EQ(jh2_failure_strain(0.005, 1.0, -0.3 / 1.46, 0.2 / 1.46, 0.01), 0.01);
  // X eq 25: D grows by d_eps_p / eps_f.
  const double dD = damage_increment(m, 1e-4, 1e-4, 0.0, 1e9, 1e9, 0.0, 293.0);
  EXPECT_NEAR(dD, 1e-4 / 0.00410958904109589, 1e-12);
  EXPECT_EQ(damage_increment(m, 0.0, 0.0, 0.0, 1e9, 1e9, 0.0, 293.0), 0.0);  // no flow, no damage
  EXPECT_EQ(damage_increment(m, 1e-6, 1e-6, 0.0, -0.3e9, 1e9, 0.0, 293.0), 1.0);  // beyond the tensile limit
}

TEST(Jh2, TensilePressureLimitFallsWithDamage) {
  const MaterialParams<double> m = alumina();
  for (auto [D, expected] : {std::pair{0.0, -0.2e9}, {0.5, -0.1e9}, {1.0, 0.0}}) {
    double P = -1e9;
    Sym3<double> S{1e8, -5e7, -5e7, 0, 0, 0};
    apply_failure(m, S, P, D);
    EXPECT_NEAR(P, expected, 1e-3) << D;
    EXPECT_EQ(S.xx, 1e8) << "the JH-2 deviator is left to the strength model";
  }
  double P = 3e9;
  Sym3<double> S = Sym3<double>::zero();
  apply_failure(m, S, P, 1.0);
  EXPECT_EQ(P, 3e9);  // compression is untouched
}

TEST(Jh2, BulkingPressureFromLostElasticEnergy) {
  const MaterialParams<double> m = alumina();
  const double rho = 3921 * 1.01, P = 130.95e9 * 0.01;
  const double dP = jh2_bulking_increment(m, rho, P, 0.0, 1.0, 0.0, 0.0);
  EXPECT_NEAR(dP, 0.50347416746430016e9, 1e-2 * 1e3);  // within 10 kPa of 0.503 GPa
  // The energy balance it solves: (dP - 0) mu + dP^2/(2 K1) = beta dU.
  const double s0 = jh2_flow_stress(m.strength, P, 0.0, 0.0), s1 = jh2_flow_stress(m.strength, P, 0.0, 1.0);
  const double dU = (s0 * s0 - s1 * s1) / (6 * 90.16e9);
  EXPECT_NEAR(dP * 0.01 + dP * dP / (2 * 130.95e9), dU, 1e-9 * dU);
  // No bulking without damage growth, with beta = 0, or for other materials; never decreasing.
  EXPECT_EQ(jh2_bulking_increment(m, rho, P, 0.5, 0.5, 0.0, 1e8), 1e8);
  MaterialParams<double> nb = m;
  nb.damage.jh2.bulking = 0;
  EXPECT_EQ(jh2_bulking_increment(nb, rho, P, 0.0, 1.0, 0.0, 0.0), 0.0);
  // The material pressure adds it to the EOS pressure for the JH-2 damage model only, and only that model
  // grows it (damage_added_pressure dispatches to it).
  double c = 0;
  EXPECT_NEAR(material_pressure(m, rho, 0.0, dP, c), P + dP, 1e-3);
  EXPECT_EQ(damage_added_pressure(m, rho, P, 0.0, 1.0, 0.0, 0.0), dP);
  MaterialParams<double> metal = m;
  metal.strength.kind = StrengthKind::JohnsonCook;
  metal.damage.kind = DamageKind::JohnsonCook;
  EXPECT_NEAR(material_pressure(metal, rho, 0.0, dP, c), P, 1e-3);
  EXPECT_EQ(damage_added_pressure(metal, rho, P, 0.0, 1.0, 0.0, 1e8), 1e8);
}

TEST(Jh2, PairDamageOnlyForMaterialsThatScalePairs) {
  MaterialParams<double> m = alumina();
  EXPECT_EQ(pair_damage(m, 1.0), 0.0);
  m.damage.scale_pairs = true;
  EXPECT_EQ(pair_damage(m, 0.7), 0.7);
}

// The end of a step (integration.hpp, both solvers): from D = 0 at mu = 0.01 (P = K1 mu), a plastic
// increment of twice the failure strain fails the particle (X eq 25), the strength it loses becomes the
// bulking pressure of the hand values above, and the pressure carries it.
TEST(Jh2, FinishStepDamagesBulksAndRaisesThePressure) {
  const MaterialParams<double> m = alumina();
  const double rho = 3921 * 1.01, P_eos = 130.95e9 * 0.01;
  const double eps_f = 0.005 * (P_eos / 1.46e9 + 0.2 / 1.46);
  Sym3<double> S{1e8, -5e7, -5e7, 0, 0, 0};
  double eps_p = 0, work = 0, T = 293, D = 0, P = 0, bulking = 0;
  finish_step(m, rho, 0.0, S, eps_p, work, T, D, P, bulking, 2 * eps_f, 1.5e3, 0.0, 0.0);
  EXPECT_EQ(eps_p, 2 * eps_f);
  EXPECT_EQ(work, 1.5e3);  // the plastic work per unit mass of the step, J/kg, accumulated
  EXPECT_EQ(D, 1.0);
  EXPECT_NEAR(bulking, 0.50347416746430016e9, 1e4);
  EXPECT_NEAR(P, P_eos + bulking, 1e-3);
  EXPECT_EQ(S.xx, 1e8) << "a JH-2 particle keeps its deviator (the fractured strength bounds it)";
  // A failed metal particle (D reaching 1) carries no deviator and no tension.
  MaterialParams<double> metal;
  metal.eos = m.eos;
  metal.strength.kind = StrengthKind::PerfectlyPlastic;
  metal.strength.shear_modulus = 80e9;
  metal.strength.perfectly_plastic.yield_stress = 1e9;
  metal.damage.kind = DamageKind::CriticalPlasticStrain;
  metal.damage.critical_plastic_strain.strain = 0.1;
  Sym3<double> Sm{1e8, -5e7, -5e7, 0, 0, 0};
  double eps_m = 0.09, wm = 0, Tm = 293, Dm = 0, Pm = 0, bm = 0;
  finish_step(metal, 3921 * 0.99, 0.0, Sm, eps_m, wm, Tm, Dm, Pm, bm, 0.02, 0.0, 0.0, 0.0);
  EXPECT_EQ(Dm, 1.0);
  EXPECT_EQ(Sm.xx, 0.0);
  EXPECT_EQ(Pm, 0.0);
  EXPECT_EQ(bm, 0.0);
}

// The gpu port's float build takes every constant of the material, converted (convert_material).
TEST(Jh2, MaterialConstantsConvertToFloat) {
  MaterialParams<double> m = alumina();
  m.strength.jh2.sfmax = 0.8;
  m.damage.jh2.min_failure_strain = 0.01;
  m.specific_heat = 880;
  const MaterialParams<float> f = convert_material<float>(m);
  EXPECT_EQ(f.strength.kind, StrengthKind::JohnsonHolmquist2);
  EXPECT_EQ(f.damage.kind, DamageKind::JohnsonHolmquist2);
  EXPECT_EQ(f.eos.kind, EosKind::Polynomial);
  EXPECT_FLOAT_EQ(f.eos.k1, 130.95e9f);
  EXPECT_FLOAT_EQ(f.strength.jh2.a, 0.93f);
  EXPECT_FLOAT_EQ(f.strength.jh2.b, 0.31f);
  EXPECT_FLOAT_EQ(f.strength.jh2.m, 0.6f);
  EXPECT_FLOAT_EQ(f.strength.jh2.hel, 2.79e9f);
  EXPECT_FLOAT_EQ(f.strength.jh2.p_hel, 1.46e9f);
  EXPECT_FLOAT_EQ(f.strength.jh2.tensile_pressure, 0.2e9f);
  EXPECT_FLOAT_EQ(f.strength.jh2.sfmax, 0.8f);
  EXPECT_FLOAT_EQ(f.damage.jh2.d1, 0.005f);
  EXPECT_FLOAT_EQ(f.damage.jh2.bulking, 1.0f);
  EXPECT_FLOAT_EQ(f.damage.jh2.min_failure_strain, 0.01f);
  EXPECT_FALSE(f.damage.scale_pairs);
  EXPECT_FLOAT_EQ(f.specific_heat, 880.0f);
  // The float flow stress follows the double one.
  EXPECT_NEAR(jh2_flow_stress(f.strength, 2e9f, 0.0f, 0.4f), 1.7224949782415552e9, 1e3);
}

// Analytic: a uniaxial-strain compression (plate impact) driven through the constitutive update that the
// solver uses (EOS pressure, Jaumann rate, JH-2 return) yields at the Hugoniot elastic limit. Before
// yield sigma_x = P + 4/3 G eps (log strain eps); the first plastic step gives sigma_x = HEL, which the
// constants of X Table 1 put at 2.79 GPa (their P_HEL = 1.46 GPa and G, K1 are consistent with it).
TEST(Jh2Analytic, UniaxialStrainCompressionFindsTheHel) {
  const MaterialParams<double> m = alumina();
  const double rate = 1e4;  // 1/s; C = 0, so the rate does not matter
  const double dt = 1e-10;  // strain 1e-6 per step
  Mat3<double> grad_v = Mat3<double>::zero();
  grad_v.m[0][0] = -rate;
  double rho = m.eos.rho0, eps_p = 0, D = 0;
  Sym3<double> S = Sym3<double>::zero();
  double hel = -1, p_at_hel = -1;
  for (int step = 0; step < 40000 && hel < 0; ++step) {
    rho *= std::exp(rate * dt);  // d rho/dt = -rho div v
    S = S + dt * deviatoric_stress_rate(m, S, grad_v);
    double c = 0;
    double P = material_pressure(m, rho, 0.0, 0.0, c);
    apply_failure(m, S, P, D);
    const PlasticResult<double> r = plastic_update(m, S, eps_p, rate, 293.0, rho, D, P);
    if (r.d_eps_p > 0) {
      hel = P - S.xx;  // longitudinal compressive stress -sigma_xx
      p_at_hel = P;
    }
    eps_p += r.d_eps_p;
  }
  ASSERT_GT(hel, 0) << "never yielded";
  std::printf("uniaxial strain: HEL %.4f GPa at P %.4f GPa\n", hel * 1e-9, p_at_hel * 1e-9);
  EXPECT_NEAR(hel, 2.79e9, 0.01 * 2.79e9) << "HEL " << hel << " Pa";
  EXPECT_NEAR(p_at_hel, 1.46e9, 0.02 * 1.46e9) << "P at the HEL " << p_at_hel << " Pa";
}

// Past the HEL, continued uniaxial compression damages the ceramic (eps_f is small: D1 = 0.005) and the
// bulking pressure rises; nothing becomes NaN.
TEST(Jh2Analytic, CompressionPastTheHelDamagesAndBulks) {
  const MaterialParams<double> m = alumina();
  const double rate = 1e4, dt = 1e-10;
  Mat3<double> grad_v = Mat3<double>::zero();
  grad_v.m[0][0] = -rate;
  double rho = m.eos.rho0, eps_p = 0, D = 0, dP = 0;
  Sym3<double> S = Sym3<double>::zero();
  for (int step = 0; step < 30000; ++step) {  // 3 % strain
    rho *= std::exp(rate * dt);
    S = S + dt * deviatoric_stress_rate(m, S, grad_v);
    double c = 0;
    double P = material_pressure(m, rho, 0.0, dP, c);
    apply_failure(m, S, P, D);
    const PlasticResult<double> r = plastic_update(m, S, eps_p, rate, 293.0, rho, D, P);
    eps_p += r.d_eps_p;
    const double D_old = D;
    D = std::min(1.0, D + damage_increment(m, r.d_eps_p, eps_p, 0.0, P, von_mises(S), rate, 293.0));
    dP = jh2_bulking_increment(m, rho, P, D_old, D, rate, dP);
  }
  EXPECT_EQ(D, 1.0);
  EXPECT_GT(dP, 0.0);
  EXPECT_TRUE(std::isfinite(von_mises(S)));
  EXPECT_GT(von_mises(S), 0.0);  // fractured strength under confinement
}

TEST(SmoothingLength, RateAndBounds) {
  EXPECT_DOUBLE_EQ(smoothing_length_rate(1e-3, 300.0), 0.1);  // (1/3) h div v
  EXPECT_DOUBLE_EQ(advance_smoothing_length(1e-3, 300.0, 1e-3, 0.2e-3, 2e-3), 1.1e-3);  // expansion grows h
  EXPECT_DOUBLE_EQ(advance_smoothing_length(1e-3, -300.0, 1e-3, 0.2e-3, 2e-3), 0.9e-3);
  EXPECT_DOUBLE_EQ(advance_smoothing_length(1e-3, 3e5, 1e-3, 0.2e-3, 2e-3), 2e-3);   // HMAX
  EXPECT_DOUBLE_EQ(advance_smoothing_length(1e-3, -3e5, 1e-3, 0.2e-3, 2e-3), 0.2e-3);  // HMIN
  // Consistency with continuity: h^3 rho stays constant to first order.
  const double h = 1e-3, divv = 50.0, dt = 1e-6, rho = 1000;
  const double h1 = advance_smoothing_length(h, divv, dt, 0.0, 1.0), rho1 = rho * (1 - dt * divv);
  EXPECT_NEAR(h1 * h1 * h1 * rho1, h * h * h * rho, 1e-8 * h * h * h * rho);
}

}  // namespace
