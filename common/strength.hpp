// Deviatoric stress: hypo-elastic Hooke law with the Jaumann rate (F eqs 3.5-3.7) and the von Mises
// radial return (F eqs 3.8-3.11, with the yield function corrected as in physics-notes), and the normalised
// strain rate and temperature that several models share. The flow stresses are in common/models/.
// Units: stress in Pa, rates in 1/s, G in Pa, temperatures in K.
#pragma once
#include "common/tensor.hpp"

namespace impactsph {

// Strain rate (symmetric part of grad v) and spin (antisymmetric part). grad_v(a,b) = d v_a / d x_b.
template <class Real> IMPACTSPH_HD Sym3<Real> strain_rate(const Mat3<Real>& grad_v) { return Sym3<Real>::from(grad_v); }
template <class Real> IMPACTSPH_HD Mat3<Real> spin(const Mat3<Real>& grad_v) {
  return Real(0.5) * (grad_v - grad_v.transpose());
}

// dS/dt = 2 G (eps_dot - tr(eps_dot)/3 I) + Omega S - S Omega  (F 3.5-3.7: S Omega^T + Omega S).
// The rotation terms make the stress rate objective: under a rigid spin S only rotates.
template <class Real>
IMPACTSPH_HD Sym3<Real> jaumann_stress_rate(Sym3<Real> S, const Mat3<Real>& grad_v, Real shear_modulus) {
  const Sym3<Real> d = deviator(strain_rate(grad_v));
  const Mat3<Real> w = spin(grad_v);
  const Mat3<Real> s = S.full();
  const Mat3<Real> rot = w * s - s * w;  // symmetric, since w is antisymmetric and s symmetric
  return Real(2) * shear_modulus * d + Sym3<Real>::from(rot);
}

// Von Mises radial return (F 3.8-3.11). Yield when sqrt(J2) > sigma_y/sqrt(3), i.e. sqrt(3 J2) > sigma_y.
// S is scaled by c_y = min(1, sigma_y / sqrt(3 J2)); the equivalent plastic strain increment is
// (1 - c_y)/(3 G) sqrt(3/2 S:S) with S the trial stress. Returns that increment (dimensionless).
template <class Real>
IMPACTSPH_HD Real radial_return(Sym3<Real>& S, Real yield_stress, Real shear_modulus) {
  const Real seq = von_mises(S);  // sqrt(3 J2)
  if (!(seq > yield_stress)) return Real(0);
  const Real cy = yield_stress > Real(0) ? yield_stress / seq : Real(0);
  S = cy * S;
  return (Real(1) - cy) * seq / (Real(3) * shear_modulus);
}

// Equivalent strain rate of a velocity gradient, sqrt(2/3 d':d') with d' the deviator of the strain rate
// d = sym(grad v) (1/s). It is the rate that reads eps_dot for a uniaxial-stress test of an incompressible
// material (d = eps_dot diag(1, -1/2, -1/2)); a rigid spin or a pure volume change gives 0. This is the
// total, not the plastic, strain rate: the strain-rate measure of X eq 29 and of LS-DYNA's Johnson-Cook;
// F eq 3.12 writes the plastic rate, which is not known before the return and is zero in elastic steps.
template <class Real> IMPACTSPH_HD Real equivalent_strain_rate(const Mat3<Real>& grad_v) {
  const Sym3<Real> d = deviator(strain_rate(grad_v));
  return std::sqrt(Real(2) / Real(3) * ddot(d, d));
}

// Normalised strain rate of the Johnson-Cook laws (F eqs 3.12 and 4.7, X eqs 29 and 33):
// eps_dot* = max(eps_rate / eps_dot0, 1), dimensionless. The clamp at 1 means no rate softening below the
// reference rate: ln(eps_dot*) < 0 would lower the flow stress (C > 0) and diverge at rest (ln 0). The
// usual hydrocode choice. A reference rate <= 0 turns the rate dependence off (eps_dot* = 1).
template <class Real> IMPACTSPH_HD Real johnson_cook_rate_ratio(Real eps_rate, Real reference_strain_rate) {
  if (!(reference_strain_rate > Real(0))) return Real(1);
  return max_of(eps_rate / reference_strain_rate, Real(1));
}

// Homologous temperature of the Johnson-Cook laws (F eq 3.13, X after eq 29):
// T* = (T - T_room)/(T_melt - T_room), clamped to [0, 1] (dimensionless; temperatures in K). Below room
// temperature there is no extra hardening (T* = 0); at and above the melt T* = 1, where the flow stress
// vanishes. T_melt <= T_room (in particular the default T_melt = 0) turns thermal softening off (T* = 0).
template <class Real> IMPACTSPH_HD Real homologous_temperature(Real T, Real room_temperature, Real melt_temperature) {
  if (!(melt_temperature > room_temperature)) return Real(0);
  const Real t = (T - room_temperature) / (melt_temperature - room_temperature);
  return min_of(max_of(t, Real(0)), Real(1));
}

}  // namespace impactsph
