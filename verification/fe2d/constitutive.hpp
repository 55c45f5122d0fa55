// The material of an axisymmetric element, through the functions the SPH solvers call (common/): the
// axisymmetric flow written as a 3D velocity gradient in the frame x = r, y = theta, z = z, so that the
// strength model's Jaumann/Hooke rate, its von Mises return with heating and the equivalent strain rate of
// its rate term are common/'s, unchanged. The EOS (material_pressure) and the bulk viscosity
// (bulk_viscosity, common/viscosity.hpp) are called directly by the solver. README.md, "The material".
#pragma once
#include "common/material.hpp"

namespace impactsph::fe2d {

// The velocity gradient grad_v(a, b) = d v_a / d x_b (1/s) of an axisymmetric flow without swirl
// (v_theta = 0) in the frame x = r, y = theta, z = z: the four in-plane derivatives and the hoop rate v_r / r
// in the (theta, theta) slot; the theta row and column are otherwise zero. Its antisymmetric part is the
// r-z spin alone, its trace the divergence dv_r/dr + v_r/r + dv_z/dz.
template <class Real>
IMPACTSPH_HD Mat3<Real> axisymmetric_velocity_gradient(Real dvr_dr, Real dvr_dz, Real dvz_dr, Real dvz_dz,
                                                       Real vr_over_r) {
  return {{{dvr_dr, Real(0), dvr_dz}, {Real(0), vr_over_r, Real(0)}, {dvz_dr, Real(0), dvz_dz}}};
}

// What one element's deviatoric update did: the equivalent strain rate it was taken at (1/s) and the
// plastic return's increments.
template <class Real>
struct DeviatoricStep {
  Real strain_rate;
  PlasticResult<Real> plastic;
};

// The deviatoric stress S (Pa) of one element over a step dt (s) at the velocity gradient grad_v (1/s) of the
// step's midpoint, in the order of the SPH's advance_point (common/stages.hpp): the trial stress
// S + dt dS/dt with the strength model's rate (deviatoric_stress_rate: Hooke with the Jaumann rate), then
// plastic_update (the von Mises return and its heating) at the step start's plastic strain eps_p, temperature
// T (K) and pressure P (Pa, read by a pressure-dependent strength only), the density rho (kg/m^3), no damage,
// and the equivalent strain rate of grad_v (equivalent_strain_rate, the total rate, as in the SPH).
template <class Real>
IMPACTSPH_HD DeviatoricStep<Real> update_deviatoric_stress(const MaterialParams<Real>& m, Sym3<Real>& S,
                                                           const Mat3<Real>& grad_v, Real dt, Real eps_p, Real T,
                                                           Real rho, Real P) {
  S = S + dt * deviatoric_stress_rate(m, S, grad_v);
  DeviatoricStep<Real> step;
  step.strain_rate = equivalent_strain_rate(grad_v);
  step.plastic = plastic_update(m, S, eps_p, step.strain_rate, T, rho, Real(0), P);
  return step;
}

}  // namespace impactsph::fe2d
