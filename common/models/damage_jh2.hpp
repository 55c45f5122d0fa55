// Damage model "johnson-holmquist-2" (JH-2; X eqs 25-28, Johnson and Holmquist 1994): D = sum d eps_p /
// eps_f with eps_f = D1 (P* + T*)^D2, and bulking: the strength the damage takes becomes pressure. It needs
// the JH-2 strength (its P_HEL and T) and, by default, leaves the pair terms unscaled: a ceramic carries
// its damage in its strength (X eq 22), and comminuted material must still resist compression.
#pragma once
#include "common/models/model_base.hpp"
#include "common/models/strength_jh2.hpp"
#include "common/eos.hpp"

namespace impactsph {

// JH-2 plastic strain to fracture (X eq 26): eps_f = D1 (P* + T*)^D2 with P* = P/P_HEL, T* = T/P_HEL,
// bounded below by EFMIN (min_failure_strain). Where P* + T* <= 0 (at or beyond the tensile limit) the
// power part is 0, so eps_f = EFMIN: with EFMIN = 0 any plastic flow there fails the particle at once.
template <class Real>
IMPACTSPH_HD Real jh2_failure_strain(Real d1, Real d2, Real p_star, Real t_star, Real min_failure_strain) {
  const Real s = p_star + t_star;
  const Real power = s > Real(0) ? d1 * std::pow(s, d2) : Real(0);
  return max_of(power, min_failure_strain);
}

// JH-2 bulking (X eq 28; Johnson and Holmquist 1994): when the damage grows from D_old to D_new at the
// pressure P, the strength falls and the elastic (deviatoric) energy U = sigma_y^2/(6 G) drops by
// dU = U(D_old) - U(D_new) (J/m^3). A fraction beta of it becomes hydrostatic potential energy through
// the pressure increment dP, updated by
//   dP_new = -K1 mu + sqrt((K1 mu + dP_old)^2 + 2 beta K1 dU),
// the root of (dP_new - dP_old) mu + (dP_new^2 - dP_old^2)/(2 K1) = beta dU (mu = rho/rho0 - 1).
// Returns dP_new (Pa). dP never decreases: no bulking without a loss of energy (dU <= 0), and none while
// K1 mu + dP_old < 0 (net tension, where the root jumps to the other branch and the tensile limit
// (Jh2Strength::carry_at_damage) governs anyway). beta = 0 returns dP_old. `Material` is MaterialParams
// (material.hpp), of JH-2 strength and damage.
template <class Material, class Real>
IMPACTSPH_HD Real jh2_bulking_increment(const Material& m, Real rho, Real P, Real D_old, Real D_new, Real eps_rate,
                                        Real dP_old) {
  if (!(m.damage.jh2.bulking > Real(0)) || !(D_new > D_old)) return dP_old;
  const Real G = m.strength.shear_modulus;
  const Real s_old = jh2_flow_stress(m.strength, P, eps_rate, D_old);
  const Real s_new = jh2_flow_stress(m.strength, P, eps_rate, D_new);
  const Real dU = (s_old * s_old - s_new * s_new) / (Real(6) * G);
  const Real k1mu = m.eos.k1 * compression(m.eos, rho);
  const Real a = k1mu + dP_old;
  if (!(dU > Real(0)) || a < Real(0)) return dP_old;
  return max_of(dP_old, -k1mu + std::sqrt(a * a + Real(2) * m.damage.jh2.bulking * m.eos.k1 * dU));
}

struct Jh2Damage : DamageModelDefaults {
  static constexpr const char* key = "johnson-holmquist-2";
  static constexpr bool default_pair_factor = false;
  static constexpr bool takes_crack_faces = false;
  static constexpr bool needs_ductile_strength = false;
  static constexpr const char* required_strength = "johnson-holmquist-2";
  static constexpr const char* required_strength_because =
      "its failure strain uses the strength's p_hel and tensile_strength, X eq 26";
  // D1, D2 of X eq 26, EFMIN and beta of X eq 28 (the fraction of the lost elastic energy converted to
  // hydrostatic potential energy, 0 to 1); dimensionless.
  template <class Real> struct Params {
    Real d1 = 0, d2 = 0;
    Real min_failure_strain = 0;
    Real bulking = 0;
    template <class To> Params<To> to() const { return {To(d1), To(d2), To(min_failure_strain), To(bulking)}; }
  };
  // d_eps_p / eps_f at the pressure P (Pa, with the bulking increment); 1 when eps_f <= 0; 0 without
  // plastic flow.
  template <class Material, class Real>
  static IMPACTSPH_HD Real increment(const Material& m, const DamageStep<Real>& s) {
    if (!(s.d_eps_p > Real(0))) return Real(0);
    const Real eps_f = jh2_failure_strain(m.damage.jh2.d1, m.damage.jh2.d2, s.P / m.strength.jh2.p_hel,
                                          m.strength.jh2.tensile_pressure / m.strength.jh2.p_hel,
                                          m.damage.jh2.min_failure_strain);
    return eps_f > Real(0) ? s.d_eps_p / eps_f : Real(1);
  }
  // The EOS pressure plus the bulking increment dP (Pa).
  template <class Material, class Real> static IMPACTSPH_HD Real pressure(const Material&, Real P_eos, Real dP) {
    return P_eos + dP;
  }
  template <class Material, class Real>
  static IMPACTSPH_HD Real added_pressure(const Material& m, Real rho, Real P, Real D_old, Real D_new, Real eps_rate,
                                          Real dP_old) {
    return jh2_bulking_increment(m, rho, P, D_old, D_new, eps_rate, dP_old);
  }
  static ModelKeys keys() { return {"d1", "d2", "min_failure_strain", "bulking"}; }
  template <class Reader, class Damage> static void read(const Reader& d, Damage& p) {
    Params<double>& j = p.jh2;
    j.d1 = d.number("d1");
    d.range("d1", j.d1, 0, 1, Dimension::Dimensionless, true, false, "D1 of eps_f = D1 (P* + T*)^D2 (X eq 26)");
    j.d2 = d.number("d2");
    d.range("d2", j.d2, 0, 5, Dimension::Dimensionless, false, false, "D2 of eps_f = D1 (P* + T*)^D2 (X eq 26)");
    j.min_failure_strain = d.number_or("min_failure_strain", 0.0);
    d.range("min_failure_strain", j.min_failure_strain, 0, 10, Dimension::Dimensionless);
    j.bulking = d.number_or("bulking", 0.0);
    d.range("bulking", j.bulking, 0, 1, Dimension::Dimensionless, false, false,
            "beta, the fraction of lost elastic energy converted to pressure (X eq 28)");
  }
};

}  // namespace impactsph
