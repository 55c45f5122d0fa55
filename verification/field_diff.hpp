// Field differences between two particle sets of the same scene (a solver against the reference), with
// these definitions: for displacement u = x - x_0 (m), velocity (m/s),
// density (kg/m^3) and stress sigma = S - P I (Pa, six components), the relative L2 difference
// |a - b|_2 / |b|_2 over the particles and the relative max difference max_i |a_i - b_i| / max_i |b_i|,
// b the reference. Used by verification/crosscheck and `impactsph verify` (section "CPU against GPU port").
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "common/particle_set.hpp"

namespace impactsph::verification {

struct FieldDiff {
  double l2 = 0, max = 0;  // relative
};

// Relative L2 and max differences of a field with `dim` components per particle; get(i, c, a, b) sets
// component c of particle i in both sets.
template <class Get>
FieldDiff field_diff(std::size_t n, int dim, Get get) {
  double d2 = 0, b2 = 0, dmax = 0, bmax = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double dd = 0, bb = 0;
    for (int c = 0; c < dim; ++c) {
      double a = 0, b = 0;
      get(i, c, a, b);
      dd += (a - b) * (a - b);
      bb += b * b;
    }
    d2 += dd;
    b2 += bb;
    dmax = std::max(dmax, std::sqrt(dd));
    bmax = std::max(bmax, std::sqrt(bb));
  }
  FieldDiff r;
  r.l2 = b2 > 0 ? std::sqrt(d2 / b2) : std::sqrt(d2);
  r.max = bmax > 0 ? dmax / bmax : dmax;
  return r;
}

inline double stress_component(const ParticleSet& p, std::size_t i, int c) {
  const Sym3d& s = p.dev_stress[i];
  const double v[6] = {s.xx - p.pressure[i], s.yy - p.pressure[i], s.zz - p.pressure[i], s.xy, s.yz, s.zx};
  return v[c];
}

// Displacement, velocity, density, stress (in this order) of `a` against the reference `b`; x0 holds the
// initial positions of both.
struct FieldDiffs {
  static constexpr const char* names[4] = {"displacement", "velocity", "density", "stress"};
  std::array<FieldDiff, 4> field;
};

inline FieldDiffs compare_fields(const ParticleSet& a, const ParticleSet& b, const std::vector<Vec3d>& x0) {
  const std::size_t n = b.size();
  FieldDiffs d;
  d.field[0] = field_diff(n, 3, [&](std::size_t i, int c, double& va, double& vb) {
    va = a.pos[i][c] - x0[i][c];
    vb = b.pos[i][c] - x0[i][c];
  });
  d.field[1] = field_diff(n, 3, [&](std::size_t i, int c, double& va, double& vb) {
    va = a.vel[i][c];
    vb = b.vel[i][c];
  });
  d.field[2] = field_diff(n, 1, [&](std::size_t i, int, double& va, double& vb) {
    va = a.rho[i];
    vb = b.rho[i];
  });
  d.field[3] = field_diff(n, 6, [&](std::size_t i, int c, double& va, double& vb) {
    va = stress_component(a, i, c);
    vb = stress_component(b, i, c);
  });
  return d;
}

}  // namespace impactsph::verification
