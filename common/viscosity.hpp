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

}  // namespace impactsph
