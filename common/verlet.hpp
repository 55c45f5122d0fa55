// Verlet neighbour lists, written once for both solvers: the reach a list must cover and when it may be
// kept (reference/solver.cpp update_neighbours, gpu/solver_impl.hpp step). Lengths in m, speeds in m/s.
#pragma once
#include "common/hd.hpp"
#include "common/kernels.hpp"

namespace impactsph {

// Reach of the neighbour search without its skin: the kernel support at the largest h, the largest fixed
// penalty contact distance, or SRAD times the largest h (X eqs 18, 20), whichever is largest.
IMPACTSPH_HD double search_reach(double support_at_h_max, double contact_distance, double srad, double h_max) {
  const double c = contact_distance > srad * h_max ? contact_distance : srad * h_max;
  return support_at_h_max > c ? support_at_h_max : c;
}

// Two resolutions in one scene (a body's coarse region, BodySpec::coarse_ratio) give the particles two
// fixed smoothing lengths; a list built with the largest reach for every row would hold ratio^3 times the
// pairs a fine particle needs. The list then holds a pair when it lies within the reach of the larger h of
// the two plus the skin: every pair within the support at (h_i + h_j) / 2, the contact distance or
// srad (h_i + h_j) / 2 is held. With one h, or a variable h (whose lists follow the largest h), every row
// keeps the one radius.
inline bool reach_per_pair(double h_min, double h_max, bool variable_h) { return h_min < h_max && !variable_h; }
// The search radius of one point of smoothing length h (m) when reach_per_pair, its skin included; a pair is
// held within the larger of its two points' radii.
IMPACTSPH_HD double point_search_radius(double h, double contact_distance, double srad, double skin) {
  return search_reach(kernel_support(h), contact_distance, srad, h) + skin;
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
