// Scene builder: fills each body of a CaseSpec with particles on a lattice fitted to its shape at about the
// case's spacing dx, clips bodies that reach across a symmetry plane to the model side of it (quarter and
// half models), then checks the geometry (overlaps, symmetry planes, fixed regions, contact pairs) and
// throws CaseError naming the body or boundary, with the line of its table in the case file, when it is
// impossible. Particles are stored body by body in file order, each body in lattice order (the first
// cross-section axis fastest, the third slowest), so the same case always gives the same particle
// numbering (design.md, "Deterministic").
//
// A body is the shape the case gives, whatever dx: the cells of its lattice add up to the shape's volume
// and its particles carry the mass rho0 x cell volume, so the body has its mass rho0 V and its sizes.
//   box:      along each axis, n = round(extent/dx) layers of cells of width extent/n, the outermost
//             cells ending on the faces (a stretch of at most dx/2 over the extent, per axis);
//   cylinder: the same along the axis; in each layer a square lattice at offsets (i + 1/2) s from the
//             axis, kept where the distance to the axis is at most the radius, with s the spacing within
//             10 % of dx nearest to it at which the N kept points hold exactly the circle: N s^2 = pi r^2
//             (fit_round_spacing); a nose (hemispherical, conical, ogival) keeps, in each of its layers,
//             the points within the profile's radius at the layer's centre (the midpoint rule for its
//             volume); the few tenths of a percent by which the cells then miss the closed-form volume are
//             made up by scaling the body's masses (a warning above 1 %);
//   sphere:   a cubic lattice at offsets (i + 1/2) s from the centre, kept within the radius, N s^3 =
//             (4/3) pi r^3 in the same way.
// A symmetry plane strictly inside a box or a cylinder's length splits that axis into two pieces filled
// separately, so its layers lie half a cell from the plane. Stretching the lattice rather than scaling the
// masses keeps each particle's volume m/rho0 the cell it stands for, so the kernel sums over neighbours
// (sum_j m_j/rho_j W_ij = 1 inside a body) stay those of the lattice. Only where no round-lattice spacing
// within 10 % fits (a body a few spacings across) is dx kept and the masses scaled to rho0 V, with a
// warning. Every particle centre lies inside its shape; density rho0, zero energy, stress and damage,
// and h = h_factor dx.
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
#include "common/scene.hpp"
#include "common/units.hpp"

