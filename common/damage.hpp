// Damage and failure (F section 4.2): the damage increment of the chosen damage model (the models are in
// common/models/), what a failed particle may still carry, and the damaged pair factor.
// D is dimensionless in [0, 1]; stresses and pressures in Pa, strain rates in 1/s, temperatures in K.
#pragma once
#include <cstdint>

#include "common/material.hpp"

namespace impactsph {

// A particle counts as failed from D >= 0.99 in every observable, picture and report (damaged mass,
// residual and eroded mass, plug detection): the continuous damage models approach 1 only in the limit.
constexpr double kFailedDamage = 0.99;

// Damage increment of one step of the material's damage model (common/models/), to be added to D (the
// caller keeps D = min(D + increment, 1)): d_eps_p the plastic strain increment, eps_p_after and w_p_after
// (J/kg) the plastic strain and work after the step, P and sigma_eq (Pa) the pressure and the von Mises
// stress, eps_rate (1/s) and T (K), and the non-local plastic work density nonlocal_work (J/m^3) where
// damage_uses_nonlocal_work. Dimensionless. None: 0; no damage without plastic flow (d_eps_p <= 0) except in
// the critical-plastic-strain model.
template <class Real>
IMPACTSPH_HD Real damage_increment(const MaterialParams<Real>& m, Real d_eps_p, Real eps_p_after, Real w_p_after, Real P,
                                   Real sigma_eq, Real eps_rate, Real T, Real nonlocal_work = Real(0)) {
  const DamageStep<Real> step{d_eps_p, eps_p_after, w_p_after, P, sigma_eq, eps_rate, T, nonlocal_work};
  return with_damage_model(m.damage.kind, [&](auto model) { return decltype(model)::increment(m, step); });
}

// What a material carries at damage D (applied after material_pressure and the plastic return): its
// strength model's carry_at_damage. By default apply_failure(S, P, D) (common/models/model_base.hpp): a
// failed particle keeps no deviator and no tension; the JH-2 strength bounds the pressure by its tensile
// limit at D instead and leaves S to its flow stress.
template <class Real> IMPACTSPH_HD void apply_failure(const MaterialParams<Real>& m, Sym3<Real>& S, Real& P, Real D) {
  with_strength_model(m.strength.kind, [&](auto model) { decltype(model)::carry_at_damage(m, S, P, D); });
}

// The pressure the damage model adds (Pa) after the damage grew from D_old to D_new at density rho (kg/m^3),
// pressure P (Pa) and strain rate eps_rate (1/s), dP_old (Pa) before: the JH-2 bulking (X eq 28); dP_old
// for every other model.
template <class Real>
IMPACTSPH_HD Real damage_added_pressure(const MaterialParams<Real>& m, Real rho, Real P, Real D_old, Real D_new,
                                        Real eps_rate, Real dP_old) {
  return with_damage_model(m.damage.kind, [&](auto model) {
    return decltype(model)::added_pressure(m, rho, P, D_old, D_new, eps_rate, dP_old);
  });
}

// Sets the damage constants that follow from the initial smoothing length h0 (m): the critical work of a
// fracture-energy criterion. The scene calls it once per material (host only).
inline void set_damage_smoothing_length(DamageParams<double>& d, double h0) {
  with_damage_model(d.kind, [&](auto model) { decltype(model)::set_smoothing_length(d, h0); });
}

// The radius R (m) over which a material's damage model averages the plastic work (common/nonlocal.hpp);
// 0 for a local model.
template <class Real> IMPACTSPH_HD Real damage_nonlocal_radius(const MaterialParams<Real>& m) {
  return m.damage.kind == DamageKind::FractureEnergy ? m.damage.fracture_energy.nonlocal_radius : Real(0);
}

// Plastic work per unit initial volume (J/m^3) of a particle whose plastic work per unit mass is w_p (J/kg):
// rho0 w_p, what the fracture-energy criterion and its non-local average compare with W_c.
template <class Real> IMPACTSPH_HD Real plastic_work_density(const MaterialParams<Real>& m, Real w_p) {
  return m.eos.rho0 * w_p;
}

// Whether the solvers must form the non-local plastic work density of a particle for its damage increment
// this step: its material averages (damage_nonlocal_radius > 0), it is intact, it flowed plastically
// (d_eps_p > 0), and its own plastic work density rho0 w_p (J/m^3; w_p in J/kg after the step) reached the
// critical work, without which the model does not fail it (damage_fracture_energy.hpp). Only the particles
// at the crack tip pass, so the average costs little.
template <class Real>
IMPACTSPH_HD bool damage_uses_nonlocal_work(const MaterialParams<Real>& m, Real D, Real d_eps_p, Real w_p_after) {
  return damage_nonlocal_radius(m) > Real(0) && D < Real(1) && d_eps_p > Real(0) &&
         plastic_work_density(m, w_p_after) >= m.damage.fracture_energy.critical_work;
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
