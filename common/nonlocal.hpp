// Integral non-local plastic work (the non-local fracture-energy damage, common/models/
// damage_fracture_energy.hpp): a particle's average of the plastic work per unit initial volume over the
// material of its body within R of it, weighted by nonlocal_weight and the neighbours' initial volumes,
// in the initial configuration (a material neighbourhood: the same neighbours for the whole run, and a
// stretched band does not thin its average). The average is normalised by the weights it found, so a
// uniform field averages to itself at a free surface too. Symmetry planes are not mirrored: across a
// plane the average is one-sided, which leaves a band that crosses the plane at right angles (a plug's
// rim crossing the quarter model's planes) unchanged.
// The cell grid is built once on the host (build_nonlocal_grid) in the scene's particle order; each
// solver keeps its arrays and calls nonlocal_work_density in its own loop.
#pragma once
#include <cstdint>
#include <vector>

#include "common/material.hpp"
#include "common/nonlocal_weight.hpp"
#include "common/particle_set.hpp"

namespace impactsph {

// The particles that average, in cells of side `cell` (m) from `origin` (m), nx x ny x nz of them. Entries
// are ordered by cell and, within a cell, by scene index; cell c holds entries cell_start[c] ..
// cell_start[c+1]. Pointers into host or device arrays (NonlocalGridData holds the host's).
template <class Real> struct NonlocalGrid {
  Vec3<double> origin{0, 0, 0};
  double cell = 0;
  int nx = 0, ny = 0, nz = 0;
  const std::int32_t* cell_start = nullptr;  // nx ny nz + 1
  const std::int32_t* particle = nullptr;    // scene index of each entry
  const Vec3<double>* position = nullptr;    // initial position of each entry, m
  const Real* volume = nullptr;              // initial volume m / rho0 of each entry, m^3
  const std::int32_t* body = nullptr;        // body of each entry
  const std::int32_t* entry_of = nullptr;    // per scene index: its entry, -1 for a particle that does not average
};

// The non-local plastic work density of the particle of scene index i (J/m^3): sum_j V0_j alpha_ij W_j /
// sum_j V0_j alpha_ij over the entries j of its body within R (m) of its initial position, W_j = work[j]
// (J/m^3, indexed by scene index) and alpha = nonlocal_weight. The sum runs over cells and entries in a fixed
// order, so it does not depend on the solver's particle order. 0 for a particle that does not average.
template <class Real>
IMPACTSPH_HD Real nonlocal_work_density(const NonlocalGrid<Real>& g, std::int32_t i, Real R, const Real* work) {
  const std::int32_t e = g.entry_of[i];
  if (e < 0) return Real(0);
  const Vec3<double> x = g.position[e];
  const std::int32_t b = g.body[e];
  int lo[3], hi[3];
  const int n[3] = {g.nx, g.ny, g.nz};
  for (int a = 0; a < 3; ++a) {
    const double u = (x[a] - g.origin[a]) / g.cell;
    const double r = double(R) / g.cell;
    lo[a] = static_cast<int>(u - r);
    hi[a] = static_cast<int>(u + r);
    lo[a] = lo[a] < 0 ? 0 : lo[a];
    hi[a] = hi[a] > n[a] - 1 ? n[a] - 1 : hi[a];
  }
  Real sum_w = 0, sum_wW = 0;
  for (int cz = lo[2]; cz <= hi[2]; ++cz)
    for (int cy = lo[1]; cy <= hi[1]; ++cy)
      for (int cx = lo[0]; cx <= hi[0]; ++cx) {
        const int c = (cz * g.ny + cy) * g.nx + cx;
        for (std::int32_t k = g.cell_start[c]; k < g.cell_start[c + 1]; ++k) {
          if (g.body[k] != b) continue;
          const Vec3<double> d = g.position[k] - x;
          const Real alpha = nonlocal_weight(Real(dot(d, d)), R);
          if (!(alpha > Real(0))) continue;
          const Real w = g.volume[k] * alpha;
          sum_w += w;
          sum_wW += w * work[g.particle[k]];
        }
      }
  return sum_w > Real(0) ? sum_wW / sum_w : Real(0);
}

// The host's arrays of a NonlocalGrid.
struct NonlocalGridData {
  Vec3<double> origin{0, 0, 0};
  double cell = 0;
  int nx = 0, ny = 0, nz = 0;
  std::vector<std::int32_t> cell_start, particle, body, entry_of;
  std::vector<Vec3<double>> position;
  std::vector<double> volume;
  bool empty() const { return particle.empty(); }
  NonlocalGrid<double> view() const {
    return {origin, cell, nx, ny, nz, cell_start.data(), particle.data(), position.data(), volume.data(),
            body.data(), entry_of.data()};
  }
};

// The grid of the particles of p whose material averages (damage_nonlocal_radius > 0), at their positions
// in p (the initial configuration: the solvers build it from the scene before a checkpoint is loaded), in
// cells as large as the largest radius. Empty when no material averages.
NonlocalGridData build_nonlocal_grid(const ParticleSet& p, const std::vector<MaterialParams<double>>& materials);

}  // namespace impactsph