namespace impactsph {
namespace {

// Keeps an absurd spacing from exhausting memory before it is reported; also the int32 index range.
constexpr double kMaxParticles = 1e9;

struct Box3 {
  Vec3d lo, hi;
  bool intersects(const Box3& o) const {
    for (int a = 0; a < 3; ++a)
      if (hi[a] < o.lo[a] || o.hi[a] < lo[a]) return false;
    return true;
  }
  bool contains(const Vec3d& p) const {
    for (int a = 0; a < 3; ++a)
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
    return true;
  }
  Box3 grown(double d) const { return {lo - Vec3d{d, d, d}, hi + Vec3d{d, d, d}}; }
};

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

// Cells of one lattice axis that fill [lo, hi] exactly: the interval is cut at the symmetry planes strictly
// inside it, and each piece of length L holds n = max(1, round(L / dx)) cells of width L / n, so that the
// outermost cells end on the body's faces and the layers next to a plane lie half a cell from it.
struct AxisCells {
  std::vector<double> centre, width;
};

AxisCells fill_axis(double lo, double hi, const std::vector<double>& cuts, double dx) {
  std::vector<double> ends{lo};
  ends.insert(ends.end(), cuts.begin(), cuts.end());
  ends.push_back(hi);
  AxisCells out;
  for (std::size_t piece = 0; piece + 1 < ends.size(); ++piece) {
    const double a = ends[piece], length = ends[piece + 1] - a;
    // A piece of exactly n + 1/2 spacings up to rounding takes the finer lattice, n + 1 cells.
    const long long n = std::max(1LL, static_cast<long long>(std::floor(length / dx + 0.5 + 1e-9)));
    const double w = length / double(n);
    for (long long i = 0; i < n; ++i) {
      out.centre.push_back(a + (double(i) + 0.5) * w);
      out.width.push_back(w);
    }
  }
  return out;
}

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

// The particles of one body before clipping, each with its cell (widths along x, y, z), and how the
// lattice was fitted.
struct BodyLattice {
  std::vector<Vec3d> pts;
  std::vector<Vec3d> cell;  // m, widths of each particle's lattice cell along x, y, z
  bool round_fitted = true; // false: no round-lattice spacing within 10 % of dx fits; dx kept
};

// A body from a surface mesh: the box lattice of its bounding box (fill_axis, split at the symmetry planes
// inside it), kept where the point lies inside the surface. A symmetry plane that cuts the mesh must be a
// plane of symmetry of the mesh itself, since the solver mirrors the model across it: the mirror image of
// every kept point must be inside too (up to 0.5 % of them, points within rounding of the surface).
BodyLattice mesh_lattice(const CaseSpec& spec, std::size_t k, double dx, const std::string& thin_hint) {
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
  for (int a = 0; a < 3; ++a) axes[a] = fill_axis(lo[a], hi[a], cuts_inside(spec, a, lo[a], hi[a], dx), dx);
  BodyLattice out;
  for (std::size_t iz = 0; iz < axes[2].centre.size(); ++iz)
    for (std::size_t iy = 0; iy < axes[1].centre.size(); ++iy)
      for (std::size_t ix = 0; ix < axes[0].centre.size(); ++ix) {
        const Vec3d p{axes[0].centre[ix], axes[1].centre[iy], axes[2].centre[iz]};
        if (!b.mesh->inside(p)) continue;
        out.pts.push_back(p);
        out.cell.push_back({axes[0].width[ix], axes[1].width[iy], axes[2].width[iz]});
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
BodyLattice lattice(const CaseSpec& spec, std::size_t k, double dx) {
  const BodySpec& b = spec.bodies[k];
  const std::string key = body_key(k);
  const std::string thin_hint = " at spacing " + format_quantity(dx, Dimension::Length) +
                                ": a body needs at least two particles across; make it at least " +
                                format_quantity(2 * dx, Dimension::Length) + " or refine numerics.spacing";
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
      axes[a] = fill_axis(b.box_min[a], b.box_max[a], cuts_inside(spec, a, b.box_min[a], b.box_max[a], dx), dx);
    out.pts.reserve(axes[0].centre.size() * axes[1].centre.size() * axes[2].centre.size());
    for (std::size_t iz = 0; iz < axes[2].centre.size(); ++iz)
      for (std::size_t iy = 0; iy < axes[1].centre.size(); ++iy)
        for (std::size_t ix = 0; ix < axes[0].centre.size(); ++ix) {
          out.pts.push_back({axes[0].centre[ix], axes[1].centre[iy], axes[2].centre[iz]});
          out.cell.push_back({axes[0].width[ix], axes[1].width[iy], axes[2].width[iz]});
        }
    return out;
  }

  if (b.shape == Shape::Mesh) return mesh_lattice(spec, k, dx, thin_hint);

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
  const AxisCells layers = fill_axis(base, base + b.length, cuts_inside(spec, b.axis, base, base + b.length, dx), dx);
  double s = fit_round_spacing(b.radius, dx, 2);
  out.round_fitted = s > 0;
  if (!out.round_fitted) s = dx;
  const double q = round_q(b.radius, s);
  std::vector<std::pair<double, double>> section;
  const long long mi = static_cast<long long>(std::ceil(b.radius / s)) + 1;
  for (long long j = -mi; j < mi; ++j)
    for (long long i = -mi; i < mi; ++i)
      if (in_round(q, fold(i), fold(j), 0, 2)) section.emplace_back((double(i) + 0.5) * s, (double(j) + 0.5) * s);
  out.pts.reserve(layers.centre.size() * section.size());
  for (std::size_t kk = 0; kk < layers.centre.size(); ++kk) {
    // A layer of the nose keeps the points of the cross-section within the profile at its centre (the
    // midpoint rule for the nose's volume); 1e-12 keeps points exactly on it.
    const double keep = section_radius(b, layers.centre[kk] - base);
    const double keep2 = sqr(keep) * (1 + 1e-12);
    for (const auto& [ou, ov] : section) {
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
    }
  }
  return out;
}

// Two bodies overlap when a particle of one lies inside the other's shape, or when particles of the two
// come closer than half a spacing (which catches lattices that interleave at a shared face). Only the
// particles in the intersection of the two bodies' bounding boxes are looked at, hashed on a grid of
// cells dx/2 wide, so the check costs about the size of the contact zone, not N^2.
void check_overlaps(const CaseSpec& spec, const ParticleSet& ps, const std::vector<std::size_t>& first,
                    const std::vector<Box3>& bounds, double dx) {
  const std::size_t nb = spec.bodies.size();
  const double eps = 1e-9 * dx;
  for (std::size_t a = 0; a < nb; ++a)
    for (std::size_t b = 0; b < nb; ++b) {
      if (a == b) continue;
      const Box3 sb = shape_bounds(spec.bodies[b]);
      if (!bounds[a].intersects(sb)) continue;
      for (std::size_t i = first[a]; i < first[a + 1]; ++i)
        if (sb.contains(ps.pos[i]) && strictly_inside(spec.bodies[b], ps.pos[i], eps)) {
          const std::size_t later = std::max(a, b), earlier = std::min(a, b);
          throw CaseError(spec.source_file, spec.bodies[later].line, body_key(later),
                          body_name(spec, later) + " overlaps " + body_label(spec, earlier) + ": the particle of \"" +
                              spec.bodies[a].name + "\" at " + point(ps.pos[i]) + " lies inside \"" +
                              spec.bodies[b].name + "\"; bodies must not overlap");
        }
    }

  const double min_d = 0.5 * dx, cell = 0.5 * dx;
  for (std::size_t a = 0; a < nb; ++a)
    for (std::size_t b = a + 1; b < nb; ++b) {
      const Box3 ga = bounds[a].grown(min_d), gb = bounds[b].grown(min_d);
      if (!ga.intersects(gb)) continue;
      Box3 zone;
      for (int c = 0; c < 3; ++c) zone.lo[c] = std::max(ga.lo[c], gb.lo[c]), zone.hi[c] = std::min(ga.hi[c], gb.hi[c]);
      auto cell_of = [&](const Vec3d& p, int c) { return static_cast<long long>(std::floor((p[c] - zone.lo[c]) / cell)); };
      auto key = [](long long x, long long y, long long z) {
        // Spatial hash of the cell indices (neighbour indices may be -1; the cast wraps consistently).
        // Collisions only cost time: distances are checked exactly.
        return (static_cast<unsigned long long>(x) * 73856093ull) ^ (static_cast<unsigned long long>(y) * 19349663ull) ^
               (static_cast<unsigned long long>(z) * 83492791ull);
      };
      std::unordered_map<unsigned long long, std::vector<std::size_t>> grid;
      for (std::size_t j = first[a]; j < first[a + 1]; ++j)
        if (zone.contains(ps.pos[j])) grid[key(cell_of(ps.pos[j], 0), cell_of(ps.pos[j], 1), cell_of(ps.pos[j], 2))].push_back(j);
      if (grid.empty()) continue;
      for (std::size_t i = first[b]; i < first[b + 1]; ++i) {
        const Vec3d& p = ps.pos[i];
        if (!zone.contains(p)) continue;
        const long long cx = cell_of(p, 0), cy = cell_of(p, 1), cz = cell_of(p, 2);
        for (long long x = cx - 1; x <= cx + 1; ++x)
          for (long long y = cy - 1; y <= cy + 1; ++y)
            for (long long z = cz - 1; z <= cz + 1; ++z) {
              const auto it = grid.find(key(x, y, z));
              if (it == grid.end()) continue;
              for (const std::size_t j : it->second) {
                const double d = norm(p - ps.pos[j]);
                if (d < min_d - eps)
                  throw CaseError(spec.source_file, spec.bodies[b].line, body_key(b),
                                  body_name(spec, b) + " overlaps " + body_label(spec, a) + ": its particle at " +
                                      point(p) + " is " + format_quantity(d, Dimension::Length) + " from one of \"" +
                                      spec.bodies[a].name + "\" at " + point(ps.pos[j]) +
                                      ", closer than half the spacing (" + format_quantity(min_d, Dimension::Length) +
                                      "); move the bodies apart");
              }
            }
      }
    }
}

// The model lies on one side of every symmetry plane (two planes on one axis bound a channel); the
// solver mirrors the particles near the plane to the other side. For each plane the side is decided
// from the bodies: a body whose particles all lie on one side decides it (the first such body in file
// order; a body wholly on the other side is an error); when every body reaches across the plane, it is
// the side holding more of their particles, the positive side on a tie. Then every body keeps only its
// particles on the model side of every plane, in lattice order, so a cylinder whose axis lies in two
// planes becomes an exact quarter. A kept particle closer than dx/4 to a plane (one on the plane
// included) would lie closer than dx/2 to its own mirror image, the overlap rule between bodies.
// Returns the model side of each plane (+1: axis > position, -1: below), indexed like spec.symmetry.
std::vector<int> clip_to_symmetry(const CaseSpec& spec, std::vector<BodyLattice>& lattices, double dx) {
  const double eps = 1e-9 * dx;
  const std::size_t nb = spec.bodies.size();
  std::vector<int> side(spec.symmetry.size(), 0);
  auto where = [&](std::size_t s) {
    const SymmetryPlaneSpec& plane = spec.symmetry[s];
    return std::string(1, axis_name(plane.axis)) + " = " + format_quantity(plane.position, Dimension::Length) +
           " (" + plane_key(spec, s) + ")";
  };
  for (std::size_t s = 0; s < spec.symmetry.size(); ++s) {
    const SymmetryPlaneSpec& plane = spec.symmetry[s];
    const int a = plane.axis;
    if (a < 0 || a > 2)
      throw CaseError(spec.source_file, plane.line, plane_key(spec, s) + ".axis",
                      "must be x, y or z");
    std::size_t first_body = nb;  // the first body wholly on one side decides the side
    std::size_t plus = 0, minus = 0;  // particles on either side, for when every body reaches across
    for (std::size_t k = 0; k < nb; ++k) {
      std::size_t above = 0, below = 0;
      const std::vector<Vec3d>& pts = lattices[k].pts;
      for (const Vec3d& p : pts) {
        if (p[a] > plane.position + eps) ++above;
        if (p[a] < plane.position - eps) ++below;
      }
      plus += above;
      minus += below;
      const int this_side = above == pts.size() ? 1 : (below == pts.size() ? -1 : 0);
      if (plane.wall && this_side == 0 && !pts.empty())
        throw CaseError(spec.source_file, spec.bodies[k].line, body_key(k),
                        body_name(spec, k) + " reaches through the wall " + where(s) +
                            "; a wall is not a plane of symmetry, so every body must lie wholly on one side of it "
                            "(move the body, or use [[boundaries.symmetry]] for a plane that cuts it)");
      if (this_side == 0 || pts.empty()) continue;
      if (first_body == nb) {
        first_body = k;
        side[s] = this_side;
      } else if (this_side != side[s]) {
        throw CaseError(spec.source_file, spec.bodies[k].line, body_key(k),
                        body_name(spec, k) + " lies on the other side of the symmetry plane " + where(s) + " from " +
                            body_label(spec, first_body) + "; the model must lie on one side of the plane");
      }
    }
    if (side[s] == 0) side[s] = plus >= minus ? 1 : -1;
  }
  if (spec.symmetry.empty()) return side;

  auto model_side = [&]() {
    std::string out;
    for (std::size_t s = 0; s < spec.symmetry.size(); ++s)
      out += (out.empty() ? "" : ", ") + std::string(1, axis_name(spec.symmetry[s].axis)) +
             (side[s] > 0 ? " > " : " < ") + format_quantity(spec.symmetry[s].position, Dimension::Length);
    return out;
  };
  const double min_d = 0.25 * dx;
  for (std::size_t k = 0; k < nb; ++k) {
    const BodyLattice& all = lattices[k];
    BodyLattice kept;
    kept.round_fitted = all.round_fitted;
    for (std::size_t i = 0; i < all.pts.size(); ++i) {
      const Vec3d& p = all.pts[i];
      bool keep = true;
      std::size_t closest = 0;
      double closest_d = 1e300;
      for (std::size_t s = 0; s < spec.symmetry.size(); ++s) {
        const double d = side[s] * (p[spec.symmetry[s].axis] - spec.symmetry[s].position);
        if (d < -eps) keep = false;
        if (d < closest_d) closest_d = d, closest = s;
      }
      if (!keep) continue;
      if (closest_d < min_d - eps)
        throw CaseError(spec.source_file, spec.bodies[k].line, body_key(k),
                        "the particle of " + body_name(spec, k) + " at " + point(p) + " is " +
                            format_quantity(std::max(closest_d, 0.0), Dimension::Length) + " from the symmetry plane " +
                            where(closest) + ", closer than half the spacing (" +
                            format_quantity(2 * min_d, Dimension::Length) +
                            ") to its own mirror image; the plane must lie halfway between two layers of the "
                            "body's lattice (for a cylinder cut by the plane: its axis in the plane; for a sphere: its centre)");
      kept.pts.push_back(p);
      kept.cell.push_back(all.cell[i]);
    }
    if (kept.pts.empty() && !all.pts.empty())
      throw CaseError(spec.source_file, spec.bodies[k].line, body_key(k),
                      body_name(spec, k) + " would be clipped to nothing: none of its particles lies on the model "
                                           "side of every symmetry plane (" + model_side() +
                          "); move it, or remove it from the model");
    lattices[k] = std::move(kept);
  }
  return side;
}

bool in_fixed_region(const FixedRegionSpec& r, const Vec3d& p, double eps) {
  if (r.kind == FixedRegionSpec::Kind::Box) {
    for (int a = 0; a < 3; ++a)
      if (p[a] < r.box_min[a] - eps || p[a] > r.box_max[a] + eps) return false;
    return true;
  }
  int u, v;
  cross_axes(r.axis, u, v);
  return sqr(p[u] - r.axis_point[u]) + sqr(p[v] - r.axis_point[v]) > sqr(r.radius);
}

void mark_fixed(const CaseSpec& spec, ParticleSet& ps, const std::vector<std::size_t>& first, double dx) {
  const double eps = 1e-9 * dx;
  for (std::size_t f = 0; f < spec.fixed.size(); ++f) {
    const FixedRegionSpec& r = spec.fixed[f];
    const std::string key = "boundaries.fixed[" + std::to_string(f) + "]";
    std::size_t selected = 0;
    bool any_body = false;
    Box3 candidates{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
    for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
      if (!r.body.empty() && r.body != spec.bodies[k].name) continue;
      any_body = true;
      for (std::size_t i = first[k]; i < first[k + 1]; ++i) {
        for (int a = 0; a < 3; ++a)
          candidates.lo[a] = std::min(candidates.lo[a], ps.pos[i][a]), candidates.hi[a] = std::max(candidates.hi[a], ps.pos[i][a]);
        if (in_fixed_region(r, ps.pos[i], eps)) {
          ps.fixed[i] = 1;
          ++selected;
        }
      }
    }
    if (!any_body) {
      std::string names;
      for (const BodySpec& b : spec.bodies) names += (names.empty() ? "\"" : ", \"") + b.name + "\"";
      throw CaseError(spec.source_file, r.line, key + ".body", "no body named \"" + r.body + "\"; bodies: " + names);
    }
    if (selected == 0) {
      const std::string region =
          r.kind == FixedRegionSpec::Kind::Box
              ? "the box from " + point(r.box_min) + " to " + point(r.box_max)
              : "the outside of the cylinder of radius " + format_quantity(r.radius, Dimension::Length) + " about the " +
                    std::string(1, axis_name(r.axis)) + " axis through " + point(r.axis_point);
      throw CaseError(spec.source_file, r.line, key,
                      "selects no particle: " + region + " holds none of the particles of " +
                          (r.body.empty() ? std::string("any body") : "\"" + r.body + "\"") + ", which lie from " +
                          point(candidates.lo) + " to " + point(candidates.hi));
    }
  }
}

// Contact pairs of a CaseSpec built in code may name their bodies without the indices: resolves them, and
// checks what the case file reader checks (two distinct existing bodies, each pair once).
void resolve_contacts(CaseSpec& spec) {
  const int nb = static_cast<int>(spec.bodies.size());
  for (std::size_t c = 0; c < spec.contacts.size(); ++c) {
    ContactSpec& contact = spec.contacts[c];
    const std::string key = "contacts[" + std::to_string(c) + "].bodies";
    auto resolve = [&](int& index, std::string& name) {
      if (index >= 0 && index < nb) {
        name = spec.bodies[index].name;
        return;
      }
      for (int k = 0; k < nb; ++k)
        if (spec.bodies[k].name == name) {
          index = k;
          return;
        }
      std::string names;
      for (const BodySpec& b : spec.bodies) names += (names.empty() ? "\"" : ", \"") + b.name + "\"";
      throw CaseError(spec.source_file, contact.line, key, "no body named \"" + name + "\"; bodies: " + names);
    };
    resolve(contact.index_a, contact.body_a);
    resolve(contact.index_b, contact.body_b);
    if (contact.index_a == contact.index_b)
      throw CaseError(spec.source_file, contact.line, key,
                      "names \"" + contact.body_a + "\" twice; a contact is between two different bodies");
    for (std::size_t j = 0; j < c; ++j) {
      const ContactSpec& o = spec.contacts[j];
      if ((o.index_a == contact.index_a && o.index_b == contact.index_b) ||
          (o.index_a == contact.index_b && o.index_b == contact.index_a))
        throw CaseError(spec.source_file, contact.line, key,
                        "the pair \"" + contact.body_a + "\", \"" + contact.body_b + "\" is already listed in contacts[" +
                            std::to_string(j) + "]; each pair is given once");
    }
  }
}

}  // namespace

double shape_volume(const BodySpec& b) {
  if (b.shape == Shape::Box)
    return (b.box_max.x - b.box_min.x) * (b.box_max.y - b.box_min.y) * (b.box_max.z - b.box_min.z);
  if (b.shape == Shape::Sphere) return 4.0 / 3.0 * Constants<double>::pi * b.radius * b.radius * b.radius;
  if (b.shape == Shape::Mesh) return b.mesh->volume();
  return Constants<double>::pi * sqr(b.radius) * (b.length - b.nose_length) + nose_volume(b);
}

namespace {

std::string percent(double ratio_minus_one) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.2f %%", std::abs(ratio_minus_one) < 1e-12 ? 0.0 : 100 * ratio_minus_one);
  return text;
}

// What BodyInfo says of body k's geometry: its mass and sizes as specified and as generated, for the
// whole body (along an axis on which a symmetry plane cuts the shape, the model's cells reach from the
// plane and the whole body is their mirror image too), the lattice's spacing and stretch, and warnings
// when the generated body differs from the specified one by more than 1 % or half a spacing in a size,
// 0.1 % in mass, or when the lattice is stretched by more than 5 % to fit it.
void describe_geometry(const CaseSpec& spec, std::size_t k, const BodyLattice& lat, const std::vector<int>& side,
                       double dx, double rho0, double model_mass, double model_cells, double scale, BodyInfo& info) {
  const BodySpec& b = spec.bodies[k];
  const double copies = symmetry_multiplicity(spec, static_cast<int>(k));
  info.specified_mass = rho0 * shape_volume(b);
  info.generated_mass = copies * model_mass;
  info.mass_scale = scale;

  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300}, width{0, 0, 0};
  double stretch = 0;
  for (std::size_t i = 0; i < lat.pts.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], lat.pts[i][a] - 0.5 * lat.cell[i][a]);
      hi[a] = std::max(hi[a], lat.pts[i][a] + 0.5 * lat.cell[i][a]);
      width[a] += lat.cell[i][a];
      stretch = std::max(stretch, std::abs(lat.cell[i][a] / dx - 1));
    }
  const Box3 shape = shape_bounds(b);
  for (std::size_t s = 0; s < spec.symmetry.size(); ++s) {
    const int a = spec.symmetry[s].axis;
    const double plane = spec.symmetry[s].position;
    if (!(plane > shape.lo[a] && plane < shape.hi[a])) continue;
    if (side[s] > 0) lo[a] = 2 * plane - hi[a];
    else hi[a] = 2 * plane - lo[a];
  }
  const Vec3d extent = hi - lo;
  info.lattice_spacing = width * (1.0 / double(lat.pts.size()));
  info.max_stretch = stretch;

  const double cells = copies * model_cells;  // m^3, the whole body's lattice cells
  if (b.shape == Shape::Box) {
    for (int a = 0; a < 3; ++a)
      info.sizes.push_back({std::string(1, axis_name(a)), b.box_max[a] - b.box_min[a], extent[a]});
  } else if (b.shape == Shape::Mesh) {
    for (int a = 0; a < 3; ++a)
      info.sizes.push_back({std::string(1, axis_name(a)), b.mesh->upper()[a] - b.mesh->lower()[a], extent[a]});
  } else if (b.shape == Shape::Cylinder) {
    int u, v;
    cross_axes(b.axis, u, v);
    for (const Vec3d& q : lat.pts)
      info.outer_centre_radius = std::max(info.outer_centre_radius, std::hypot(q[u] - b.base[u], q[v] - b.base[v]));
    info.sizes.push_back({"length", b.length, extent[b.axis]});
    // The diameter of the circle whose area is the lattice's widest layer (a layer of the shank), the
    // model's layer mirrored by the symmetry planes along the cross-section axes.
    std::map<double, double> layer_area;  // m^2, by the layer's centre on the axis
    for (std::size_t i = 0; i < lat.pts.size(); ++i) layer_area[lat.pts[i][b.axis]] += lat.cell[i][u] * lat.cell[i][v];
    double widest = 0;
    for (const auto& [centre, area] : layer_area) widest = std::max(widest, area);
    double section_copies = 1;
    for (const SymmetryPlaneSpec& plane : spec.symmetry)
      if ((plane.axis == u || plane.axis == v) && plane.position > shape.lo[plane.axis] && plane.position < shape.hi[plane.axis])
        section_copies *= 2;
    info.sizes.push_back({"diameter", 2 * b.radius, 2 * std::sqrt(section_copies * widest / Constants<double>::pi)});
  } else {
    info.sizes.push_back({"diameter", 2 * b.radius, 2 * std::cbrt(3 * cells / (4 * Constants<double>::pi))});
  }

  for (const BodySize& size : info.sizes) {
    const double diff = size.generated - size.specified;
    if (std::abs(diff) > 0.01 * size.specified || std::abs(diff) > 0.5 * dx)
      info.warnings.push_back("its " + size.name + " is " + format_quantity(size.generated, Dimension::Length) +
                              " against " + format_quantity(size.specified, Dimension::Length) + " specified (" +
                              percent(size.generated / size.specified - 1) +
                              "); a finer numerics.spacing fits the lattice to it more closely");
  }
  if (std::abs(info.generated_mass / info.specified_mass - 1) > 1e-3)
    info.warnings.push_back("its mass is " + format_quantity(info.generated_mass, Dimension::Mass) + " against rho0 V = " +
                            format_quantity(info.specified_mass, Dimension::Mass) + " (" +
                            percent(info.generated_mass / info.specified_mass - 1) +
                            "): a symmetry plane cuts it off its centre, so the model mirrored is not the body as "
                            "specified; put the plane through the body's centre or axis");
  if (!lat.round_fitted)
    info.warnings.push_back("no round lattice within 10 % of the spacing holds exactly its " +
                            std::string(b.shape == Shape::Sphere ? "volume" : "cross-section") +
                            " (it is only a few spacings across); its particle masses are scaled by " +
                            format_quantity(scale, Dimension::Dimensionless) +
                            " to give it the mass rho0 V; a finer numerics.spacing avoids this");
  if (b.shape == Shape::Cylinder && b.nose != Nose::Flat && std::abs(scale - 1) > 0.01)
    info.warnings.push_back("the lattice's cells hold " + percent(1 / scale - 1) +
                            " of its volume with the nose; its particle masses are scaled by " +
                            format_quantity(scale, Dimension::Dimensionless) +
                            " to give it the mass rho0 V; a finer numerics.spacing resolves the nose better");
  if (b.shape == Shape::Mesh && std::abs(scale - 1) > 0.01)
    info.warnings.push_back("the lattice's cells inside the mesh miss its volume by " + percent(1 / scale - 1) +
                            "; its particle masses are scaled by " + format_quantity(scale, Dimension::Dimensionless) +
                            " to give it the mass rho0 V; a finer numerics.spacing follows the surface more closely");
  if (stretch > 0.05)
    info.warnings.push_back("its lattice is stretched by up to " + percent(stretch).substr(1) +
                            " against the spacing to fit its size (mean cells " +
                            format_quantity(info.lattice_spacing.x, Dimension::Length) + " x " +
                            format_quantity(info.lattice_spacing.y, Dimension::Length) + " x " +
                            format_quantity(info.lattice_spacing.z, Dimension::Length) +
                            "); a spacing that divides its sizes, or a finer one, keeps the cells nearer cubic");
}

}  // namespace

