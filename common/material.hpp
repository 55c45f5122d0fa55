// A material is an EOS x a strength model x a damage model, each chosen independently per body in the
// case file (design.md, "materials compose"). This is the one place the choices are dispatched.
// Everything here is a trivially copyable parameter struct so the gpu port can copy it to the device.
#pragma once
#include "common/eos.hpp"
#include "common/strength.hpp"

namespace impactsph {

enum class StrengthKind : int {
  Hydrodynamic = 0,       // no deviatoric stress (Hugoniot tests, fluids)
  Elastic = 1,            // Hooke + Jaumann, never yields (elastic projectile, elastic-wave test)
  PerfectlyPlastic = 2,   // Hooke + Jaumann + von Mises at a constant yield stress
  JohnsonCook = 3,        // Hooke + Jaumann + von Mises at the Johnson-Cook flow stress (F 3.12-3.13)
  JohnsonHolmquist2 = 4   // Hooke + Jaumann + von Mises at the JH-2 strength (X eqs 22-24): ceramics
};

enum class DamageKind : int {
  None = 0,
  CriticalPlasticStrain = 1,  // D = 1 once eps_p >= eps_c (F 4.9)
  JohnsonCook = 2,            // D = sum d eps_p / eps_f, eps_f of F 4.7 bounded below as X eq 33
  JohnsonHolmquist2 = 3,      // D = sum d eps_p / eps_f, eps_f = D1 (P* + T*)^D2 (X eqs 25-26), bulking
  FractureEnergy = 4          // D = 1 once rho0 w_p x band width >= Gamma (crack band, damage.hpp)
};

template <class Real>
struct StrengthParams {
  StrengthKind kind = StrengthKind::Hydrodynamic;
  Real shear_modulus = 0;  // G, Pa
  Real yield_stress = 0;   // sigma_y, Pa (PerfectlyPlastic)
  // Johnson-Cook: sigma_y = (A + B eps_p^n)(1 + C ln eps_dot*)(1 - T*^m), eps_dot* = eps_dot/eps_dot0,
  // T* = (T - T_room)/(T_melt - T_room).
  Real jc_a = 0, jc_b = 0, jc_n = 1, jc_c = 0, jc_m = 1;  // A, B in Pa
  Real reference_strain_rate = 1;  // eps_dot0, 1/s
  Real melt_temperature = 0;       // T_melt, K (0: no thermal softening)
  Real taylor_quinney = Real(0.9);  // fraction of plastic work that heats (F 3.14)
  // JH-2 (X eqs 22-24, Table 1): normalised strength constants, the Hugoniot elastic limit HEL (Pa), the
  // pressure at the HEL P_HEL (Pa), the maximum tensile pressure T (Pa, > 0) and SFMAX, the cap of the
  // normalised fractured strength (1e30: no cap). The rate reference is reference_strain_rate (EPSI).
  Real jh_a = 0, jh_b = 0, jh_c = 0, jh_m = 1, jh_n = 1;
  Real hel = 0, p_hel = 0, tensile_pressure = 0;
  Real sfmax = Real(1e30);
};

// Equivalent (von Mises) stress at the HEL, Pa: the HEL is the longitudinal stress of uniaxial strain,
// HEL = P_HEL + (2/3) sigma_HEL, so sigma_HEL = 3/2 (HEL - P_HEL) (Johnson and Holmquist 1994).
template <class Real> IMPACTSPH_HD Real jh2_sigma_hel(const StrengthParams<Real>& p) {
  return Real(1.5) * (p.hel - p.p_hel);
}

template <class Real>
struct DamageParams {
  DamageKind kind = DamageKind::None;
  Real critical_plastic_strain = 0;          // eps_c (F 4.9)
  // FractureEnergy (crack band; damage.hpp): the energy per unit crack area Gamma (J/m^2), the width of
  // the band the failure localises in as a multiple of the initial smoothing length h0 (dimensionless),
  // and the plastic work density at failure Gamma / (band_width_factor h0) (J/m^3), which the scene sets
  // from its h0 (fracture_energy_critical_work).
  Real fracture_energy = 0;
  Real band_width_factor = 0;
  Real critical_plastic_work = 0;
  Real d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0;  // Johnson-Cook failure constants (F 4.7)
  Real min_failure_strain = 0;               // lower bound of eps_f (X eq 33; JH-2: EFMIN)
  // JH-2 uses d1, d2 as D1, D2 of X eq 26 and min_failure_strain; bulking is beta of X eq 28, the
  // fraction of the lost elastic energy converted to hydrostatic potential energy (0 to 1).
  Real bulking = 0;
  // Scale the SPH pair terms by 1 - D_ij (F eq 4.10). F's metals do; a JH-2 ceramic carries its damage
  // in its strength (X eq 22) and comminuted material must still resist compression, so it does not.
  bool scale_pairs = true;
  // Crack faces: the pairs of a failed particle (D >= 1) carry only the compressive mean stress of each
  // side, so that intact material across a crack no longer pulls or shears the failed layer (case key
  // crack_faces = "compression"); false keeps F 4.10, where such a pair carries both full stresses at 1 - D_ij.
  bool compressive_crack_faces = false;
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
// scene). Every field is listed by name, so a constant added to a struct above must be added here.
template <class To, class From> MaterialParams<To> convert_material(const MaterialParams<From>& m) {
  MaterialParams<To> r;
  const EosParams<From>& e = m.eos;
  r.eos.kind = e.kind;
  r.eos.rho0 = To(e.rho0); r.eos.k1 = To(e.k1); r.eos.k2 = To(e.k2); r.eos.k3 = To(e.k3); r.eos.c0 = To(e.c0);
  r.eos.s1 = To(e.s1); r.eos.s2 = To(e.s2); r.eos.s3 = To(e.s3); r.eos.gamma0 = To(e.gamma0); r.eos.a = To(e.a);
  r.eos.min_pressure = To(e.min_pressure);
  const StrengthParams<From>& s = m.strength;
  r.strength.kind = s.kind;
  r.strength.shear_modulus = To(s.shear_modulus); r.strength.yield_stress = To(s.yield_stress);
  r.strength.jc_a = To(s.jc_a); r.strength.jc_b = To(s.jc_b); r.strength.jc_n = To(s.jc_n);
  r.strength.jc_c = To(s.jc_c); r.strength.jc_m = To(s.jc_m);
  r.strength.reference_strain_rate = To(s.reference_strain_rate);
  r.strength.melt_temperature = To(s.melt_temperature); r.strength.taylor_quinney = To(s.taylor_quinney);
  r.strength.jh_a = To(s.jh_a); r.strength.jh_b = To(s.jh_b); r.strength.jh_c = To(s.jh_c);
  r.strength.jh_m = To(s.jh_m); r.strength.jh_n = To(s.jh_n);
  r.strength.hel = To(s.hel); r.strength.p_hel = To(s.p_hel); r.strength.tensile_pressure = To(s.tensile_pressure);
  r.strength.sfmax = To(s.sfmax);
  const DamageParams<From>& d = m.damage;
  r.damage.kind = d.kind;
  r.damage.critical_plastic_strain = To(d.critical_plastic_strain);
  r.damage.fracture_energy = To(d.fracture_energy); r.damage.band_width_factor = To(d.band_width_factor);
  r.damage.critical_plastic_work = To(d.critical_plastic_work);
  r.damage.d1 = To(d.d1); r.damage.d2 = To(d.d2); r.damage.d3 = To(d.d3); r.damage.d4 = To(d.d4); r.damage.d5 = To(d.d5);
  r.damage.min_failure_strain = To(d.min_failure_strain);
  r.damage.bulking = To(d.bulking);
  r.damage.scale_pairs = d.scale_pairs;
  r.damage.compressive_crack_faces = d.compressive_crack_faces;
  r.specific_heat = To(m.specific_heat);
  r.room_temperature = To(m.room_temperature);
  return r;
}

template <class Real> IMPACTSPH_HD bool has_deviatoric_stress(const MaterialParams<Real>& m) {
  return m.strength.kind != StrengthKind::Hydrodynamic;
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

// Johnson-Cook flow stress of a material's constants (F eqs 3.12-3.13, X eq 29), Pa:
//   sigma_y = (A + B eps_p^n)(1 + C ln eps_dot*)(1 - T*^m),
// eps_p the equivalent plastic strain, eps_rate the equivalent strain rate (1/s, equivalent_strain_rate),
// T and T_room in K. eps_dot* = max(eps_rate/eps_dot0, 1): no rate softening below the reference rate.
// T* = (T - T_room)/(T_melt - T_room) clamped to [0, 1]: zero strength at and above the melt; no thermal
// softening when melt_temperature is 0 (F neglects thermal effects for its plates). See strength.hpp.
template <class Real>
IMPACTSPH_HD Real johnson_cook_yield(const StrengthParams<Real>& p, Real eps_p, Real eps_rate, Real T, Real T_room) {
  return johnson_cook_flow_stress(p.jc_a, p.jc_b, p.jc_n, p.jc_c, p.jc_m, eps_p,
                                  johnson_cook_rate_ratio(eps_rate, p.reference_strain_rate),
                                  homologous_temperature(T, T_room, p.melt_temperature));
}

// JH-2 flow stress, Pa: sigma_HEL sigma*(P, D, eps_dot) with sigma* of X eqs 22-24 (strength.hpp), at
// the pressure P (Pa, the EOS pressure plus the bulking increment), damage D and the equivalent strain
// rate eps_rate (1/s).
template <class Real>
IMPACTSPH_HD Real jh2_flow_stress(const StrengthParams<Real>& p, Real P, Real eps_rate, Real D) {
  const Real rate = johnson_cook_rate_ratio(eps_rate, p.reference_strain_rate);
  const Real p_star = P / p.p_hel, t_star = p.tensile_pressure / p.p_hel;
  const Real intact = jh2_intact_strength(p.jh_a, p.jh_n, p.jh_c, p_star, t_star, rate);
  const Real fractured = jh2_fractured_strength(p.jh_b, p.jh_m, p.jh_c, p_star, rate, p.sfmax);
  return jh2_sigma_hel(p) * jh2_damaged_strength(intact, fractured, D);
}

// Whether the flow stress depends on the pressure (then plastic_update wants it).
template <class Real> IMPACTSPH_HD bool strength_needs_pressure(const MaterialParams<Real>& m) {
  return m.strength.kind == StrengthKind::JohnsonHolmquist2;
}

// Pressure of a material, Pa: the EOS pressure (eos.hpp) plus, for a JH-2 ceramic, the bulking increment
// dP_bulk (Pa; X eq 28, kept per particle and grown by jh2_bulking_increment in damage.hpp). The tensile
// limit and what failed particles carry are applied afterwards by apply_failure(m, ...) (damage.hpp).
// sound_speed is the EOS bulk sound speed (m/s).
template <class Real>
IMPACTSPH_HD Real material_pressure(const MaterialParams<Real>& m, Real rho, Real e, Real dP_bulk, Real& sound_speed) {
  const Real P = eos_pressure(m.eos, rho, e, sound_speed);
  return m.strength.kind == StrengthKind::JohnsonHolmquist2 ? P + dP_bulk : P;
}

// What one plastic step did to a particle.
template <class Real>
struct PlasticResult {
  Real d_eps_p;       // equivalent plastic strain increment, dimensionless (F eq 3.11)
  Real d_T;           // adiabatic temperature increment, K (F eq 3.14 with a Taylor-Quinney factor)
  Real plastic_work;  // plastic work per unit mass, sigma_y d_eps_p / rho, J/kg
};

// Plastic step after the elastic (trial) stress update: the von Mises radial return (F eqs 3.8-3.11 as
// corrected in physics-notes) at the flow stress of the strength model:
//   Hydrodynamic, Elastic: never yield, S untouched, result zero;
//   PerfectlyPlastic: sigma_y = yield_stress;
//   JohnsonCook: sigma_y = johnson_cook_yield at the current eps_p, eps_rate (1/s) and T (K), i.e. at the
//     start of the increment. This explicit choice (no iteration for the hardening within the step) is
//     the usual hydrocode one; the returned von Mises stress lags the hardened flow stress by
//     d sigma_y/d eps_p x d_eps_p, an error of first order in the step.
//   JohnsonHolmquist2: sigma_y = jh2_flow_stress at the pressure P (Pa), the damage and eps_rate; the
//     damage softens the strength towards the fractured strength (X eq 22) instead of failing the
//     particle, so a JH-2 particle keeps its (fractured) strength at D = 1.
// After the return von_mises(S) = sigma_y and d_eps_p = (seq_trial - sigma_y)/(3 G). The plastic work per
// unit mass is S:d eps_pl / rho = sigma_y d_eps_p / rho (J/kg; rho in kg/m^3), and the adiabatic heating
// (F eq 3.14) d_T = taylor_quinney sigma_y d_eps_p / (rho c_p), zero when specific_heat is 0 (temperature
// not tracked). A fully failed particle (damage >= 1) of any other model carries no deviatoric stress: S
// is set to zero and no plastic strain or heat is counted (the same rule as apply_failure in damage.hpp).
// Partial damage (damage < 1) leaves the Johnson-Cook flow stress unchanged: in F it acts through the
// pair kernel factor (F eq 4.10).
template <class Real>
IMPACTSPH_HD PlasticResult<Real> plastic_update(const MaterialParams<Real>& m, Sym3<Real>& S, Real eps_p, Real eps_rate,
                                                Real T, Real rho, Real damage, Real P) {
  PlasticResult<Real> r{Real(0), Real(0), Real(0)};
  Real sigma_y;
  if (m.strength.kind == StrengthKind::PerfectlyPlastic) {
    sigma_y = m.strength.yield_stress;
  } else if (m.strength.kind == StrengthKind::JohnsonCook) {
    sigma_y = johnson_cook_yield(m.strength, eps_p, eps_rate, T, m.room_temperature);
  } else if (m.strength.kind == StrengthKind::JohnsonHolmquist2) {
    sigma_y = jh2_flow_stress(m.strength, P, eps_rate, damage);
  } else {
    return r;
  }
  if (damage >= Real(1) && m.strength.kind != StrengthKind::JohnsonHolmquist2) {
    S = Sym3<Real>::zero();
    return r;
  }
  r.d_eps_p = radial_return(S, sigma_y, m.strength.shear_modulus);
  if (rho > Real(0)) r.plastic_work = sigma_y * r.d_eps_p / rho;
  if (m.specific_heat > Real(0)) r.d_T = m.strength.taylor_quinney * r.plastic_work / m.specific_heat;
  return r;
}

}  // namespace impactsph
