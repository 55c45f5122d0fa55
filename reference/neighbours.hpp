// Cell-linked list neighbour search for the reference solver (design.md, step 1).
// Particles are binned into cubic cells of half the search radius; each particle's neighbours are gathered
// from the surrounding cells in a fixed order into a compressed list (CSR). The solver keeps the list
// over several steps (a Verlet list with a skin, ReferenceSolver::update_neighbours) and sorts each row by
// index. Building and the order inside each row do not depend on the thread count.
#pragma once
#include <cstdint>
#include <vector>

#include "common/particle_set.hpp"

namespace impactsph::reference {

struct NeighbourList {
  std::vector<std::int64_t> offsets;  // row i is indices[offsets[i], offsets[i+1])
  std::vector<std::int32_t> indices;  // neighbour j (excluding i itself)
  double mean_count() const {
    const std::size_t rows = offsets.empty() ? 0 : offsets.size() - 1;
    return rows ? static_cast<double>(indices.size()) / static_cast<double>(rows) : 0.0;
  }
};

// Neighbours within `radius` of each of the first `query_count` points, searched among all points
// (queries first, then e.g. mirror ghosts). With `point_radius` (one per point, none above `radius`), a pair
// is held when it lies within the larger of its two points' radii (reach_per_pair, common/verlet.hpp).
void build_neighbour_list(const std::vector<Vec3d>& points, std::size_t query_count, double radius, NeighbourList& out,
                          const std::vector<double>* point_radius = nullptr);

}  // namespace impactsph::reference
