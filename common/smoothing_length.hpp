// Variable smoothing length (X eqs 9-10; LS-DYNA *CONTROL_SPH with DERIV = 0).
// From continuity d rho/dt = -rho div v and h ~ rho^(-1/d) at a constant neighbour count,
//   dh/dt = (1/d) h div v,  d = 3,
// so h grows where the material expands (div v > 0) and shrinks where it is compressed. (X eq 9 prints
// this sign, which is the consistent one; physics-notes agrees.) The result is kept within
// [h_lo, h_hi] = [HMIN h0, HMAX h0] (X eq 10; X uses HMIN = 0.2, HMAX = 2.0). Units: h in m, div v in 1/s,
// dt in s.
#pragma once
#include "common/hd.hpp"

namespace impactsph {

template <class Real> IMPACTSPH_HD Real smoothing_length_rate(Real h, Real div_v) { return h * div_v / Real(3); }

// One explicit Euler step of X eq 9, clamped to the bounds of X eq 10.
template <class Real>
IMPACTSPH_HD Real advance_smoothing_length(Real h, Real div_v, Real dt, Real h_lo, Real h_hi) {
  const Real next = h + dt * smoothing_length_rate(h, div_v);
  return min_of(max_of(next, h_lo), h_hi);
}

}  // namespace impactsph
