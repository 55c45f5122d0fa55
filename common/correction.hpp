// Kernel-gradient correction (F eqs 2.13-2.14):
//   L_i = -sum_j V_j grad_i W_ij (x) (x_i - x_j),  corrected gradient  grad^ W_ij = L_i^-1 grad_i W_ij.
// With this order of the outer product, sum_j V_j (f_j - f_i) grad^ W_ij is exact for linear f (patch
// test in tests/). L_i is singular for isolated particles and thin fragments (X section 3.1); there the
// uncorrected gradient is used and the particle is counted.
#pragma once
#include "common/tensor.hpp"

namespace impactsph {

template <class Real>
struct CorrectionParams {
  // Largest accepted Frobenius condition number ||L|| ||L^-1|| (3 for the identity). Above it, or for a
  // non-positive determinant, the particle falls back to the uncorrected gradient.
  Real max_condition = Real(1e3);
};

// Contribution of neighbour j to L_i.
template <class Real>
IMPACTSPH_HD void accumulate_correction(Mat3<Real>& L, Real vol_j, Vec3<Real> grad_w, Vec3<Real> xij) {
  L = L - vol_j * outer(grad_w, xij);
}

// Returns L^-1, or the identity when L is ill-conditioned; `fell_back` says which.
template <class Real>
IMPACTSPH_HD Mat3<Real> correction_inverse(const Mat3<Real>& L, const CorrectionParams<Real>& p, bool& fell_back) {
  const Real det = determinant(L);
  fell_back = true;
  if (!(det > Real(0))) return Mat3<Real>::identity();
  const Mat3<Real> inv = inverse(L, det);
  const Real norm_l = frobenius(L), norm_inv = frobenius(inv);
  const Real cond = norm_l * norm_inv;
  if (!(cond <= p.max_condition)) return Mat3<Real>::identity();
  // Rank-1 L (all neighbours on one line through x_i: a lone pair, a chain) has a determinant AND
  // cofactors that are pure rounding noise, and their ratio can pass the test above (about 40% of random
  // rank-1 cases did, in float and in double). The adjugate det L^-1 has norm >= sigma1 sigma2 >=
  // ||L||^2 / (3 cond), so every L the condition test rightly accepts passes this one; noise does not.
  if (!(Real(3) * p.max_condition * det * norm_inv >= norm_l * norm_l)) return Mat3<Real>::identity();
  fell_back = false;
  return inv;
}

}  // namespace impactsph
