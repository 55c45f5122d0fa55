// Deviatoric stress: hypo-elastic Hooke law with the Jaumann rate (F eqs 3.5-3.7) and the von Mises
// radial return (F eqs 3.8-3.11, with the yield function corrected as in physics-notes).
// Units: stress in Pa, rates in 1/s, G in Pa.
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

}  // namespace impactsph
