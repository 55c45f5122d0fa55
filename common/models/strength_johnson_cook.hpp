// Strength model "johnson-cook": Hooke + Jaumann + von Mises at the Johnson-Cook flow stress
// (F eqs 3.12-3.13, X eq 29). Its rate and thermal terms use the shared reference strain rate and melt
// temperature of the strength table (common to the Johnson-Cook failure model).
#pragma once
#include "common/models/model_base.hpp"

namespace impactsph {

// Johnson-Cook flow stress (F eqs 3.12-3.13, X eq 29), Pa:
//   sigma_y = (A + B eps_p^n)(1 + C ln eps_dot*)(1 - T*^m),
// with A, B in Pa, eps_p the equivalent plastic strain (negative values read as 0), eps_dot* and T* from
// johnson_cook_rate_ratio and homologous_temperature. eps_p^n at eps_p = 0 is its limit from above: 0 for
// n > 0, 1 for n = 0 (constant B: no jump at the first plastic step); pow and log are never called at 0.
// T*^m is 0 at T* = 0. Never negative: a negative rate factor (C < 0 at extreme rates) gives 0.
template <class Real>
IMPACTSPH_HD Real johnson_cook_flow_stress(Real a, Real b, Real n, Real c, Real m, Real eps_p, Real eps_rate_star,
                                           Real t_star) {
  const Real eps_n = eps_p > Real(0) ? std::pow(eps_p, n) : (n > Real(0) ? Real(0) : Real(1));
  const Real hardening = a + b * eps_n;
  const Real rate = eps_rate_star > Real(1) ? Real(1) + c * std::log(eps_rate_star) : Real(1);
  const Real thermal = t_star > Real(0) ? Real(1) - std::pow(t_star, m) : Real(1);
  return max_of(hardening * rate * thermal, Real(0));
}

// Johnson-Cook flow stress of a material's strength constants (`Strength` is StrengthParams, material.hpp),
// Pa: johnson_cook_flow_stress at eps_p, eps_dot* = max(eps_rate/eps_dot0, 1) (eps_rate in 1/s) and
// T* of T and T_room (K). No thermal softening when melt_temperature is 0 (F neglects thermal effects for
// its plates).
template <class Strength, class Real>
IMPACTSPH_HD Real johnson_cook_yield(const Strength& p, Real eps_p, Real eps_rate, Real T, Real T_room) {
  return johnson_cook_flow_stress(p.johnson_cook.a, p.johnson_cook.b, p.johnson_cook.n, p.johnson_cook.c,
                                  p.johnson_cook.m, eps_p, johnson_cook_rate_ratio(eps_rate, p.reference_strain_rate),
                                  homologous_temperature(T, T_room, p.melt_temperature));
}

// The flow stress is taken at the history variables of the step start (no iteration for the hardening
// within the step): the usual explicit hydrocode choice. The returned von Mises stress then lags the
// hardened flow stress by d sigma_y/d eps_p x d_eps_p, an error of first order in the step. Partial damage
// (D < 1) leaves it unchanged: in F it acts through the pair kernel factor (F eq 4.10).
struct JohnsonCookStrength : StrengthModelDefaults {
  static constexpr const char* key = "johnson-cook";
  static constexpr bool ductile = true;
  template <class Real> struct Params {
    Real a = 0, b = 0, n = 1, c = 0, m = 1;  // A, B in Pa; n, C, m dimensionless
    template <class To> Params<To> to() const { return {To(a), To(b), To(n), To(c), To(m)}; }
  };
  template <class Material, class Real>
  static IMPACTSPH_HD Real flow_stress(const Material& mat, const FlowState<Real>& s) {
    return johnson_cook_yield(mat.strength, s.eps_p, s.eps_rate, s.T, mat.room_temperature);
  }
  static ModelKeys keys() {
    return {"a", "b", "n", "c", "m", "reference_strain_rate", "melt_temperature", "taylor_quinney"};
  }
  template <class Reader, class Strength> static void read(const Reader& s, Strength& p) {
    Params<double>& jc = p.johnson_cook;
    jc.a = s.stress("a", "; A is the yield stress at zero plastic strain");
    jc.b = s.stress_or_zero("b", "; b = 0 means no strain hardening");
    jc.n = jc.b > 0 ? s.number("n") : s.number_or("n", 1.0);  // n is needed only with hardening
    s.range("n", jc.n, 0, 2, Dimension::Dimensionless, true);
    jc.c = s.number_or("c", 0.0);
    s.range("c", jc.c, 0, 1, Dimension::Dimensionless);
    jc.m = s.number_or("m", 1.0);
    s.range("m", jc.m, 0, 5, Dimension::Dimensionless, true);
    p.reference_strain_rate = s.quantity_or("reference_strain_rate", Dimension::StrainRate, 1.0);
    s.positive("reference_strain_rate", p.reference_strain_rate, Dimension::StrainRate);
    p.melt_temperature = 0;  // 0: no thermal softening; checked against room_temperature by the material reader
    if (s.has("melt_temperature")) {
      p.melt_temperature = s.quantity("melt_temperature", Dimension::Temperature);
      s.positive("melt_temperature", p.melt_temperature, Dimension::Temperature);
    }
    p.taylor_quinney = s.number_or("taylor_quinney", 0.9);
    s.range("taylor_quinney", p.taylor_quinney, 0, 1, Dimension::Dimensionless, false, false,
            "the fraction of plastic work that heats the material");
  }
};

}  // namespace impactsph
