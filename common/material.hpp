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
  JohnsonCook = 3         // Hooke + Jaumann + von Mises at the Johnson-Cook flow stress (F 3.12-3.13)
};

enum class DamageKind : int {
  None = 0,
  CriticalPlasticStrain = 1,  // D = 1 once eps_p >= eps_c (F 4.9)
  JohnsonCook = 2             // D = sum d eps_p / eps_f, eps_f of F 4.7 bounded below as X eq 33
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
  Real taylor_quinney = 0.9;       // fraction of plastic work that heats (F 3.14)
};

template <class Real>
struct DamageParams {
  DamageKind kind = DamageKind::None;
  Real critical_plastic_strain = 0;          // eps_c (F 4.9)
  Real d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0;  // Johnson-Cook failure constants (F 4.7)
  Real min_failure_strain = 0;               // lower bound of eps_f (X eq 33)
};

template <class Real>
struct MaterialParams {
  EosParams<Real> eos;
  StrengthParams<Real> strength;
  DamageParams<Real> damage;
  Real specific_heat = 0;       // c_p, J/(kg K); 0 means temperature is not tracked
  Real room_temperature = 293;  // K, the temperature at e = 0
};

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

// Plastic correction after the elastic stress update; returns the equivalent plastic strain increment.
template <class Real> IMPACTSPH_HD Real plastic_correction(const MaterialParams<Real>& m, Sym3<Real>& S) {
  if (m.strength.kind != StrengthKind::PerfectlyPlastic) return Real(0);
  return radial_return(S, m.strength.yield_stress, m.strength.shear_modulus);
}

}  // namespace impactsph
