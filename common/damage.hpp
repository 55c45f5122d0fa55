// Damage and failure (F section 4.2, X eqs 32-34): the Johnson-Cook failure strain, the damage increment
// of the chosen damage model, what a failed particle may still carry, and the damaged pair factor.
// D is dimensionless in [0, 1]; stresses and pressures in Pa, strain rates in 1/s, temperatures in K.
#pragma once
#include <cstdint>

#include "common/material.hpp"

namespace impactsph {

// A particle counts as failed from D >= 0.99 in every observable, picture and report (damaged mass,
// residual and eroded mass, plug detection): the continuous damage models approach 1 only in the limit.
constexpr double kFailedDamage = 0.99;

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
template <class Real>
IMPACTSPH_HD Real johnson_cook_failure_strain(const DamageParams<Real>& d, Real triaxiality, Real eps_rate_star,
                                              Real T_star) {
  const Real expo = min_of(d.d3 * triaxiality, failure_exponent_cap<Real>());
  const Real stress_part = d.d1 + d.d2 * std::exp(expo);
  const Real rate_part = eps_rate_star > Real(1) ? Real(1) + d.d4 * std::log(eps_rate_star) : Real(1);
  const Real t = min_of(max_of(T_star, Real(0)), Real(1));
  const Real thermal_part = Real(1) + d.d5 * t;
  return max_of(stress_part * rate_part * thermal_part, d.min_failure_strain);
}

// JH-2 plastic strain to fracture (X eq 26): eps_f = D1 (P* + T*)^D2 with P* = P/P_HEL, T* = T/P_HEL,
// bounded below by EFMIN (min_failure_strain). Where P* + T* <= 0 (at or beyond the tensile limit) the
// power part is 0, so eps_f = EFMIN: with EFMIN = 0 any plastic flow there fails the particle at once.
template <class Real>
IMPACTSPH_HD Real jh2_failure_strain(Real d1, Real d2, Real p_star, Real t_star, Real min_failure_strain) {
  const Real s = p_star + t_star;
  const Real power = s > Real(0) ? d1 * std::pow(s, d2) : Real(0);
  return max_of(power, min_failure_strain);
}

// Crack-band regularisation (Bazant and Oh 1983, "Crack band theory for fracture of concrete", Materiaux
// et Constructions 16, 155-177): a criterion on a strain or a work density fails a band of material as wide
// as the discretisation localises it in, so the energy per unit crack area it dissipates scales with the
// spacing. Holding that energy at a material constant Gamma (J/m^2) over a band of width w = k h0 (k the
// band width in initial smoothing lengths, measured, not fitted) fails a particle once its plastic work per
// unit initial volume reaches
//   W_c = Gamma / (k h0)   (J/m^3),
// the critical work this returns (h0 in m). Production codes scale the failure measure with the element
// size in the same way (LS-DYNA GISSMO and *MAT_ADD_EROSION with LCREGD, Radioss /FAIL element-size
// functions, Abaqus damage evolution by plastic displacement).
template <class Real>
IMPACTSPH_HD Real fracture_energy_critical_work(const DamageParams<Real>& d, Real h0) {
  return d.fracture_energy / (d.band_width_factor * h0);
}

// Damage increment of one step, to be added to D (the caller keeps D = min(D + increment, 1)):
//   None: 0;
//   CriticalPlasticStrain (F eq 4.9): 1 once the plastic strain after the step eps_p_after >= eps_c,
//     else 0 (D jumps from 0 to 1; eps_c must be > 0, or the material fails at once);
//   FractureEnergy (crack band, above): 1 once the plastic work per unit initial volume after the step,
//     rho0 w_p_after (w_p_after in J/kg, the particle's accumulated sum sigma_y d eps_p / rho), reaches the
//     critical work W_c = Gamma / (k h0) on a plastic step, else 0 (D jumps from 0 to 1, as in F 4.9);
//     never while W_c <= 0 (unset: the scene sets it from the spacing, fracture_energy_critical_work);
//   JohnsonCook (F eq 4.8, X eq 32): d_eps_p / eps_f, eps_f of johnson_cook_failure_strain at the
//     triaxiality -P/sigma_eq (P and sigma_eq in Pa), eps_dot* = max(eps_rate/eps_dot0, 1) with the
//     strength model's reference rate, and T* from the strength model's melt temperature and the
//     material's room temperature (T in K). 1 when eps_f <= 0 and the step is plastic.
//   JohnsonHolmquist2 (X eqs 25-26): d_eps_p / eps_f, eps_f of jh2_failure_strain at the pressure P (Pa,
//     with the bulking increment) and the strength model's P_HEL and T. 1 when eps_f <= 0.
// No damage without plastic flow (d_eps_p <= 0) except in CriticalPlasticStrain. Dimensionless.
template <class Real>
IMPACTSPH_HD Real damage_increment(const MaterialParams<Real>& m, Real d_eps_p, Real eps_p_after, Real w_p_after, Real P,
                                   Real sigma_eq, Real eps_rate, Real T) {
  if (m.damage.kind == DamageKind::CriticalPlasticStrain)
    return eps_p_after >= m.damage.critical_plastic_strain ? Real(1) : Real(0);
  if (!(d_eps_p > Real(0))) return Real(0);
  if (m.damage.kind == DamageKind::FractureEnergy)
    return m.damage.critical_plastic_work > Real(0) && m.eos.rho0 * w_p_after >= m.damage.critical_plastic_work
               ? Real(1) : Real(0);
  if (m.damage.kind == DamageKind::JohnsonHolmquist2) {
    const Real eps_f = jh2_failure_strain(m.damage.d1, m.damage.d2, P / m.strength.p_hel,
                                          m.strength.tensile_pressure / m.strength.p_hel, m.damage.min_failure_strain);
    return eps_f > Real(0) ? d_eps_p / eps_f : Real(1);
  }
  if (m.damage.kind != DamageKind::JohnsonCook) return Real(0);
  const Real eps_f = johnson_cook_failure_strain(
      m.damage, stress_triaxiality(P, sigma_eq), johnson_cook_rate_ratio(eps_rate, m.strength.reference_strain_rate),
      homologous_temperature(T, m.room_temperature, m.strength.melt_temperature));
  if (!(eps_f > Real(0))) return Real(1);
  return d_eps_p / eps_f;
}

// A fully failed particle (D >= 1; F section 4.2, physics-notes) carries no deviatoric stress and no
// tension: S = 0 and P = max(P, 0) (Pa). It still resists compression, so failed fragments do not
// interpenetrate. A particle with D < 1 is left unchanged.
template <class Real> IMPACTSPH_HD void apply_failure(Sym3<Real>& S, Real& P, Real D) {
  if (!(D >= Real(1))) return;
  S = Sym3<Real>::zero();
  P = max_of(P, Real(0));
}

// What a material may carry at damage D (applied after material_pressure and the plastic return):
//   JH-2 strength: the pressure is bounded below by the tensile limit, P >= -T (1 - D) (Johnson and
//     Holmquist 1994: the intact material holds tension up to T, a fully damaged one none); S is left
//     to the JH-2 flow stress (plastic_update), which falls to the fractured strength at D = 1;
//   any other model: apply_failure(S, P, D) above.
template <class Real> IMPACTSPH_HD void apply_failure(const MaterialParams<Real>& m, Sym3<Real>& S, Real& P, Real D) {
  if (m.strength.kind == StrengthKind::JohnsonHolmquist2) {
    const Real d = min_of(max_of(D, Real(0)), Real(1));
    P = max_of(P, -m.strength.tensile_pressure * (Real(1) - d));
    return;
  }
  apply_failure(S, P, D);
}

// JH-2 bulking (X eq 28; Johnson and Holmquist 1994): when the damage grows from D_old to D_new at the
// pressure P, the strength falls and the elastic (deviatoric) energy U = sigma_y^2/(6 G) drops by
// dU = U(D_old) - U(D_new) (J/m^3). A fraction beta of it becomes hydrostatic potential energy through
// the pressure increment dP, updated by
//   dP_new = -K1 mu + sqrt((K1 mu + dP_old)^2 + 2 beta K1 dU),
// the root of (dP_new - dP_old) mu + (dP_new^2 - dP_old^2)/(2 K1) = beta dU (mu = rho/rho0 - 1).
// Returns dP_new (Pa). dP never decreases: no bulking without a loss of energy (dU <= 0), and none while
// K1 mu + dP_old < 0 (net tension, where the root jumps to the other branch and the tensile limit of
// apply_failure governs anyway). Non-JH-2 materials and beta = 0 return dP_old.
template <class Real>
IMPACTSPH_HD Real jh2_bulking_increment(const MaterialParams<Real>& m, Real rho, Real P, Real D_old, Real D_new,
                                        Real eps_rate, Real dP_old) {
  if (m.damage.kind != DamageKind::JohnsonHolmquist2 || m.strength.kind != StrengthKind::JohnsonHolmquist2 ||
      !(m.damage.bulking > Real(0)) || !(D_new > D_old))
    return dP_old;
  const Real G = m.strength.shear_modulus;
  const Real s_old = jh2_flow_stress(m.strength, P, eps_rate, D_old);
  const Real s_new = jh2_flow_stress(m.strength, P, eps_rate, D_new);
  const Real dU = (s_old * s_old - s_new * s_new) / (Real(6) * G);
  const Real k1mu = m.eos.k1 * compression(m.eos, rho);
  const Real a = k1mu + dP_old;
  if (!(dU > Real(0)) || a < Real(0)) return dP_old;
  return max_of(dP_old, -k1mu + std::sqrt(a * a + Real(2) * m.damage.bulking * m.eos.k1 * dU));
}

// Damage a particle brings into the pair factor below: its D when its material scales pairs (F eq 4.10),
// else 0 (JH-2 ceramics, and metals modelled as in X, carry damage in their constitutive law only).
template <class Real> IMPACTSPH_HD Real pair_damage(const MaterialParams<Real>& m, Real D) {
  return m.damage.scale_pairs ? D : Real(0);
}

// Whether a particle of material `material` (an index into `materials`) at pair damage D (pair_damage) is a
// crack face whose pairs carry compression only (DamageParams::compressive_crack_faces): it has failed and
// its material asks for it. The material is looked up only for a failed particle, so the pair loops of both
// solvers can ask it of every neighbour.
template <class Real>
IMPACTSPH_HD bool compressive_crack_face(const MaterialParams<Real>* materials, std::int32_t material, Real D) {
  return D >= Real(1) && materials[material].damage.compressive_crack_faces;
}

// Damaged interaction (F eq 4.10): the kernel and its gradient between i and j are scaled by
// 1 - D_ij, D_ij = (D_i + D_j)/2, clamped to [0, 1] (dimensionless): two failed particles no longer
// interact, an intact pair is unaffected.
template <class Real> IMPACTSPH_HD Real damaged_pair_factor(Real Di, Real Dj) {
  const Real f = Real(1) - Real(0.5) * (Di + Dj);
  return min_of(max_of(f, Real(0)), Real(1));
}

}  // namespace impactsph
