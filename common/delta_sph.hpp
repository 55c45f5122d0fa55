// delta-SPH density diffusion of Marrone et al. (2011), as corrected in physics-notes (F 2.10 and
// 2.18-2.19 are misprinted). The diffusive rate of particle i is
//   delta h c0 sum_j V_j psi_ij . grad_i W_ij,
//   psi_ij = 2 (rho_j - rho_i) (x_j - x_i)/|x_j - x_i|^2 - (<grad rho>_i + <grad rho>_j),
// with <grad rho> the renormalised density gradient. Units: kg/m^3/s.
#pragma once
#include "common/hd.hpp"
#include "common/tensor.hpp"

namespace impactsph {

// Term of one neighbour: V_j psi_ij . grad_i W_ij. xij = x_i - x_j, so x_j - x_i = -xij.
template <class Real>
IMPACTSPH_HD Real delta_sph_term(Real vol_j, Real rho_i, Real rho_j, Vec3<Real> xij, Vec3<Real> grad_rho_i,
                                 Vec3<Real> grad_rho_j, Vec3<Real> grad_w) {
  const Real r2 = norm2(xij);
  const Vec3<Real> psi = (Real(-2) * (rho_j - rho_i) / r2) * xij - (grad_rho_i + grad_rho_j);
  return choose(r2 > Real(0), vol_j * dot(psi, grad_w), Real(0));
}

}  // namespace impactsph