int symmetry_multiplicity(const CaseSpec& spec, int body) {
  const Box3 shape = shape_bounds(spec.bodies[static_cast<std::size_t>(body)]);
  int m = 1;
  for (const SymmetryPlaneSpec& plane : spec.symmetry)
    if (plane.position > shape.lo[plane.axis] && plane.position < shape.hi[plane.axis]) m *= 2;
  return m;
}

Scene build_scene(const CaseSpec& spec) {
  const double dx = spec.numerics.spacing;
  if (!(dx > 0) || !std::isfinite(dx))
    throw CaseError(spec.source_file, spec.numerics.spacing_line, "numerics.spacing", "must be greater than zero");
  if (spec.bodies.empty()) throw CaseError(spec.source_file, 0, "bodies", "the case has no bodies");

  Scene scene;
  scene.spec = spec;
  // A fracture-energy criterion fails at Gamma / (k h0): its critical work is set here from the case's
  // initial smoothing length h0 = h_factor x spacing (damage.hpp, fracture_energy_critical_work).
  for (const MaterialSpec& m : spec.materials) {
    MaterialParams<double> params = m.params;
    if (params.damage.kind == DamageKind::FractureEnergy)
      params.damage.critical_plastic_work =
          fracture_energy_critical_work(params.damage, spec.numerics.h_factor * spec.numerics.spacing);
    scene.materials.push_back(params);
  }

  // Lattices first, so that the symmetry planes can be decided from every body and clip them.
  std::vector<BodyLattice> lattices(spec.bodies.size());
  std::vector<double> mass_scale(spec.bodies.size(), 1.0);
  for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
    BodySpec& b = scene.spec.bodies[k];
    // A CaseSpec built in code may name its material without the index.
    if (b.material_index < 0 || b.material_index >= static_cast<int>(spec.materials.size())) {
      const auto it = std::find_if(spec.materials.begin(), spec.materials.end(),
                                   [&](const MaterialSpec& m) { return m.name == b.material; });
      if (it == spec.materials.end())
        throw CaseError(spec.source_file, b.line, body_key(k) + ".material", "no material named \"" + b.material + "\"");
      b.material_index = static_cast<int>(it - spec.materials.begin());
    }
    const MaterialSpec& m = spec.materials[b.material_index];
    if (!(m.params.eos.rho0 > 0))
      throw CaseError(spec.source_file, m.line, "materials." + m.name + ".density", "must be greater than zero");
    lattices[k] = lattice(spec, k, dx);
    if (lattices[k].pts.empty())
      throw CaseError(spec.source_file, b.line, body_key(k), body_name(spec, k) + " holds no particle at this spacing");
    // The whole lattice's cells against the shape: 1 up to rounding where the lattice fits; otherwise the
    // masses are scaled so that the body still has the mass rho0 V.
    double cells = 0;
    for (const Vec3d& c : lattices[k].cell) cells += c.x * c.y * c.z;
    mass_scale[k] = shape_volume(b) / cells;
  }
  const std::vector<int> side = clip_to_symmetry(scene.spec, lattices, dx);

  ParticleSet& ps = scene.particles;
  std::vector<std::size_t> first{0};  // particles of body k are [first[k], first[k+1])
  std::vector<Box3> bounds;            // bounding boxes of the bodies' particles
  const double h = spec.numerics.h_factor * dx;
  for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
    const BodySpec& b = scene.spec.bodies[k];
    const MaterialParams<double>& mat = spec.materials[b.material_index].params;
    const BodyLattice& lat = lattices[k];
    const std::size_t n0 = ps.size();
    ps.resize(n0 + lat.pts.size());
    Box3 box{lat.pts[0], lat.pts[0]};
    double model_mass = 0, model_cells = 0;
    for (std::size_t i = 0; i < lat.pts.size(); ++i) {
      const Vec3d& q = lat.pts[i];
      const Vec3d& c = lat.cell[i];
      const std::size_t p = n0 + i;
      ps.pos[p] = q;
      ps.vel[p] = b.velocity;
      ps.mass[p] = mat.eos.rho0 * c.x * c.y * c.z * mass_scale[k];  // rho0 times the particle's cell
      ps.rho[p] = mat.eos.rho0;
      ps.energy[p] = 0;
      ps.pressure[p] = 0;  // every EOS gives P = 0 at rho = rho0, e = 0
      ps.h[p] = h;
      ps.dev_stress[p] = Sym3d::zero();
      ps.plastic_strain[p] = 0;
      ps.plastic_work[p] = 0;
      ps.damage[p] = 0;
      ps.temperature[p] = mat.room_temperature;
      ps.bulking_pressure[p] = 0;
      ps.body[p] = static_cast<std::int32_t>(k);
      ps.material[p] = b.material_index;
      ps.fixed[p] = 0;
      model_mass += ps.mass[p];
      model_cells += c.x * c.y * c.z;
      for (int a = 0; a < 3; ++a) box.lo[a] = std::min(box.lo[a], q[a]), box.hi[a] = std::max(box.hi[a], q[a]);
    }
    first.push_back(ps.size());
    bounds.push_back(box);

    BodyInfo info;
    info.name = b.name;
    info.material = b.material_index;
    info.particle_count = lat.pts.size();  // after clipping by the symmetry planes
    info.initial_mass = model_mass;
    describe_geometry(scene.spec, k, lat, side, dx, mat.eos.rho0, model_mass, model_cells, mass_scale[k], info);
    scene.bodies.push_back(info);
  }
  if (ps.size() == 0) throw CaseError(spec.source_file, 0, "bodies", "the case holds no particle");

  check_overlaps(scene.spec, ps, first, bounds, dx);
  mark_fixed(scene.spec, ps, first, dx);
  resolve_contacts(scene.spec);
  return scene;
}

}  // namespace impactsph
