// The weight of an integral non-local average (common/nonlocal.hpp) and the width it gives a band, written
// once for both solvers. Lengths in m.
#pragma once
#include "common/hd.hpp"

namespace impactsph {

// The bell-shaped weight alpha = (1 - r^2/R^2)^2 for r < R, 0 beyond (dimensionless; r2 = r^2 in m^2, R the
// averaging radius in m): the usual weight of integral non-local models (Bazant and Jirasek 2002,
// "Nonlocal integral formulations of plasticity and damage: survey of progress", J. Eng. Mech. 128,
// 1119-1149). Smooth at R, so that a particle's average does not jump as a neighbour crosses it.
template <class Real> IMPACTSPH_HD Real nonlocal_weight(Real r2, Real R) {
  const Real q = Real(1) - r2 / (R * R);
  return q > Real(0) ? q * q : Real(0);
}

// The width L (m) of the average across a plane: a thin band of work per unit area G (J/m^2) in an
// unbounded body raises the average at its centre by G / L. L = int alpha dV / int_plane alpha dA
// = (32 pi R^3 / 105) / (pi R^2 / 3) = 32 R / 35.
template <class Real> IMPACTSPH_HD Real nonlocal_band_width(Real R) { return Real(32) / Real(35) * R; }

}  // namespace impactsph
