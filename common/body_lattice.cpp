// The lattice of one body, fitted to its shape at about the case's spacing (scene.cpp says how): boxes and
// cylinder lengths in whole layers, round sections at the spacing that holds the circle exactly, noses,
// spheres and meshes (common/scene_parts.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/damage.hpp"
#include "common/errors.hpp"
#include "common/mesh_solid.hpp"
#include "common/scene_parts.hpp"
#include "common/units.hpp"

namespace impactsph::scene_detail {

std::string point(const Vec3d& p) {
  return "(" + format_quantity(p.x, Dimension::Length) + ", " + format_quantity(p.y, Dimension::Length) + ", " +
         format_quantity(p.z, Dimension::Length) + ")";
}

std::string body_key(std::size_t k) { return "bodies[" + std::to_string(k) + "]"; }
// How a message names body k after the key bodies[k]: by its name; other bodies as bodies[j] ("name").
std::string body_name(const CaseSpec& spec, std::size_t k) { return "\"" + spec.bodies[k].name + "\""; }
std::string body_label(const CaseSpec& spec, std::size_t k) { return body_key(k) + " (" + body_name(spec, k) + ")"; }
char axis_name(int a) { return static_cast<char>('x' + a); }

// The two cross-section axes of a cylinder along `axis`, in cyclic order.
void cross_axes(int axis, int& u, int& v) {
  u = (axis + 1) % 3;
  v = (axis + 2) % 3;
}

// The radius of a cylinder's cross-section at the distance t from its base along the axis: the radius in
// the shank, the nose's profile r(x) at the distance x from the shank in the nose (Nose in case_spec.hpp).
double section_radius(const BodySpec& b, double t) {
  const double x = b.nose_at_base ? b.nose_length - t : t - (b.length - b.nose_length);
  if (b.nose == Nose::Flat || x <= 0) return b.radius;
  if (x >= b.nose_length) return 0;
  const double r = b.radius;
  if (b.nose == Nose::Hemispherical) return std::sqrt(std::max(0.0, r * r - x * x));
  if (b.nose == Nose::Conical) return r * (1 - x / b.nose_length);
  const double s = 2 * b.nose_crh * r;  // the ogive's radius
  return std::max(0.0, std::sqrt(s * s - x * x) - (s - r));
}

// The volume of a cylinder's nose, m^3: pi int_0^L r(x)^2 dx over its profile. Ogive of radius S, offset
// a = S - R and length L: pi (S^2 L - L^3 / 3 - a S^2 asin(L / S)) (with sqrt(S^2 - L^2) = a).
double nose_volume(const BodySpec& b) {
  const double pi = Constants<double>::pi, r = b.radius, len = b.nose_length;
  if (b.nose == Nose::Hemispherical) return 2.0 / 3.0 * pi * r * r * r;
  if (b.nose == Nose::Conical) return pi * r * r * len / 3;
  if (b.nose == Nose::Ogival) {
    const double s = 2 * b.nose_crh * r, a = s - r;
    return pi * (s * s * len - len * len * len / 3 - a * s * s * std::asin(std::min(1.0, len / s)));
  }
  return 0;
}

// The shape's own bounding box (not the particles').
Box3 shape_bounds(const BodySpec& b) {
  if (b.shape == Shape::Box) return {b.box_min, b.box_max};
  if (b.shape == Shape::Sphere) return Box3{b.center, b.center}.grown(b.radius);
  if (b.shape == Shape::Mesh) return {b.mesh->lower(), b.mesh->upper()};
  int u, v;
  cross_axes(b.axis, u, v);
  Box3 out{b.base, b.base};
  out.hi[b.axis] += b.length;
  out.lo[u] -= b.radius, out.hi[u] += b.radius;
  out.lo[v] -= b.radius, out.hi[v] += b.radius;
  return out;
}

// Strictly inside the shape, by more than `eps`: particles of a neighbour that merely touches the
// surface are not inside.
bool strictly_inside(const BodySpec& b, const Vec3d& p, double eps) {
  if (b.shape == Shape::Box) {
    for (int a = 0; a < 3; ++a)
      if (!(p[a] > b.box_min[a] + eps && p[a] < b.box_max[a] - eps)) return false;
    return true;
  }
  if (b.shape == Shape::Sphere) {
    const double rin = b.radius - eps;
    return rin > 0 && norm2(p - b.center) < rin * rin;
  }
  if (b.shape == Shape::Mesh) return b.mesh->inside(p);
  const double t = p[b.axis] - b.base[b.axis];
  if (!(t > eps && t < b.length - eps)) return false;
  int u, v;
  cross_axes(b.axis, u, v);
  const double r2 = sqr(p[u] - b.base[u]) + sqr(p[v] - b.base[v]);
  const double rin = section_radius(b, t) - eps;
  return rin > 0 && r2 < rin * rin;
}

// The table of plane s in the case file, for messages: "boundaries.symmetry[0]", "boundaries.wall[0]".
std::string plane_key(const CaseSpec& spec, std::size_t s) {
  const SymmetryPlaneSpec& plane = spec.symmetry[s];
  return plane.key.empty() ? "boundaries.symmetry[" + std::to_string(s) + "]" : plane.key;
}

// Where the symmetry planes on `axis` cut the interval (lo, hi) strictly inside it.
std::vector<double> cuts_inside(const CaseSpec& spec, int axis, double lo, double hi, double dx) {
  std::vector<double> cuts;
  const double eps = 1e-9 * dx;
  for (const SymmetryPlaneSpec& plane : spec.symmetry)
    if (plane.axis == axis && plane.position > lo + eps && plane.position < hi - eps) cuts.push_back(plane.position);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}


AxisCells fill_axis(double lo, double hi, const std::vector<double>& cuts, double dx, int block_ratio) {
  std::vector<double> ends{lo};
  ends.insert(ends.end(), cuts.begin(), cuts.end());
  ends.push_back(hi);
  const std::size_t pieces = ends.size() - 1;
  const long long r = block_ratio;
  AxisCells out;
  long long first_block = 0;
  for (std::size_t piece = 0; piece < pieces; ++piece) {
    const double a = ends[piece], length = ends[piece + 1] - a;
    // A piece of exactly n + 1/2 spacings up to rounding takes the finer lattice, n + 1 cells.
    const long long n = std::max(1LL, static_cast<long long>(std::floor(length / dx + 0.5 + 1e-9)));
    const double w = length / double(n);
    const long long blocks = (n + r - 1) / r;
    // The first of several pieces ends on a plane: its blocks are counted down from that end.
    const bool from_top = piece == 0 && pieces > 1;
    for (long long i = 0; i < n; ++i) {
      out.centre.push_back(a + (double(i) + 0.5) * w);
      out.width.push_back(w);
      out.block.push_back(first_block + (from_top ? blocks - 1 - (n - 1 - i) / r : i / r));
    }
    first_block += blocks;
  }
  return out;
}

// The block of r cells that the round lattice's point (i + 1/2) s belongs to: floor(i / r), so that the
// blocks lie symmetrically about the centre (i = 0 .. r-1 in block 0, i = -r .. -1 in block -1).
long long round_block(long long i, int r) { return i >= 0 ? i / r : -((-i - 1) / r) - 1; }

// The round lattices: points at offsets (i + 1/2) s from the centre on each of `dim` axes (dim 2: a disk,
// the cross-section of a cylinder; dim 3: a ball), kept where the distance to the centre is at most R.
// The test is made in units of s, the same in the count and in the generation, with a relative tolerance
// that keeps points exactly on the circle.
bool in_round(double q, long long i, long long j, long long k, int dim) {
  const double r2 = sqr(double(i) + 0.5) + sqr(double(j) + 0.5) + (dim == 3 ? sqr(double(k) + 0.5) : 0.0);
  return r2 <= q;
}

double round_q(double radius, double s) { return sqr(radius / s) * (1 + 1e-12); }

// The index of the point (i + 1/2) s folded into the positive octant: i < 0 stands at -(|i| - 1/2) s.
long long fold(long long i) { return i < 0 ? -i - 1 : i; }

// Points of the round lattice of spacing s (a multiple of 4 for a disk, of 8 for a ball, by symmetry).
long long round_count(double radius, double s, int dim) {
  const double q = round_q(radius, s);
  long long n = 0;
  for (long long i = 0; sqr(double(i) + 0.5) <= q; ++i) {
    if (dim == 2) {
      n += static_cast<long long>(std::floor(std::sqrt(q - sqr(double(i) + 0.5)) + 0.5));
      continue;
    }
    for (long long j = 0; sqr(double(i) + 0.5) + sqr(double(j) + 0.5) <= q; ++j)
      n += static_cast<long long>(std::floor(std::sqrt(q - sqr(double(i) + 0.5) - sqr(double(j) + 0.5)) + 0.5));
  }
  return dim == 2 ? 4 * n : 8 * n;
}

// The spacing s nearest dx at which the round lattice holds exactly the shape's area (disk) or volume
// (ball), N(s) s^dim = V, so that each particle's cell s^dim (times the layer thickness of a cylinder)
// is its share of the body and the kernel sums over neighbours, sum_j (m_j / rho_j) W_ij, stay those of
// the lattice. N(s) is a step function of s: s_N = (V / N)^(1/dim) solves it when the lattice at s_N holds
// N points. The candidates N are tried in order of |ln(s_N / dx)| within +-10 %; 0 when none fits (a body
// only a few spacings across), and the caller keeps dx and scales the masses.
double fit_round_spacing(double radius, double dx, int dim) {
  const double volume = dim == 2 ? Constants<double>::pi * sqr(radius)
                                 : 4.0 / 3.0 * Constants<double>::pi * radius * radius * radius;
  const long long step = dim == 2 ? 4 : 8;
  const double n_dx = volume / std::pow(dx, dim);
  const double widest = 1.1;
  const long long lo = std::max(step, static_cast<long long>(std::floor(n_dx / std::pow(widest, dim) / double(step))) * step);
  const long long hi = static_cast<long long>(std::ceil(n_dx * std::pow(widest, dim) / double(step))) * step;
  std::vector<long long> candidates;
  for (long long n = lo; n <= hi; n += step) candidates.push_back(n);
  std::stable_sort(candidates.begin(), candidates.end(), [&](long long a, long long b) {
    return std::abs(std::log(double(a) / n_dx)) < std::abs(std::log(double(b) / n_dx));
  });
  for (const long long n : candidates) {
    const double s = std::pow(volume / double(n), 1.0 / dim);
    if (std::abs(std::log(s / dx)) > std::log(widest)) continue;
    if (round_count(radius, s, dim) == n) return s;
  }
  return 0;
}


// A body from a surface mesh: the box lattice of its bounding box (fill_axis, split at the symmetry planes
// inside it), kept where the point lies inside the surface. A symmetry plane that cuts the mesh must be a
// plane of symmetry of the mesh itself, since the solver mirrors the model across it: the mirror image of
// every kept point must be inside too (up to 0.5 % of them, points within rounding of the surface).
BodyLattice mesh_lattice(const CaseSpec& spec, std::size_t k, double dx, const std::string& thin_hint, int block_ratio) {
  const BodySpec& b = spec.bodies[k];
  const std::string key = body_key(k);
  const Vec3d lo = b.mesh->lower(), hi = b.mesh->upper();
  double count = 1;
  for (int a = 0; a < 3; ++a) {
    const double extent = hi[a] - lo[a];
    if (extent < 2 * dx * (1 - 1e-9))
      throw CaseError(spec.source_file, b.line, key + ".file",
                      body_name(spec, k) + " (" + b.mesh_file + ") is " + format_quantity(extent, Dimension::Length) +
                          " across along " + axis_name(a) + thin_hint);
    count *= std::round(extent / dx);
  }
  if (count > kMaxParticles)
    throw CaseError(spec.source_file, b.line, key,
                    body_name(spec, k) + "'s bounding box would hold about " +
                        format_quantity(count, Dimension::Dimensionless) + " particles at spacing " +
                        format_quantity(dx, Dimension::Length) + " (at most 1e9); use a coarser numerics.spacing");
  AxisCells axes[3];
  for (int a = 0; a < 3; ++a)
    axes[a] = fill_axis(lo[a], hi[a], cuts_inside(spec, a, lo[a], hi[a], dx), dx, block_ratio);
  BodyLattice out;
  for (std::size_t iz = 0; iz < axes[2].centre.size(); ++iz)
    for (std::size_t iy = 0; iy < axes[1].centre.size(); ++iy)
      for (std::size_t ix = 0; ix < axes[0].centre.size(); ++ix) {
        const Vec3d p{axes[0].centre[ix], axes[1].centre[iy], axes[2].centre[iz]};
        if (!b.mesh->inside(p)) continue;
        out.pts.push_back(p);
        out.cell.push_back({axes[0].width[ix], axes[1].width[iy], axes[2].width[iz]});
        if (block_ratio > 1) out.block.push_back({axes[2].block[iz], axes[1].block[iy], axes[0].block[ix]});
      }
  for (std::size_t s = 0; s < spec.symmetry.size(); ++s) {
    const SymmetryPlaneSpec& plane = spec.symmetry[s];
    if (!(plane.position > lo[plane.axis] + 1e-9 * dx && plane.position < hi[plane.axis] - 1e-9 * dx)) continue;
    std::size_t unmatched = 0;
    for (const Vec3d& p : out.pts) {
      Vec3d mirror = p;
      mirror[plane.axis] = 2 * plane.position - p[plane.axis];
      if (!b.mesh->inside(mirror)) ++unmatched;
    }
    if (double(unmatched) > 0.005 * double(out.pts.size()))
      throw CaseError(spec.source_file, b.line, key + ".file",
                      body_name(spec, k) + " (" + b.mesh_file + ") is not symmetric about the plane " +
                          axis_name(plane.axis) + " = " + format_quantity(plane.position, Dimension::Length) +
                          " (" + plane_key(spec, s) + "): the mirror images of " +
                          std::to_string(unmatched) + " of its " + std::to_string(out.pts.size()) +
                          " particles lie outside it, but the solver mirrors the model across that plane; move "
                          "the mesh (origin) so the plane is one of its planes of symmetry, or model the whole "
                          "body without the plane");
  }
  return out;
}

// Lattice points of one body; throws when the body is thinner than two particles. Boxes and the axis of
// a cylinder use fill_axis, the cross-section of a cylinder and a sphere the fitted round lattice, so
// that the cells add up to the shape's volume.
BodyLattice lattice(const CaseSpec& spec, std::size_t k, double dx, int block_ratio) {
  const BodySpec& b = spec.bodies[k];
  const std::string key = body_key(k);
  const std::string thin_hint = " at spacing " + format_quantity(dx, Dimension::Length) +
                                ": a body needs at least two particles across; make it at least " +
                                format_quantity(2 * dx, Dimension::Length) +
                                (b.coarse_ratio > 1 ? " or lower " + key + ".coarse.ratio (its coarse region needs two cells "
                                                      "of ratio x numerics.spacing across)"
                                                    : std::string(" or refine numerics.spacing"));
  BodyLattice out;
  if (b.shape == Shape::Box) {
    AxisCells axes[3];
    double count = 1;
    for (int a = 0; a < 3; ++a) {
      const double extent = b.box_max[a] - b.box_min[a];
      if (!(extent > 0))
        throw CaseError(spec.source_file, b.line, key, "max." + std::string(1, axis_name(a)) + " must be greater than min");
      // 1e-9: an extent of exactly two spacings up to rounding is accepted.
      if (extent < 2 * dx * (1 - 1e-9))
        throw CaseError(spec.source_file, b.line, key,
                        body_name(spec, k) + " is " + format_quantity(extent, Dimension::Length) + " thick along " +
                            axis_name(a) + thin_hint);
      if (extent / dx > kMaxParticles)
        throw CaseError(spec.source_file, b.line, key, "too many particles at this spacing; use a coarser numerics.spacing");
      count *= std::round(extent / dx);
    }
    if (count > kMaxParticles)
      throw CaseError(spec.source_file, b.line, key,
                      body_name(spec, k) + " would hold about " + format_quantity(count, Dimension::Dimensionless) +
                          " particles at spacing " + format_quantity(dx, Dimension::Length) +
                          " (at most 1e9); use a coarser numerics.spacing");
    for (int a = 0; a < 3; ++a)
      axes[a] = fill_axis(b.box_min[a], b.box_max[a], cuts_inside(spec, a, b.box_min[a], b.box_max[a], dx), dx,
                          block_ratio);
    out.pts.reserve(axes[0].centre.size() * axes[1].centre.size() * axes[2].centre.size());
    for (std::size_t iz = 0; iz < axes[2].centre.size(); ++iz)
      for (std::size_t iy = 0; iy < axes[1].centre.size(); ++iy)
        for (std::size_t ix = 0; ix < axes[0].centre.size(); ++ix) {
          out.pts.push_back({axes[0].centre[ix], axes[1].centre[iy], axes[2].centre[iz]});
          out.cell.push_back({axes[0].width[ix], axes[1].width[iy], axes[2].width[iz]});
          if (block_ratio > 1) out.block.push_back({axes[2].block[iz], axes[1].block[iy], axes[0].block[ix]});
        }
    return out;
  }

  if (b.shape == Shape::Mesh) return mesh_lattice(spec, k, dx, thin_hint, block_ratio);

  if (b.shape == Shape::Sphere) {
    // 1e-9: a diameter of exactly two cells up to rounding is accepted (it holds the 8 points at
    // (+-1/2, +-1/2, +-1/2) s).
    if (b.radius < dx * (1 - 1e-9))
      throw CaseError(spec.source_file, b.line, key,
                      body_name(spec, k) + " has a diameter of " + format_quantity(2 * b.radius, Dimension::Length) +
                          thin_hint);
    const double estimate = 4.0 / 3.0 * Constants<double>::pi * std::pow(b.radius / dx, 3);
    if (estimate > kMaxParticles)
      throw CaseError(spec.source_file, b.line, key,
                      body_name(spec, k) + " would hold about " + format_quantity(estimate, Dimension::Dimensionless) +
                          " particles at spacing " + format_quantity(dx, Dimension::Length) +
                          " (at most 1e9); use a coarser numerics.spacing");
    double s = fit_round_spacing(b.radius, dx, 3);
    out.round_fitted = s > 0;
    if (!out.round_fitted) s = dx;
    // Offsets (i + 1/2) s from the centre on every axis, as the cross-section of a cylinder: a plane
    // through the centre lies halfway between two lattice layers, so two or three planes through it
    // cut an exact quarter or eighth.
    const double q = round_q(b.radius, s);
    const long long mi = static_cast<long long>(std::ceil(b.radius / s)) + 1;
    out.pts.reserve(static_cast<std::size_t>(estimate * 1.3) + 8);
    for (long long kz = -mi; kz < mi; ++kz)
      for (long long jy = -mi; jy < mi; ++jy)
        for (long long ix = -mi; ix < mi; ++ix) {
          if (!in_round(q, fold(ix), fold(jy), fold(kz), 3)) continue;
          out.pts.push_back(b.center + Vec3d{(double(ix) + 0.5) * s, (double(jy) + 0.5) * s, (double(kz) + 0.5) * s});
          out.cell.push_back({s, s, s});
          if (block_ratio > 1)
            out.block.push_back({round_block(kz, block_ratio), round_block(jy, block_ratio), round_block(ix, block_ratio)});
        }
    return out;
  }

  // 1e-9: a length or diameter of exactly two cells up to rounding is accepted.
  if (b.length < 2 * dx * (1 - 1e-9))
    throw CaseError(spec.source_file, b.line, key,
                    body_name(spec, k) + " is " + format_quantity(b.length, Dimension::Length) + " long" + thin_hint);
  if (b.radius < dx * (1 - 1e-9))
    throw CaseError(spec.source_file, b.line, key,
                    body_name(spec, k) + " has a diameter of " + format_quantity(2 * b.radius, Dimension::Length) +
                        thin_hint);
  const double estimate = std::round(b.length / dx) * Constants<double>::pi * sqr(b.radius / dx);
  if (estimate > kMaxParticles)
    throw CaseError(spec.source_file, b.line, key,
                    body_name(spec, k) + " would hold about " + format_quantity(estimate, Dimension::Dimensionless) +
                        " particles at spacing " + format_quantity(dx, Dimension::Length) +
                        " (at most 1e9); use a coarser numerics.spacing");
  int u, v;
  cross_axes(b.axis, u, v);
  const double base = b.base[b.axis];
  const AxisCells layers =
      fill_axis(base, base + b.length, cuts_inside(spec, b.axis, base, base + b.length, dx), dx, block_ratio);
  double s = fit_round_spacing(b.radius, dx, 2);
  out.round_fitted = s > 0;
  if (!out.round_fitted) s = dx;
  const double q = round_q(b.radius, s);
  struct SectionPoint {
    double u, v;
    long long block_u, block_v;
  };
  std::vector<SectionPoint> section;
  const long long mi = static_cast<long long>(std::ceil(b.radius / s)) + 1;
  for (long long j = -mi; j < mi; ++j)
    for (long long i = -mi; i < mi; ++i)
      if (in_round(q, fold(i), fold(j), 0, 2))
        section.push_back({(double(i) + 0.5) * s, (double(j) + 0.5) * s, round_block(i, block_ratio),
                           round_block(j, block_ratio)});
  out.pts.reserve(layers.centre.size() * section.size());
  for (std::size_t kk = 0; kk < layers.centre.size(); ++kk) {
    // A layer of the nose keeps the points of the cross-section within the profile at its centre (the
    // midpoint rule for the nose's volume); 1e-12 keeps points exactly on it.
    const double keep = section_radius(b, layers.centre[kk] - base);
    const double keep2 = sqr(keep) * (1 + 1e-12);
    for (const SectionPoint& sp : section) {
      const double ou = sp.u, ov = sp.v;
      if (keep < b.radius && sqr(ou) + sqr(ov) > keep2) continue;
      Vec3d p = b.base, cell;
      p[b.axis] = layers.centre[kk];
      p[u] += ou;
      p[v] += ov;
      cell[b.axis] = layers.width[kk];
      cell[u] = s;
      cell[v] = s;
      out.pts.push_back(p);
      out.cell.push_back(cell);
      if (block_ratio > 1) out.block.push_back({layers.block[kk], sp.block_v, sp.block_u});
    }
  }
  return out;
}

// A body at two resolutions (BodySpec::coarse_ratio > 1): its one-resolution lattice at dx, with every
// complete block of ratio^3 cells whose centre lies in the coarse region merged into one cell (the blocks of
// AxisCells and round_block, in the order of the lattice at ratio x dx; within a block its cells keep the
// lattice's order). A merged cell is its block exactly (the sum of its cells' volumes, centred on their
// centroid), so the body keeps its volume, mass and sizes, and the fine part is the one-resolution lattice
// point for point, round cross-sections included. Blocks cut by the body's surface (the outer ring of a round
// section, a layer left over where a count does not divide by the ratio) stay fine. Throws when the body is
// thinner than two cells at ratio x dx, or when the region merges none of its blocks or all of its cells.
BodyLattice two_resolution_lattice(const CaseSpec& spec, std::size_t k, double dx) {
  const BodySpec& b = spec.bodies[k];
  const int r = b.coarse_ratio;
  const double coarse_dx = r * dx;
  lattice(spec, k, coarse_dx);  // its checks only: two coarse cells across, the message naming coarse.ratio
  const BodyLattice fine = lattice(spec, k, dx, r);
  std::vector<std::size_t> order(fine.pts.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t c) { return fine.block[a] < fine.block[c]; });

