// The gpu port's cell lists (in the backend's namespace: included by gpu/solver_impl.hpp): the grid of
// cells of half the search radius, the cell ranges of the sorted points and the bounding-box reduction.
#pragma once
#include <cstdint>

#include "common/hd.hpp"
#include "common/stages.hpp"

namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND {

// Cells of half the search radius in a box; key = (cz dy + cy) dx + cx, so the cells along x are
// contiguous and a row of five cells is one range of sorted points.
struct Grid {
  double lo[3];
  double cell;
  std::int64_t dims[3];
  IMPACTSPH_HD std::int64_t coord(double x, int a) const {
    const std::int64_t c = static_cast<std::int64_t>((x - lo[a]) / cell);
    return c < 0 ? 0 : (c > dims[a] - 1 ? dims[a] - 1 : c);
  }
  IMPACTSPH_HD std::uint32_t key(Vec3p x) const {
    return static_cast<std::uint32_t>((coord(x.z, 2) * dims[1] + coord(x.y, 1)) * dims[0] + coord(x.x, 0));
  }
};

// The sorted points and their cell ranges: cell c holds the slots cell_start[c] .. cell_start[c+1].
struct CellRange {
  const Vec3p* x;
  const std::int32_t* cell_start;
  Grid grid;
  // Calls f(j) for every sorted slot j != s in the 5x5x5 cells around the cell of slot s.
  template <class F> IMPACTSPH_HD void for_each_candidate(std::int64_t s, F&& f) const {
    const Vec3p xs = x[s];
    const std::int64_t cx = grid.coord(xs.x, 0), cy = grid.coord(xs.y, 1), cz = grid.coord(xs.z, 2);
    const std::int64_t x0 = cx - 2 < 0 ? 0 : cx - 2, x1 = cx + 2 > grid.dims[0] - 1 ? grid.dims[0] - 1 : cx + 2;
    const std::int64_t y0 = cy - 2 < 0 ? 0 : cy - 2, y1 = cy + 2 > grid.dims[1] - 1 ? grid.dims[1] - 1 : cy + 2;
    const std::int64_t z0 = cz - 2 < 0 ? 0 : cz - 2, z1 = cz + 2 > grid.dims[2] - 1 ? grid.dims[2] - 1 : cz + 2;
    for (std::int64_t z = z0; z <= z1; ++z)
      for (std::int64_t y = y0; y <= y1; ++y) {
        const std::int64_t row = (z * grid.dims[1] + y) * grid.dims[0];  // cells along x are contiguous
        const std::int32_t first = cell_start[row + x0], last = cell_start[row + x1 + 1];
        for (std::int32_t j = first; j < last; ++j)
          if (j != s) f(j);
      }
  }
};

struct Box {
  Vec3p lo, hi;
};
struct PointBox {
  IMPACTSPH_HD Box operator()(Vec3p x) const { return {x, x}; }
};
struct MergeBox {
  IMPACTSPH_HD Box operator()(Box a, Box b) const {
    return {{a.lo.x < b.lo.x ? a.lo.x : b.lo.x, a.lo.y < b.lo.y ? a.lo.y : b.lo.y, a.lo.z < b.lo.z ? a.lo.z : b.lo.z},
            {a.hi.x > b.hi.x ? a.hi.x : b.hi.x, a.hi.y > b.hi.y ? a.hi.y : b.hi.y, a.hi.z > b.hi.z ? a.hi.z : b.hi.z}};
  }
};

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND
