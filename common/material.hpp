// A material is an EOS x a strength model x a damage model, each chosen independently per body in the
// case file (design.md, "materials compose"). This is the one place the choices are dispatched.
// Everything here is a trivially copyable parameter struct so the gpu port can copy it to the device.
#pragma once
#include <string>
#include <vector>

#include "common/eos.hpp"
#include "common/strength.hpp"
#include "common/models/damage_critical_plastic_strain.hpp"
#include "common/models/damage_fracture_energy.hpp"
#include "common/models/damage_jh2.hpp"
#include "common/models/damage_johnson_cook.hpp"
#include "common/models/damage_none.hpp"
#include "common/models/strength_elastic.hpp"
#include "common/models/strength_hydrodynamic.hpp"
#include "common/models/strength_jh2.hpp"
#include "common/models/strength_johnson_cook.hpp"
#include "common/models/strength_perfectly_plastic.hpp"

namespace impactsph {

// The registered models, one line each: X(kind, member of the params struct, model). The kind names the
// enumerator, the member holds the model's constants, the model (common/models/) its case key, physics and
// reader. A new model is its file, its include above and its line here.
#define IMPACTSPH_STRENGTH_MODELS(X)                               \
  X(Hydrodynamic, hydrodynamic, HydrodynamicStrength)              \
  X(Elastic, elastic, ElasticStrength)                             \
  X(PerfectlyPlastic, perfectly_plastic, PerfectlyPlasticStrength) \
  X(JohnsonCook, johnson_cook, JohnsonCookStrength)                \
  X(JohnsonHolmquist2, jh2, Jh2Strength)

#define IMPACTSPH_DAMAGE_MODELS(X)                                                \
  X(None, none, NoDamage)                                                         \
  X(CriticalPlasticStrain, critical_plastic_strain, CriticalPlasticStrainDamage) \
  X(FractureEnergy, fracture_energy, FractureEnergyDamage)                        \
  X(JohnsonCook, johnson_cook, JohnsonCookDamage)                                 \
  X(JohnsonHolmquist2, jh2, Jh2Damage)

#define IMPACTSPH_MODEL_ENUMERATOR(kind, member, Model) kind,
enum class StrengthKind : int { IMPACTSPH_STRENGTH_MODELS(IMPACTSPH_MODEL_ENUMERATOR) };
enum class DamageKind : int { IMPACTSPH_DAMAGE_MODELS(IMPACTSPH_MODEL_ENUMERATOR) };
#undef IMPACTSPH_MODEL_ENUMERATOR

// f(Model{}) for the registered model of a kind: a switch, no virtual call, so it runs on the device too.
template <class F> IMPACTSPH_HD auto with_strength_model(StrengthKind kind, F&& f) {
  switch (kind) {
#define IMPACTSPH_MODEL_CASE(k, member, Model) \
  case StrengthKind::k:                        \
    return f(Model{});
    IMPACTSPH_STRENGTH_MODELS(IMPACTSPH_MODEL_CASE)
#undef IMPACTSPH_MODEL_CASE
  }
  return f(HydrodynamicStrength{});
}
template <class F> IMPACTSPH_HD auto with_damage_model(DamageKind kind, F&& f) {
  switch (kind) {
#define IMPACTSPH_MODEL_CASE(k, member, Model) \
  case DamageKind::k:                          \
    return f(Model{});
    IMPACTSPH_DAMAGE_MODELS(IMPACTSPH_MODEL_CASE)
#undef IMPACTSPH_MODEL_CASE
  }
  return f(NoDamage{});
}

// The case keys of the registered models, in the order of the lists (host only).
inline std::vector<std::string> strength_keys() {
  return {
#define IMPACTSPH_MODEL_KEY(k, member, Model) Model::key,
      IMPACTSPH_STRENGTH_MODELS(IMPACTSPH_MODEL_KEY)
#undef IMPACTSPH_MODEL_KEY
  };
}
inline std::vector<std::string> damage_keys() {
  return {
#define IMPACTSPH_MODEL_KEY(k, member, Model) Model::key,
      IMPACTSPH_DAMAGE_MODELS(IMPACTSPH_MODEL_KEY)
#undef IMPACTSPH_MODEL_KEY
  };
}
inline const char* strength_key(StrengthKind kind) {
  return with_strength_model(kind, [](auto model) { return decltype(model)::key; });
}
inline const char* damage_key(DamageKind kind) {
  return with_damage_model(kind, [](auto model) { return decltype(model)::key; });
}
// The constants of a strength model: those every model shares, then one member per registered model.
template <class Real>
struct StrengthParams {
  StrengthKind kind = StrengthKind::Hydrodynamic;
  Real shear_modulus = 0;           // G, Pa (every deviatoric model)
  Real reference_strain_rate = 1;   // eps_dot0, 1/s (Johnson-Cook and JH-2 rate terms, Johnson-Cook failure)
  Real melt_temperature = 0;        // T_melt, K (0: no thermal softening; Johnson-Cook strength and failure)
  Real taylor_quinney = Real(0.9);  // fraction of plastic work that heats (F 3.14)
#define IMPACTSPH_MODEL_MEMBER(k, member, Model) typename Model::template Params<Real> member;
  IMPACTSPH_STRENGTH_MODELS(IMPACTSPH_MODEL_MEMBER)
#undef IMPACTSPH_MODEL_MEMBER
};

// The constants of a damage model: the pair options every failing model shares, then one member per
// registered model.
template <class Real>
struct DamageParams {
  DamageKind kind = DamageKind::None;
  // Scale the SPH pair terms by 1 - D_ij (F eq 4.10). F's metals do; a JH-2 ceramic carries its damage
  // in its strength (X eq 22) and comminuted material must still resist compression, so it does not.
  bool scale_pairs = true;
  // Crack faces: the pairs of a failed particle (D >= 1) carry only the compressive mean stress of each
  // side, so that intact material across a crack no longer pulls or shears the failed layer (case key
  // crack_faces = "compression"); false keeps F 4.10, where such a pair carries both full stresses at 1 - D_ij.
  bool compressive_crack_faces = false;
#define IMPACTSPH_MODEL_MEMBER(k, member, Model) typename Model::template Params<Real> member;
  IMPACTSPH_DAMAGE_MODELS(IMPACTSPH_MODEL_MEMBER)
#undef IMPACTSPH_MODEL_MEMBER
};

template <class Real>
struct MaterialParams {
  EosParams<Real> eos;
  StrengthParams<Real> strength;
  DamageParams<Real> damage;
  Real specific_heat = 0;       // c_p, J/(kg K); 0 means temperature is not tracked
  Real room_temperature = 293;  // K, the temperature at e = 0
};

// The same constants in another precision (the gpu port's float build takes the double ones of the
// scene). The shared fields are listed by name here; each model converts its own (Params::to).
template <class To, class From> MaterialParams<To> convert_material(const MaterialParams<From>& m) {
  MaterialParams<To> r;
  const EosParams<From>& e = m.eos;
  r.eos.kind = e.kind;
  r.eos.rho0 = To(e.rho0); r.eos.k1 = To(e.k1); r.eos.k2 = To(e.k2); r.eos.k3 = To(e.k3); r.eos.c0 = To(e.c0);
  r.eos.s1 = To(e.s1); r.eos.s2 = To(e.s2); r.eos.s3 = To(e.s3); r.eos.gamma0 = To(e.gamma0); r.eos.a = To(e.a);
  r.eos.min_pressure = To(e.min_pressure);
  r.strength.kind = m.strength.kind;
  r.strength.shear_modulus = To(m.strength.shear_modulus);
  r.strength.reference_strain_rate = To(m.strength.reference_strain_rate);
  r.strength.melt_temperature = To(m.strength.melt_temperature);
  r.strength.taylor_quinney = To(m.strength.taylor_quinney);
#define IMPACTSPH_MODEL_CONVERT(k, member, Model) r.strength.member = m.strength.member.template to<To>();
  IMPACTSPH_STRENGTH_MODELS(IMPACTSPH_MODEL_CONVERT)
#undef IMPACTSPH_MODEL_CONVERT
  r.damage.kind = m.damage.kind;
  r.damage.scale_pairs = m.damage.scale_pairs;
  r.damage.compressive_crack_faces = m.damage.compressive_crack_faces;
#define IMPACTSPH_MODEL_CONVERT(k, member, Model) r.damage.member = m.damage.member.template to<To>();
  IMPACTSPH_DAMAGE_MODELS(IMPACTSPH_MODEL_CONVERT)
#undef IMPACTSPH_MODEL_CONVERT
  r.specific_heat = To(m.specific_heat);
  r.room_temperature = To(m.room_temperature);
  return r;
}

template <class Real> IMPACTSPH_HD bool has_deviatoric_stress(const MaterialParams<Real>& m) {
  return with_strength_model(m.strength.kind, [](auto model) { return decltype(model)::deviatoric; });
}

// Signal speed for the time step: the longitudinal speed sqrt(c_bulk^2 + 4G/(3 rho)) of a solid, the
// bulk speed of a fluid.
template <class Real>
IMPACTSPH_HD Real signal_speed(const MaterialParams<Real>& m, Real bulk_sound_speed, Real rho) {
  if (!has_deviatoric_stress(m)) return bulk_sound_speed;
  return std::sqrt(bulk_sound_speed * bulk_sound_speed + Real(4) * m.strength.shear_modulus / (Real(3) * rho));
}

// Deviatoric stress rate of the chosen strength model (zero for a hydrodynamic material).
template <class Real>
IMPACTSPH_HD Sym3<Real> deviatoric_stress_rate(const MaterialParams<Real>& m, Sym3<Real> S, const Mat3<Real>& grad_v) {
  if (!has_deviatoric_stress(m)) return Sym3<Real>::zero();
  return jaumann_stress_rate(S, grad_v, m.strength.shear_modulus);
}

// Whether the flow stress depends on the pressure (then plastic_update wants it).
template <class Real> IMPACTSPH_HD bool strength_needs_pressure(const MaterialParams<Real>& m) {
  return with_strength_model(m.strength.kind, [](auto model) { return decltype(model)::needs_pressure; });
}

// Whether the material can fail (a damage model other than "none").
template <class Real> IMPACTSPH_HD bool can_fail(const MaterialParams<Real>& m) {
  return with_damage_model(m.damage.kind, [](auto model) { return decltype(model)::fails; });
}

// Pressure of a material, Pa: the EOS pressure (eos.hpp) plus what its damage model added, dP_bulk (Pa;
// the JH-2 bulking increment, X eq 28, kept per particle and grown by damage_added_pressure in damage.hpp).
// The tensile limit and what failed particles carry are applied afterwards by apply_failure(m, ...)
// (damage.hpp). sound_speed is the EOS bulk sound speed (m/s).
template <class Real>
IMPACTSPH_HD Real material_pressure(const MaterialParams<Real>& m, Real rho, Real e, Real dP_bulk, Real& sound_speed) {
  const Real P = eos_pressure(m.eos, rho, e, sound_speed);
  return with_damage_model(m.damage.kind, [&](auto model) { return decltype(model)::pressure(m, P, dP_bulk); });
}

// What one plastic step did to a particle.
template <class Real>
struct PlasticResult {
  Real d_eps_p;       // equivalent plastic strain increment, dimensionless (F eq 3.11)
  Real d_T;           // adiabatic temperature increment, K (F eq 3.14 with a Taylor-Quinney factor)
  Real plastic_work;  // plastic work per unit mass, sigma_y d_eps_p / rho, J/kg
};

// Plastic step after the elastic (trial) stress update: the von Mises radial return (F eqs 3.8-3.11 as
// corrected in physics-notes) at the flow stress of the strength model (common/models/), taken at the
// plastic strain eps_p, strain rate eps_rate (1/s), temperature T (K), damage and pressure P (Pa) of the
// step start. A model without plasticity (hydrodynamic, elastic) never yields: S untouched, result zero.
// After the return von_mises(S) = sigma_y and d_eps_p = (seq_trial - sigma_y)/(3 G). The plastic work per
// unit mass is S:d eps_pl / rho = sigma_y d_eps_p / rho (J/kg; rho in kg/m^3), and the adiabatic heating
// (F eq 3.14) d_T = taylor_quinney sigma_y d_eps_p / (rho c_p), zero when specific_heat is 0 (temperature
// not tracked). A fully failed particle (damage >= 1) carries no deviatoric stress unless its model keeps
// its strength when failed (JH-2): S is set to zero and no plastic strain or heat is counted (the same
// rule as apply_failure in damage.hpp).
template <class Real>
IMPACTSPH_HD PlasticResult<Real> plastic_update(const MaterialParams<Real>& m, Sym3<Real>& S, Real eps_p, Real eps_rate,
                                                Real T, Real rho, Real damage, Real P) {
  return with_strength_model(m.strength.kind, [&](auto model) {
    using Model = decltype(model);
    PlasticResult<Real> r{Real(0), Real(0), Real(0)};
    if (!Model::plastic) return r;
    const Real sigma_y = Model::flow_stress(m, FlowState<Real>{eps_p, eps_rate, T, P, damage});
    if (damage >= Real(1) && !Model::keeps_strength_when_failed) {
      S = Sym3<Real>::zero();
      return r;
    }
    r.d_eps_p = radial_return(S, sigma_y, m.strength.shear_modulus);
    if (rho > Real(0)) r.plastic_work = sigma_y * r.d_eps_p / rho;
    if (m.specific_heat > Real(0)) r.d_T = m.strength.taylor_quinney * r.plastic_work / m.specific_heat;
    return r;
  });
}

}  // namespace impactsph