  BodyLattice out;
  out.round_fitted = fine.round_fitted;
  const std::size_t block_cells = static_cast<std::size_t>(r) * r * r;
  std::size_t merged = 0;
  for (std::size_t first = 0; first < order.size();) {
    std::size_t end = first + 1;
    while (end < order.size() && fine.block[order[end]] == fine.block[order[first]]) ++end;
    Vec3d centre{0, 0, 0}, widths{0, 0, 0};
    for (std::size_t n = first; n < end; ++n) {
      centre = centre + fine.pts[order[n]];
      widths = widths + fine.cell[order[n]];
    }
    centre = centre * (1.0 / double(end - first));
    if (end - first == block_cells && in_fixed_region(b.coarse_region, centre, 1e-9 * dx)) {
      out.pts.push_back(centre);
      out.cell.push_back(widths * (1.0 / double(r * r)));  // each of the r cells along an axis counted r^2 times
      out.spacing.push_back(coarse_dx);
      ++merged;
    } else {
      for (std::size_t n = first; n < end; ++n) {
        out.pts.push_back(fine.pts[order[n]]);
        out.cell.push_back(fine.cell[order[n]]);
        out.spacing.push_back(dx);
      }
    }
    first = end;
  }
  const std::string key = body_key(k) + ".coarse";
  if (merged == 0)
    throw CaseError(spec.source_file, b.line, key,
                    "the region holds the centre of none of " + body_name(spec, k) + "'s complete blocks of " +
                        std::to_string(block_cells) + " cells (its coarse spacing is " +
                        format_quantity(coarse_dx, Dimension::Length) +
                        "): it lies outside the body; move or enlarge it, or remove [bodies.coarse]");
  if (merged == out.pts.size())
    throw CaseError(spec.source_file, b.line, key,
                    "the region holds every cell of " + body_name(spec, k) +
                        ", so no part of it is at numerics.spacing; shrink the region, or remove [bodies.coarse] and "
                        "give the body's spacing as numerics.spacing");
  return out;
}

}  // namespace impactsph::scene_detail
