// Monaghan artificial viscosity (F eqs 2.16-2.17, X eqs 11-12). Naming: `linear` is F's kappa1 and X's
// Q2; `quadratic` is F's kappa2 and X's Q1 (the papers swap the names, see physics-notes).
// Pi_ij has the units of P/rho^2 (m^5 kg^-1 s^-2), like the stress terms of the momentum equation.
#pragma once
#include "common/tensor.hpp"

namespace impactsph {

template <class Real>
struct ViscosityParams {
  Real linear = Real(1);
  Real quadratic = Real(1);
};

// xij = x_i - x_j, vij = v_i - v_j, h the pair smoothing length, c and rho the pair means.
template <class Real>
IMPACTSPH_HD Real monaghan_viscosity(const ViscosityParams<Real>& p, Vec3<Real> xij, Vec3<Real> vij, Real h, Real c_mean,
                                     Real rho_mean) {
  const Real vx = dot(vij, xij);
  if (!(vx < Real(0))) return Real(0);
  const Real phi = h * vx / (norm2(xij) + Real(0.01) * h * h);
  return (-p.linear * c_mean * phi + p.quadratic * phi * phi) / rho_mean;
}

// Balsara (1995) shear limiter of particle i, in [0, 1]: |div v| / (|div v| + |curl v| + 0.0001 c/h).
// Near 1 in compression (shocks), near 0 in shear and isochoric plastic flow, where the Monaghan term
// otherwise acts as a physical viscosity. The pair uses the mean of the two factors.
template <class Real>
IMPACTSPH_HD Real balsara_factor(const Mat3<Real>& grad_v, Real sound_speed, Real h) {
  const Real div = grad_v.trace();
  const Real cx = grad_v.m[2][1] - grad_v.m[1][2], cy = grad_v.m[0][2] - grad_v.m[2][0], cz = grad_v.m[1][0] - grad_v.m[0][1];
  const Real curl = std::sqrt(cx * cx + cy * cy + cz * cz);
  const Real a = div < Real(0) ? -div : div;
  return a / (a + curl + Real(1e-4) * sound_speed / h);
}

}  // namespace impactsph
