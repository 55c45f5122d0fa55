// SPH smoothing kernels, support radius 2h. Units: r and h in m, W in 1/m^3, grad W in 1/m^4.
// Both kernels return the gradient as a factor F with grad_i W_ij = F * (x_i - x_j), so no division by
// r is needed and a coincident pair gives a zero gradient instead of a NaN.
#pragma once
#include "common/hd.hpp"
#include "common/tensor.hpp"

namespace impactsph {

enum class KernelKind : int { WendlandC2 = 0, CubicSpline = 1 };

// Wendland C2 (F eq 2.15): W = 21/(16 pi h^3) (1 - q/2)^4 (2q + 1), q = r/h in [0, 2].
// One division per call: these run for every pair of every pass. Both kernels' W, like their gradient
// factors, take every branch and choose by q (pair loops in SIMD lanes, gpu/solver_clusters.hpp).
template <class Real> IMPACTSPH_HD Real wendland_c2_w(Real r, Real h) {
  const Real inv_h = Real(1) / h;
  const Real q = r * inv_h;
  const Real alpha = Real(21) / (Real(16) * Constants<Real>::pi) * inv_h * inv_h * inv_h;
  const Real t = Real(1) - Real(0.5) * q;
  return choose(q >= Real(2), Real(0), alpha * (t * t) * (t * t) * (Real(2) * q + Real(1)));
}
// dW/dr = -5 alpha q (1 - q/2)^3 / h, so grad W = -5 alpha (1 - q/2)^3 / h^2 * (x_i - x_j). The gradient
// factors are taken for every r and then chosen by q, with no branch, so that a loop over pairs can take
// them in SIMD lanes (reference/solver.cpp, candidate_kernel).
template <class Real> IMPACTSPH_HD Real wendland_c2_grad_factor(Real r, Real h) {
  const Real inv_h = Real(1) / h;
  const Real q = r * inv_h;
  const Real inv_h2 = inv_h * inv_h;
  const Real alpha = Real(21) / (Real(16) * Constants<Real>::pi) * inv_h2 * inv_h;
  const Real t = Real(1) - Real(0.5) * q;
  const Real f = Real(-5) * alpha * t * t * t * inv_h2;
  return choose(q >= Real(2), Real(0), f);
}

// Cubic B-spline (X eq 2), 3D constant 1/(pi h^3):
// W = alpha (1 - 1.5 q^2 + 0.75 q^3) for q < 1, alpha (2 - q)^3 / 4 for 1 <= q < 2.
template <class Real> IMPACTSPH_HD Real cubic_spline_w(Real r, Real h) {
  const Real q = r / h;
  const Real alpha = Real(1) / (Constants<Real>::pi * h * h * h);
  const Real inner = alpha * (Real(1) - Real(1.5) * q * q + Real(0.75) * q * q * q);
  const Real t = Real(2) - q;
  const Real outer = alpha * Real(0.25) * t * t * t;
  return choose(q < Real(1), inner, choose(q < Real(2), outer, Real(0)));
}
// dW/dq = alpha (-3q + 2.25 q^2) or -0.75 alpha (2 - q)^2; grad W = (dW/dq)/(q h^2) (x_i - x_j).
template <class Real> IMPACTSPH_HD Real cubic_spline_grad_factor(Real r, Real h) {
  const Real q = r / h;
  const Real alpha = Real(1) / (Constants<Real>::pi * h * h * h);
  const Real inner = alpha * (Real(-3) + Real(2.25) * q) / (h * h);
  const Real t = Real(2) - q;
  const Real outer = Real(-0.75) * alpha * t * t / (q * h * h);  // not taken at q = 0
  return choose(q < Real(1), inner, choose(q < Real(2), outer, Real(0)));
}

template <class Real> IMPACTSPH_HD Real kernel_w(KernelKind k, Real r, Real h) {
  return k == KernelKind::WendlandC2 ? wendland_c2_w(r, h) : cubic_spline_w(r, h);
}
template <class Real> IMPACTSPH_HD Real kernel_grad_factor(KernelKind k, Real r, Real h) {
  return k == KernelKind::WendlandC2 ? wendland_c2_grad_factor(r, h) : cubic_spline_grad_factor(r, h);
}
// The same with the kernel fixed at compile time, for pair loops that choose the kernel once outside (no
// select between the two for every pair).
template <KernelKind K, class Real> IMPACTSPH_HD Real kernel_grad_factor_of(Real r, Real h) {
  if constexpr (K == KernelKind::WendlandC2) return wendland_c2_grad_factor(r, h);
  else return cubic_spline_grad_factor(r, h);
}
// grad_i W_ij for x_ij = x_i - x_j.
template <class Real> IMPACTSPH_HD Vec3<Real> kernel_grad(KernelKind k, Vec3<Real> xij, Real h) {
  return kernel_grad_factor(k, norm(xij), h) * xij;
}

// Support radius in units of h, the same for both kernels.
template <class Real> IMPACTSPH_HD Real kernel_support(Real h) { return Real(2) * h; }

}  // namespace impactsph
