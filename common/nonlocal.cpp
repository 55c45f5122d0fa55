#include "common/nonlocal.hpp"

#include <algorithm>
#include <cmath>

#include "common/damage.hpp"

namespace impactsph {

NonlocalGridData build_nonlocal_grid(const ParticleSet& p, const std::vector<MaterialParams<double>>& materials) {
  NonlocalGridData g;
  const std::size_t n = p.size();
  g.entry_of.assign(n, -1);
  double R = 0;
  std::vector<std::int32_t> members;
  Vec3<double> lo{0, 0, 0}, hi{0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const double r = damage_nonlocal_radius(materials[static_cast<std::size_t>(p.material[i])]);
    if (!(r > 0)) continue;
    R = std::max(R, r);
    const Vec3<double> x = p.pos[i];
    if (members.empty()) lo = hi = x;
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], x[a]);
      hi[a] = std::max(hi[a], x[a]);
    }
    members.push_back(static_cast<std::int32_t>(i));
  }
  if (members.empty()) {
    g.entry_of.clear();
    return g;
  }
  g.origin = lo;
  g.cell = R;
  auto cells = [&](int a) { return std::max(1, static_cast<int>(std::floor((hi[a] - lo[a]) / R)) + 1); };
  g.nx = cells(0);
  g.ny = cells(1);
  g.nz = cells(2);
  auto cell_of = [&](const Vec3<double>& x) {
    int c[3];
    const int dims[3] = {g.nx, g.ny, g.nz};
    for (int a = 0; a < 3; ++a) c[a] = std::min(dims[a] - 1, static_cast<int>((x[a] - g.origin[a]) / g.cell));
    return (c[2] * g.ny + c[1]) * g.nx + c[0];
  };
  const std::size_t ncell = static_cast<std::size_t>(g.nx) * g.ny * g.nz;
  g.cell_start.assign(ncell + 1, 0);
  for (std::int32_t i : members) ++g.cell_start[static_cast<std::size_t>(cell_of(p.pos[static_cast<std::size_t>(i)])) + 1];
  for (std::size_t c = 0; c < ncell; ++c) g.cell_start[c + 1] += g.cell_start[c];
  std::vector<std::int32_t> fill(g.cell_start.begin(), g.cell_start.end() - 1);
  const std::size_t m = members.size();
  g.particle.resize(m);
  g.position.resize(m);
  g.volume.resize(m);
  g.body.resize(m);
  for (std::int32_t i : members) {  // in scene order, so each cell lists its particles by scene index
    const std::size_t s = static_cast<std::size_t>(i);
    const std::int32_t e = fill[static_cast<std::size_t>(cell_of(p.pos[s]))]++;
    const std::size_t k = static_cast<std::size_t>(e);
    g.particle[k] = i;
    g.position[k] = p.pos[s];
    g.volume[k] = p.mass[s] / materials[static_cast<std::size_t>(p.material[s])].eos.rho0;
    g.body[k] = p.body[s];
    g.entry_of[s] = e;
  }
  return g;
}

}  // namespace impactsph
