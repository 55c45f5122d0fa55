// What a strength or a damage model is: the state a model is evaluated at, and the defaults a model
// inherits unless it says otherwise. One model is one file in common/models/ and one line in the lists of
// common/material.hpp (docs/architecture.md, "A material model"). A model is a struct of static members:
// its case key, its constants (Params, trivially copyable, so the gpu port copies them to the device), its
// physics (IMPACTSPH_HD, called by both solvers through the dispatch in material.hpp and damage.hpp) and
// how it reads its constants (`read`, host only: it calls the case reader it is given and does no I/O).
#pragma once
#include <string>
#include <vector>

#include "common/hd.hpp"
#include "common/strength.hpp"
#include "common/tensor.hpp"
#include "common/units.hpp"

namespace impactsph {

using ModelKeys = std::vector<std::string>;

// Where a flow stress is evaluated: equivalent plastic strain eps_p (dimensionless), equivalent strain rate
// eps_rate (1/s), temperature T (K), pressure P (Pa; with the bulking increment, needed only by a strength
// with needs_pressure) and damage D (dimensionless).
template <class Real>
struct FlowState {
  Real eps_p, eps_rate, T, P, D;
};

// One step's damage increment is taken at: the plastic strain increment d_eps_p and the plastic strain
// after it (dimensionless), the plastic work per unit mass after it (J/kg), the pressure P and the von
// Mises stress sigma_eq (Pa), the equivalent strain rate (1/s) and the temperature T (K).
template <class Real>
struct DamageStep {
  Real d_eps_p, eps_p_after, w_p_after, P, sigma_eq, eps_rate, T;
  // The non-local plastic work density around the particle after the step (J/m^3, common/nonlocal.hpp),
  // for a model that asks for it (damage_uses_nonlocal_work); 0 where the solver did not form it.
  Real nonlocal_work;
};

// A fully failed particle (D >= 1; F section 4.2, physics-notes) carries no deviatoric stress and no
// tension: S = 0 and P = max(P, 0) (Pa). It still resists compression, so failed fragments do not
// interpenetrate. A particle with D < 1 is left unchanged.
template <class Real> IMPACTSPH_HD void apply_failure(Sym3<Real>& S, Real& P, Real D) {
  if (!(D >= Real(1))) return;
  S = Sym3<Real>::zero();
  P = max_of(P, Real(0));
}

// The constants of a model that has none of its own (`template <class Real> using Params = NoParams<Real>;`).
template <class Real> struct NoParams {
  template <class To> NoParams<To> to() const { return {}; }
};

// A strength model. `Material` is MaterialParams<Real> (material.hpp), whose `strength` holds the
// constants every model shares (shear modulus, reference strain rate, melt temperature, Taylor-Quinney
// factor) and one Params member per model.
struct StrengthModelDefaults {
  static constexpr bool deviatoric = true;   // carries a deviatoric stress (Hooke + Jaumann, F 3.5-3.7)
  static constexpr bool plastic = true;      // has a flow stress and the von Mises return (F 3.8-3.11)
  static constexpr bool ductile = false;     // a metal's flow, whose plastic strain and work the metal damage models count
  static constexpr bool needs_pressure = false;              // the flow stress depends on the pressure
  static constexpr bool keeps_strength_when_failed = false;  // at D >= 1 it keeps its flow stress (else S = 0)
  // Flow stress sigma_y (Pa) at the state s.
  template <class Material, class Real>
  static IMPACTSPH_HD Real flow_stress(const Material&, const FlowState<Real>&) { return Real(0); }
  // What a particle carries at damage D, after the EOS and the return: S (Pa) and the pressure P (Pa).
  template <class Material, class Real>
  static IMPACTSPH_HD void carry_at_damage(const Material&, Sym3<Real>& S, Real& P, Real D) { apply_failure(S, P, D); }
  static ModelKeys keys() { return {}; }  // the keys of its strength table beyond kind and the elastic constants
  template <class Reader, class Strength> static void read(const Reader&, Strength&) {}
};

// A damage model. `Material` as above; its `damage` holds the pair options every model shares and one
// Params member per model.
struct DamageModelDefaults {
  static constexpr bool fails = true;                    // accumulates damage; takes pair_factor
  static constexpr bool default_pair_factor = true;      // scales the pair terms by 1 - D_ij (F eq 4.10)
  static constexpr bool takes_crack_faces = true;        // takes crack_faces
  static constexpr bool needs_ductile_strength = true;   // counts a metal's plastic strain or work
  static constexpr const char* required_strength = nullptr;  // the strength kind it needs, if one only
  static constexpr const char* required_strength_because = "";
  // Damage increment of one step (dimensionless; the caller keeps D = min(D + increment, 1)).
  template <class Material, class Real>
  static IMPACTSPH_HD Real increment(const Material&, const DamageStep<Real>&) { return Real(0); }
  // The pressure (Pa) a particle carries: the EOS pressure P_eos plus what the damage added (dP, Pa).
  template <class Material, class Real>
  static IMPACTSPH_HD Real pressure(const Material&, Real P_eos, Real) { return P_eos; }
  // The added pressure after the damage grew from D_old to D_new at density rho (kg/m^3), pressure P (Pa)
  // and strain rate eps_rate (1/s); dP_old (Pa) before.
  template <class Material, class Real>
  static IMPACTSPH_HD Real added_pressure(const Material&, Real, Real, Real, Real, Real, Real dP_old) { return dP_old; }
  // Constants that follow from the initial smoothing length h0 (m), set once by the scene.
  template <class Damage> static void set_smoothing_length(Damage&, double) {}
  static ModelKeys keys() { return {}; }  // the keys of its damage table beyond kind, pair_factor, crack_faces
  template <class Reader, class Damage> static void read(const Reader&, Damage&) {}
};

}  // namespace impactsph
