// Equations of state: pressure P (Pa) from density rho (kg/m^3) and specific internal energy e (J/kg),
// with the bulk sound speed c (m/s) used by the artificial viscosity and the time step.
// mu = rho/rho0 - 1 is the compression (F's eta).
#pragma once
#include "common/hd.hpp"

namespace impactsph {

enum class EosKind : int {
  Linear = 0,       // P = K mu: small-strain elastic solids (elastic-wave verification)
  Polynomial = 1,   // P = K1 mu + K2 mu^2 + K3 mu^3 (mu > 0), K1 mu (mu <= 0): JH-2 style
  MieGruneisen = 2, // F eqs 3.2-3.4, linear Us-up Hugoniot expanded to third order
  GruneisenCubic = 3 // X eqs 30-31 (LS-DYNA *EOS_GRUNEISEN), cubic Us-up
};

template <class Real>
struct EosParams {
  EosKind kind = EosKind::Linear;
  Real rho0 = 0;    // reference density, kg/m^3
  Real k1 = 0;      // bulk modulus (Linear, Polynomial K1), Pa
  Real k2 = 0, k3 = 0;  // Polynomial K2, K3, Pa
  Real c0 = 0;      // bulk sound speed at rest, m/s (Mie-Grueneisen, Grueneisen)
  Real s1 = 0, s2 = 0, s3 = 0;  // Us-up slope coefficients (MieGruneisen uses s1 only)
  Real gamma0 = 0;  // Grueneisen coefficient
  Real a = 0;       // first-order volume correction to gamma0 (GruneisenCubic)
  // Pressure cutoff, Pa (<= 0; LS-DYNA's PC of *MAT_NULL): the EOS pressure is held at or above it, so a
  // material with no strength and no failure model cannot carry unbounded tension. -1e30: no cutoff.
  Real min_pressure = Real(-1e30);
};

template <class Real> IMPACTSPH_HD Real compression(const EosParams<Real>& p, Real rho) { return rho / p.rho0 - Real(1); }

// Mie-Grueneisen, F eqs 3.2-3.4 with the density restored (physics-notes):
//   P = (1 - Gamma0 mu / 2) P_H(mu) + Gamma0 rho e,
//   P_H = C1 mu + C2 mu^2 + C3 mu^3 in compression, C1 mu in tension,
//   C1 = rho0 c0^2, C2 = C1 (1 + 2(s-1)), C3 = C1 (2(s-1) + 3(s-1)^2).
// Returns P; dP_dmu and dP_de are the partial derivatives at fixed e and fixed rho.
template <class Real>
IMPACTSPH_HD Real mie_gruneisen_pressure(const EosParams<Real>& p, Real rho, Real e, Real& dP_drho, Real& dP_de) {
  const Real mu = compression(p, rho);
  const Real c1 = p.rho0 * p.c0 * p.c0;
  const Real sm1 = p.s1 - Real(1);
  Real ph, dph;
  if (mu > Real(0)) {
    const Real c2 = c1 * (Real(1) + Real(2) * sm1);
    const Real c3 = c1 * (Real(2) * sm1 + Real(3) * sm1 * sm1);
    ph = mu * (c1 + mu * (c2 + mu * c3));
    dph = c1 + mu * (Real(2) * c2 + Real(3) * c3 * mu);
  } else {
    ph = c1 * mu;
    dph = c1;
  }
  const Real f = Real(1) - Real(0.5) * p.gamma0 * mu;
  dP_de = p.gamma0 * rho;
  dP_drho = (f * dph - Real(0.5) * p.gamma0 * ph) / p.rho0 + p.gamma0 * e;
  return f * ph + p.gamma0 * rho * e;
}

// Grueneisen with cubic Us-up, X eqs 30 (compression) and 31 (tension). E is the internal energy per
// unit reference volume, E = rho0 e (LS-DYNA convention).
template <class Real>
IMPACTSPH_HD Real gruneisen_cubic_pressure(const EosParams<Real>& p, Real rho, Real e, Real& dP_drho, Real& dP_de) {
  const Real mu = compression(p, rho);
  const Real c1 = p.rho0 * p.c0 * p.c0;
  const Real gam = p.gamma0 + p.a * mu;
  const Real E = p.rho0 * e;
  dP_de = gam * p.rho0;
  if (mu > Real(0)) {
    const Real mp1 = mu + Real(1);
    const Real num = c1 * mu * (Real(1) + (Real(1) - Real(0.5) * p.gamma0) * mu - Real(0.5) * p.a * mu * mu);
    const Real dnum = c1 * (Real(1) + Real(2) * (Real(1) - Real(0.5) * p.gamma0) * mu - Real(1.5) * p.a * mu * mu);
    const Real den = Real(1) - (p.s1 - Real(1)) * mu - p.s2 * mu * mu / mp1 - p.s3 * mu * mu * mu / (mp1 * mp1);
    // d/dmu of mu^2/(mu+1) = (mu^2 + 2mu)/(mu+1)^2; of mu^3/(mu+1)^2 = (mu^3 + 3mu^2)/(mu+1)^3.
    const Real dden = -(p.s1 - Real(1)) - p.s2 * (mu * mu + Real(2) * mu) / (mp1 * mp1) -
                      p.s3 * (mu * mu * mu + Real(3) * mu * mu) / (mp1 * mp1 * mp1);
    const Real den2 = den * den;
    const Real dpdmu = dnum / den2 - Real(2) * num * dden / (den2 * den) + p.a * E;
    dP_drho = dpdmu / p.rho0;
    return num / den2 + gam * E;
  }
  dP_drho = (c1 + p.a * E) / p.rho0;
  return c1 * mu + gam * E;
}

template <class Real>
IMPACTSPH_HD Real polynomial_pressure(const EosParams<Real>& p, Real rho, Real& dP_drho) {
  const Real mu = compression(p, rho);
  if (mu > Real(0)) {
    dP_drho = (p.k1 + mu * (Real(2) * p.k2 + Real(3) * p.k3 * mu)) / p.rho0;
    return mu * (p.k1 + mu * (p.k2 + mu * p.k3));
  }
  dP_drho = p.k1 / p.rho0;
  return p.k1 * mu;
}

// c^2 at the reference state (rho0, e = 0), m^2/s^2.
template <class Real> IMPACTSPH_HD Real eos_reference_sound_speed2(const EosParams<Real>& p) {
  switch (p.kind) {
    case EosKind::Linear:
    case EosKind::Polynomial: return p.k1 / p.rho0;
    case EosKind::MieGruneisen:
    case EosKind::GruneisenCubic: return p.c0 * p.c0;
  }
  return Real(0);
}

// Pressure and bulk sound speed. The isentropic c^2 = dP/drho|_e + (P/rho^2) dP/de|_rho; it is floored at
// a quarter of the reference value so strongly expanded or hot states cannot stall the time step or the
// viscosity (the floor only binds far from any state the verifications visit).
template <class Real>
IMPACTSPH_HD Real eos_pressure(const EosParams<Real>& p, Real rho, Real e, Real& sound_speed) {
  Real dP_drho = 0, dP_de = 0, P = 0;
  switch (p.kind) {
    case EosKind::Linear:
      dP_drho = p.k1 / p.rho0;
      P = p.k1 * compression(p, rho);
      break;
    case EosKind::Polynomial: P = polynomial_pressure(p, rho, dP_drho); break;
    case EosKind::MieGruneisen: P = mie_gruneisen_pressure(p, rho, e, dP_drho, dP_de); break;
    case EosKind::GruneisenCubic: P = gruneisen_cubic_pressure(p, rho, e, dP_drho, dP_de); break;
  }
  const Real c2_ref = eos_reference_sound_speed2(p);
  Real c2 = dP_drho + P / (rho * rho) * dP_de;
  if (!(c2 > Real(0.25) * c2_ref)) c2 = Real(0.25) * c2_ref;
  sound_speed = std::sqrt(c2);
  if (P < p.min_pressure) P = p.min_pressure;  // the cutoff (a NaN pressure stays NaN)
  return P;
}

}  // namespace impactsph
