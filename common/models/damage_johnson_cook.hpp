// Damage model "johnson-cook" (F eqs 4.7-4.8, X eqs 32-34): D = sum d eps_p / eps_f, the failure strain of
// the triaxiality, the strain rate and the temperature, bounded below as X eq 33. Its rate and thermal
// terms use the strength table's reference strain rate and melt temperature.
#pragma once
#include "common/models/model_base.hpp"

namespace impactsph {

// Stress triaxiality sigma* = sigma_m / sigma_eq (F after eq 4.7, X eq 34), with the mean stress
// sigma_m = -P (P > 0 in compression) and sigma_eq the von Mises stress (Pa). Dimensionless; defined as 0
// when sigma_eq == 0 (no deviatoric stress: the ratio has no meaning, and 0 is the pure-shear value).
template <class Real> IMPACTSPH_HD Real stress_triaxiality(Real P, Real sigma_eq) {
  return sigma_eq > Real(0) ? -P / sigma_eq : Real(0);
}

// Largest exponent D3 sigma* used in exp(): exp(80) ~ 5.5e34 fits a float. Beyond it the failure strain is
// astronomically large either way; the cap keeps it finite so that D2 = 0 never meets 0 x inf.
template <class Real> IMPACTSPH_HD Real failure_exponent_cap() { return Real(80); }

// Johnson-Cook failure strain (F eq 4.7) bounded below by the minimum failure strain (X eq 33):
//   eps_f = max([D1 + D2 exp(D3 sigma*)] [1 + D4 ln eps_dot*] [1 + D5 T*], eps_f_min),
// sigma* the triaxiality (stress_triaxiality), eps_dot* the normalised strain rate, T* the homologous
// temperature. As in the flow stress (johnson_cook_rate_ratio, homologous_temperature), eps_dot* is read
// as max(eps_dot*, 1) (no rate effect below the reference rate, no ln 0) and T* is clamped to [0, 1].
// Dimensionless. It can be <= 0 only for unphysical constants with eps_f_min = 0; damage_increment then
// fails the particle at its first plastic increment.
template <class Damage, class Real>
IMPACTSPH_HD Real johnson_cook_failure_strain(const Damage& damage, Real triaxiality, Real eps_rate_star, Real T_star) {
  const auto& d = damage.johnson_cook;
  const Real expo = min_of(d.d3 * triaxiality, failure_exponent_cap<Real>());
  const Real stress_part = d.d1 + d.d2 * std::exp(expo);
  const Real rate_part = eps_rate_star > Real(1) ? Real(1) + d.d4 * std::log(eps_rate_star) : Real(1);
  const Real t = min_of(max_of(T_star, Real(0)), Real(1));
  const Real thermal_part = Real(1) + d.d5 * t;
  return max_of(stress_part * rate_part * thermal_part, d.min_failure_strain);
}

struct JohnsonCookDamage : DamageModelDefaults {
  static constexpr const char* key = "johnson-cook";
  // D1-D5 of F eq 4.7 and the lower bound of eps_f (X eq 33), dimensionless.
  template <class Real> struct Params {
    Real d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0;
    Real min_failure_strain = 0;
    template <class To> Params<To> to() const {
      return {To(d1), To(d2), To(d3), To(d4), To(d5), To(min_failure_strain)};
    }
  };
  // d_eps_p / eps_f with eps_f at the triaxiality -P/sigma_eq, eps_dot* = max(eps_rate/eps_dot0, 1) and T*
  // from the melt and room temperatures; 1 when eps_f <= 0 on a plastic step; 0 without plastic flow.
  template <class Material, class Real>
  static IMPACTSPH_HD Real increment(const Material& m, const DamageStep<Real>& s) {
    if (!(s.d_eps_p > Real(0))) return Real(0);
    const Real eps_f = johnson_cook_failure_strain(
        m.damage, stress_triaxiality(s.P, s.sigma_eq), johnson_cook_rate_ratio(s.eps_rate, m.strength.reference_strain_rate),
        homologous_temperature(s.T, m.room_temperature, m.strength.melt_temperature));
    if (!(eps_f > Real(0))) return Real(1);
    return s.d_eps_p / eps_f;
  }
  static ModelKeys keys() { return {"d1", "d2", "d3", "d4", "d5", "min_failure_strain"}; }
  template <class Reader, class Damage> static void read(const Reader& d, Damage& p) {
    Params<double>& j = p.johnson_cook;
    const std::string why = "the Johnson-Cook failure constants are at most 20 in magnitude";
    j.d1 = d.number("d1");
    d.range("d1", j.d1, -1, 20, Dimension::Dimensionless, false, false, why);
    j.d2 = d.number("d2");
    d.range("d2", j.d2, 0, 20, Dimension::Dimensionless, false, false, why);
    j.d3 = d.number("d3");
    d.range("d3", j.d3, -20, 20, Dimension::Dimensionless, false, false, why);
    j.d4 = d.number_or("d4", 0.0);
    d.range("d4", j.d4, -20, 20, Dimension::Dimensionless, false, false, why);
    j.d5 = d.number_or("d5", 0.0);
    d.range("d5", j.d5, -20, 20, Dimension::Dimensionless, false, false, why);
    j.min_failure_strain = d.number_or("min_failure_strain", 0.0);
    d.range("min_failure_strain", j.min_failure_strain, 0, 10, Dimension::Dimensionless);
  }
};

}  // namespace impactsph
