#include "reference/neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/parallel.hpp"

namespace impactsph::reference {

void build_neighbour_list(const std::vector<Vec3d>& points, std::size_t query_count, double radius, NeighbourList& out,
                          const std::vector<double>* point_radius) {
  const std::size_t n = points.size();
  out.offsets.assign(query_count + 1, 0);
  out.indices.clear();
  if (n == 0) return;
  if (!(radius > 0)) throw std::invalid_argument("neighbour search radius must be positive");

  Vec3d lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3d hi{-lo.x, -lo.y, -lo.z};
  for (const Vec3d& x : points) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], x[a]);
      hi[a] = std::max(hi[a], x[a]);
    }
  }
  // Cells of half the radius, searched two cells either way: 125 cells of (radius/2)^3 hold about 60%
  // of the candidates of 27 cells of radius^3.
  const double cell = 0.5 * radius;
  std::int64_t dims[3];
  for (int a = 0; a < 3; ++a) dims[a] = std::max<std::int64_t>(1, static_cast<std::int64_t>((hi[a] - lo[a]) / cell) + 1);
  const std::int64_t cell_count = dims[0] * dims[1] * dims[2];
  if (cell_count > 32 * static_cast<std::int64_t>(n) + 1000000)
    throw std::runtime_error("particles spread over too large a box for the cell list (a particle has flown far away?)");

  auto cell_coord = [&](const Vec3d& x, int a) {
    return std::min<std::int64_t>(dims[a] - 1, static_cast<std::int64_t>((x[a] - lo[a]) / cell));
  };
  // Counting sort into cells: particles keep their index order inside a cell.
  std::vector<std::int64_t> cell_of(n);
  std::vector<std::int64_t> cell_start(static_cast<std::size_t>(cell_count) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d& x = points[i];
    cell_of[i] = (cell_coord(x, 2) * dims[1] + cell_coord(x, 1)) * dims[0] + cell_coord(x, 0);
    ++cell_start[static_cast<std::size_t>(cell_of[i]) + 1];
  }
  for (std::int64_t c = 0; c < cell_count; ++c) cell_start[c + 1] += cell_start[c];
  std::vector<std::int32_t> sorted(n);
  {
    std::vector<std::int64_t> fill(cell_start.begin(), cell_start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) sorted[static_cast<std::size_t>(fill[cell_of[i]]++)] = static_cast<std::int32_t>(i);
  }

  const double r2max = radius * radius;
  auto visit = [&](std::size_t i, auto&& emit) {
    const Vec3d xi = points[i];
    const std::int64_t cx = cell_coord(xi, 0), cy = cell_coord(xi, 1), cz = cell_coord(xi, 2);
    for (std::int64_t z = std::max<std::int64_t>(0, cz - 2); z <= std::min(dims[2] - 1, cz + 2); ++z)
      for (std::int64_t y = std::max<std::int64_t>(0, cy - 2); y <= std::min(dims[1] - 1, cy + 2); ++y) {
        // Cells along x are contiguous in the sorted order: one run of particles per (y, z) row.
        const std::int64_t row = (z * dims[1] + y) * dims[0];
        const std::int64_t first = cell_start[row + std::max<std::int64_t>(0, cx - 2)];
        const std::int64_t last = cell_start[row + std::min(dims[0] - 1, cx + 2) + 1];
        for (std::int64_t k = first; k < last; ++k) {
          const std::int32_t j = sorted[static_cast<std::size_t>(k)];
          if (static_cast<std::size_t>(j) == i) continue;
          const double d2 = norm2(xi - points[static_cast<std::size_t>(j)]);
          if (!point_radius) {
            if (d2 < r2max) emit(j);
          } else {
            const double r = std::max((*point_radius)[i], (*point_radius)[static_cast<std::size_t>(j)]);
            if (d2 < r * r) emit(j);
          }
        }
      }
  };

  // One pass: the queries are cut into one contiguous block per thread, each block gathers its rows into
  // its own buffer, and the buffers are laid end to end in block order. The list is the rows in query order
  // whatever the number of blocks.
  const std::int64_t blocks = parallel_thread_count();
  auto block_begin = [&](std::int64_t b) {
    return query_count * static_cast<std::size_t>(b) / static_cast<std::size_t>(blocks);
  };
  std::vector<std::int64_t> counts(query_count);
  std::vector<std::vector<std::int32_t>> buffers(static_cast<std::size_t>(blocks));
  parallel_for(blocks, [&](std::int64_t b) {
    std::vector<std::int32_t>& buf = buffers[static_cast<std::size_t>(b)];
    buf.reserve((block_begin(b + 1) - block_begin(b)) * 64);
    for (std::size_t i = block_begin(b); i < block_begin(b + 1); ++i) {
      const std::size_t before = buf.size();
      visit(i, [&](std::int32_t j) { buf.push_back(j); });
      counts[i] = static_cast<std::int64_t>(buf.size() - before);
    }
  });
  for (std::size_t i = 0; i < query_count; ++i) out.offsets[i + 1] = out.offsets[i] + counts[i];
  out.indices.resize(static_cast<std::size_t>(out.offsets[query_count]));
  parallel_for(blocks, [&](std::int64_t b) {
    const std::vector<std::int32_t>& buf = buffers[static_cast<std::size_t>(b)];
    std::copy(buf.begin(), buf.end(), out.indices.begin() + out.offsets[block_begin(b)]);
  });
}

}  // namespace impactsph::reference
