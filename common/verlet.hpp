// Verlet neighbour lists, written once for both solvers: the reach a list must cover and when it may be
// kept (reference/solver.cpp update_neighbours, gpu/solver_impl.hpp step). Lengths in m, speeds in m/s.
#pragma once
#include "common/hd.hpp"

namespace impactsph {

// Reach of the neighbour search without its skin: the kernel support at the largest h, the largest fixed
// penalty contact distance, or SRAD times the largest h (X eqs 18, 20), whichever is largest.
inline double search_reach(double support_at_h_max, double contact_distance, double srad, double h_max) {
  const double c = contact_distance > srad * h_max ? contact_distance : srad * h_max;
  return support_at_h_max > c ? support_at_h_max : c;
}

// The skin a list is built with, as a share of the reach: a larger skin keeps a list over more steps but
// gives every row more candidates to test.
constexpr double kVerletSkinShare = 0.05;
inline double verlet_skin(double reach) { return kVerletSkinShare * reach; }

// A list built with radius reach + skin still holds every pair that can come within reach at either
// stage of the next step of dt while 2 (largest displacement since the build + dt vmax) + growth of the
// reach (a variable h) < skin: each of the two particles moved at most that far (by the midpoint a
// particle has moved dt/2 |v|; the second evaluation's pairs are at most dt vmax closer than at the step
// start). 1.01 covers the rounding of the speed.
inline bool verlet_list_holds(double moved, double dt, double vmax, double growth, double skin) {
  return moved + dt * vmax * 1.01 + 0.5 * growth < 0.5 * skin;
}

}  // namespace impactsph
