// Strength model "johnson-holmquist-2" (JH-2; X eqs 22-24, Johnson and Holmquist 1994): ceramics. The
// strength falls with the damage from the intact to the fractured curve instead of the particle failing,
// depends on the pressure, and a damaged particle holds tension only down to -T (1 - D).
#pragma once
#include "common/models/model_base.hpp"

namespace impactsph {

// Johnson-Holmquist 2 (JH-2) normalised strengths (X eqs 23-24; Johnson and Holmquist 1994). All are
// normalised by the equivalent stress at the Hugoniot elastic limit, sigma_HEL, and take the normalised
// pressure P* = P/P_HEL, the normalised maximum tensile pressure T* = T/P_HEL and the normalised strain
// rate eps_dot* (johnson_cook_rate_ratio: at least 1, so ln eps_dot* >= 0). Dimensionless.
//   intact    sigma_i* = A (P* + T*)^N (1 + C ln eps_dot*), 0 where P* + T* <= 0 (no strength at or
//             beyond the tensile limit);
//   fractured sigma_f* = B (P*)^M (1 + C ln eps_dot*), at most SFMAX, 0 where P* <= 0 (a comminuted
//             ceramic has no strength without confinement);
//   damaged   sigma* = sigma_i* - D (sigma_i* - sigma_f*) (X eq 22), D in [0, 1].
// pow is never called at 0 or below. A rate factor below 0 (C < 0) gives 0.
template <class Real>
IMPACTSPH_HD Real jh2_rate_factor(Real c, Real eps_rate_star) {
  return eps_rate_star > Real(1) ? max_of(Real(1) + c * std::log(eps_rate_star), Real(0)) : Real(1);
}
template <class Real>
IMPACTSPH_HD Real jh2_intact_strength(Real a, Real n, Real c, Real p_star, Real t_star, Real eps_rate_star) {
  const Real s = p_star + t_star;
  if (!(s > Real(0))) return Real(0);
  return a * std::pow(s, n) * jh2_rate_factor(c, eps_rate_star);
}
template <class Real>
IMPACTSPH_HD Real jh2_fractured_strength(Real b, Real m, Real c, Real p_star, Real eps_rate_star, Real sfmax) {
  if (!(p_star > Real(0))) return Real(0);
  return min_of(b * std::pow(p_star, m) * jh2_rate_factor(c, eps_rate_star), sfmax);
}
template <class Real> IMPACTSPH_HD Real jh2_damaged_strength(Real intact, Real fractured, Real D) {
  const Real d = min_of(max_of(D, Real(0)), Real(1));
  return intact - d * (intact - fractured);
}

// Equivalent (von Mises) stress at the HEL, Pa: the HEL is the longitudinal stress of uniaxial strain,
// HEL = P_HEL + (2/3) sigma_HEL, so sigma_HEL = 3/2 (HEL - P_HEL) (Johnson and Holmquist 1994). `Strength`
// is StrengthParams (material.hpp).
template <class Strength> IMPACTSPH_HD auto jh2_sigma_hel(const Strength& p) {
  using Real = decltype(p.jh2.hel);
  return Real(1.5) * (p.jh2.hel - p.jh2.p_hel);
}

// JH-2 flow stress, Pa: sigma_HEL sigma*(P, D, eps_dot) with sigma* of X eqs 22-24 (above), at the pressure
// P (Pa, the EOS pressure plus the bulking increment), damage D and the equivalent strain rate eps_rate
// (1/s); the rate reference is the strength table's reference_strain_rate (EPSI).
template <class Strength, class Real>
IMPACTSPH_HD Real jh2_flow_stress(const Strength& p, Real P, Real eps_rate, Real D) {
  const Real rate = johnson_cook_rate_ratio(eps_rate, p.reference_strain_rate);
  const Real p_star = P / p.jh2.p_hel, t_star = p.jh2.tensile_pressure / p.jh2.p_hel;
  const Real intact = jh2_intact_strength(p.jh2.a, p.jh2.n, p.jh2.c, p_star, t_star, rate);
  const Real fractured = jh2_fractured_strength(p.jh2.b, p.jh2.m, p.jh2.c, p_star, rate, p.jh2.sfmax);
  return jh2_sigma_hel(p) * jh2_damaged_strength(intact, fractured, D);
}

struct Jh2Strength : StrengthModelDefaults {
  static constexpr const char* key = "johnson-holmquist-2";
  static constexpr bool needs_pressure = true;
  static constexpr bool keeps_strength_when_failed = true;  // a comminuted ceramic keeps its fractured strength
  // X Table 1: normalised strength constants, the Hugoniot elastic limit HEL (Pa), the pressure at the HEL
  // P_HEL (Pa), the maximum tensile pressure T (Pa, > 0) and SFMAX, the cap of the normalised fractured
  // strength (1e30: no cap).
  template <class Real> struct Params {
    Real a = 0, b = 0, c = 0, m = 1, n = 1;
    Real hel = 0, p_hel = 0, tensile_pressure = 0;
    Real sfmax = Real(1e30);
    template <class To> Params<To> to() const {
      return {To(a), To(b), To(c), To(m), To(n), To(hel), To(p_hel), To(tensile_pressure), To(sfmax)};
    }
  };
  template <class Material, class Real>
  static IMPACTSPH_HD Real flow_stress(const Material& mat, const FlowState<Real>& s) {
    return jh2_flow_stress(mat.strength, s.P, s.eps_rate, s.D);
  }
  // The pressure is bounded below by the tensile limit, P >= -T (1 - D) (Johnson and Holmquist 1994: the
  // intact material holds tension up to T, a fully damaged one none); S is left to the flow stress, which
  // falls to the fractured strength at D = 1.
  template <class Material, class Real>
  static IMPACTSPH_HD void carry_at_damage(const Material& mat, Sym3<Real>&, Real& P, Real D) {
    const Real d = min_of(max_of(D, Real(0)), Real(1));
    P = max_of(P, -mat.strength.jh2.tensile_pressure * (Real(1) - d));
  }
  static ModelKeys keys() {
    return {"a", "b", "c", "m", "n", "hel", "p_hel", "tensile_strength", "sfmax", "reference_strain_rate"};
  }
  template <class Reader, class Strength> static void read(const Reader& s, Strength& p) {
    Params<double>& j = p.jh2;
    const std::string norm = "a normalised JH-2 constant (dimensionless; X Table 1)";
    j.a = s.number("a");
    s.range("a", j.a, 0, 5, Dimension::Dimensionless, true, false, norm);
    j.b = s.number("b");
    s.range("b", j.b, 0, 5, Dimension::Dimensionless, false, false, norm);
    j.n = s.number("n");
    s.range("n", j.n, 0, 2, Dimension::Dimensionless, true, false, norm);
    j.m = s.number("m");
    s.range("m", j.m, 0, 2, Dimension::Dimensionless, true, false, norm);
    j.c = s.number_or("c", 0.0);
    s.range("c", j.c, 0, 1, Dimension::Dimensionless, false, false, norm);
    j.hel = s.stress("hel", "; the Hugoniot elastic limit, e.g. \"2.79 GPa\"");
    j.p_hel = s.stress("p_hel", "; the pressure at the HEL, e.g. \"1.46 GPa\"");
    if (!(j.p_hel < j.hel))
      s.fail("p_hel", "must be less than hel = " + format_quantity(j.hel, Dimension::Pressure) + " (got " +
                          format_quantity(j.p_hel, Dimension::Pressure) +
                          "): HEL = P_HEL + 2/3 sigma_HEL with sigma_HEL > 0");
    j.tensile_pressure = s.stress("tensile_strength", "; T, the largest hydrostatic tension, e.g. \"0.2 GPa\"");
    j.sfmax = s.number_or("sfmax", 1e30);
    s.range("sfmax", j.sfmax, 0, 1e30, Dimension::Dimensionless, true, false,
            "the cap of the normalised fractured strength; leave it out for no cap");
    p.reference_strain_rate = s.quantity_or("reference_strain_rate", Dimension::StrainRate, 1.0);
    s.positive("reference_strain_rate", p.reference_strain_rate, Dimension::StrainRate);
  }
};

}  // namespace impactsph
