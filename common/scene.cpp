// Scene builder: fills each body of a CaseSpec with particles on a regular cubic lattice of spacing dx,
// clips bodies that reach across a symmetry plane to the model side of it (quarter and half models),
// then checks the geometry (overlaps, symmetry planes, fixed regions, contact pairs) and throws CaseError
// naming the body or boundary, with the line of its table in the case file, when it is impossible. Particles are stored body by body in file order, each body in
// lattice order (the first cross-section axis fastest, the third slowest), so the same case always gives
// the same particle numbering (design.md, "Deterministic").
//
// Lattices:
//   box:      points min + (i + 1/2) dx per axis, i < floor(extent/dx); an extent that is not a multiple
//             of dx leaves a gap of equal width at both faces (the lattice is centred in the box).
//   cylinder: layers at base + (k + 1/2) dx along the axis, k < round(length/dx); in each layer a square
//             lattice at offsets (i + 1/2) dx from the axis, kept where the distance to the axis is at
//             most the radius.
//   sphere:   a cubic lattice at offsets (i + 1/2) dx from the centre on every axis, kept where the
//             distance to the centre is at most the radius (x fastest, then y, then z).
// Every particle centre lies inside its shape.
// Each particle carries the mass rho0 dx^3 of its lattice cell (so a box that is a whole number of cells
// has exactly the mass rho0 V), density rho0, zero energy, stress and damage, and h = h_factor dx.
#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/errors.hpp"
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

// The shape's own bounding box (not the particles').
Box3 shape_bounds(const BodySpec& b) {
  if (b.shape == Shape::Box) return {b.box_min, b.box_max};
  if (b.shape == Shape::Sphere) return Box3{b.center, b.center}.grown(b.radius);
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
  const double t = p[b.axis] - b.base[b.axis];
  if (!(t > eps && t < b.length - eps)) return false;
  int u, v;
  cross_axes(b.axis, u, v);
  const double r2 = sqr(p[u] - b.base[u]) + sqr(p[v] - b.base[v]);
  const double rin = b.radius - eps;
  return rin > 0 && r2 < rin * rin;
}

// Lattice points of one body; throws when the body is thinner than two particles.
std::vector<Vec3d> lattice(const CaseSpec& spec, std::size_t k, double dx) {
  const BodySpec& b = spec.bodies[k];
  const std::string key = body_key(k);
  const std::string thin_hint = " at spacing " + format_quantity(dx, Dimension::Length) +
                                ": a body needs at least two particles across; make it at least " +
                                format_quantity(2 * dx, Dimension::Length) + " or refine numerics.spacing";
  std::vector<Vec3d> pts;
  if (b.shape == Shape::Box) {
    long long n[3];
    double start[3];
    for (int a = 0; a < 3; ++a) {
      const double extent = b.box_max[a] - b.box_min[a];
      if (!(extent > 0))
        throw CaseError(spec.source_file, b.line, key, "max." + std::string(1, axis_name(a)) + " must be greater than min");
      // 1e-9: an extent that is a whole number of cells up to rounding keeps its last layer.
      const double cells = std::floor(extent / dx + 1e-9);
      if (cells < 2)
        throw CaseError(spec.source_file, b.line, key,
                        body_name(spec, k) + " is " + format_quantity(extent, Dimension::Length) + " thick along " +
                            axis_name(a) + thin_hint);
      if (cells > kMaxParticles)
        throw CaseError(spec.source_file, b.line, key, "too many particles at this spacing; use a coarser numerics.spacing");
      n[a] = static_cast<long long>(cells);
      start[a] = b.box_min[a] + 0.5 * (extent - cells * dx) + 0.5 * dx;
    }
    const double count = double(n[0]) * double(n[1]) * double(n[2]);
    if (count > kMaxParticles)
      throw CaseError(spec.source_file, b.line, key,
                      body_name(spec, k) + " would hold " + format_quantity(count, Dimension::Dimensionless) +
                          " particles at spacing " + format_quantity(dx, Dimension::Length) +
                          " (at most 1e9); use a coarser numerics.spacing");
    pts.reserve(static_cast<std::size_t>(count));
    for (long long iz = 0; iz < n[2]; ++iz)
      for (long long iy = 0; iy < n[1]; ++iy)
        for (long long ix = 0; ix < n[0]; ++ix)
          pts.push_back({start[0] + double(ix) * dx, start[1] + double(iy) * dx, start[2] + double(iz) * dx});
    return pts;
  }

  if (b.shape == Shape::Sphere) {
    // 1e-9: a diameter of exactly two cells up to rounding is accepted (it holds the 8 points at
    // (+-1/2, +-1/2, +-1/2) dx).
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
    // Offsets (i + 1/2) dx from the centre on every axis, as the cross-section of a cylinder: a plane
    // through the centre lies halfway between two lattice layers, so two or three planes through it
    // cut an exact quarter or eighth. The same relative tolerance keeps points exactly on the sphere.
    const long long mi = static_cast<long long>(std::ceil(b.radius / dx));
    const double r2 = sqr(b.radius) * (1 + 1e-12);
    pts.reserve(static_cast<std::size_t>(estimate * 1.1) + 8);
    for (long long kz = -mi; kz < mi; ++kz)
      for (long long jy = -mi; jy < mi; ++jy)
        for (long long ix = -mi; ix < mi; ++ix) {
          const Vec3d o{(double(ix) + 0.5) * dx, (double(jy) + 0.5) * dx, (double(kz) + 0.5) * dx};
          if (norm2(o) <= r2) pts.push_back(b.center + o);
        }
    return pts;
  }

  // 1e-9: a length or diameter of exactly two cells up to rounding is accepted.
  if (b.length < 2 * dx * (1 - 1e-9))
    throw CaseError(spec.source_file, b.line, key,
                    body_name(spec, k) + " is " + format_quantity(b.length, Dimension::Length) + " long" + thin_hint);
  if (b.radius < dx * (1 - 1e-9))
    throw CaseError(spec.source_file, b.line, key,
                    body_name(spec, k) + " has a diameter of " + format_quantity(2 * b.radius, Dimension::Length) +
                        thin_hint);
  const double layers = std::round(b.length / dx);
  const double m = std::ceil(b.radius / dx);  // cross-section offsets (i + 1/2) dx for i in [-m, m)
  const double estimate = layers * Constants<double>::pi * sqr(b.radius / dx);
  if (estimate > kMaxParticles)
    throw CaseError(spec.source_file, b.line, key,
                    body_name(spec, k) + " would hold about " + format_quantity(estimate, Dimension::Dimensionless) +
                        " particles at spacing " + format_quantity(dx, Dimension::Length) +
                        " (at most 1e9); use a coarser numerics.spacing");
  int u, v;
  cross_axes(b.axis, u, v);
  // Relative tolerance so that points exactly on the circle (r a half-integer multiple of dx) are kept.
  const double r2 = sqr(b.radius) * (1 + 1e-12);
  std::vector<std::pair<double, double>> section;
  const long long mi = static_cast<long long>(m);
  for (long long j = -mi; j < mi; ++j)
    for (long long i = -mi; i < mi; ++i) {
      const double ou = (double(i) + 0.5) * dx, ov = (double(j) + 0.5) * dx;
      if (ou * ou + ov * ov <= r2) section.emplace_back(ou, ov);
    }
  pts.reserve(static_cast<std::size_t>(layers) * section.size());
  for (long long kk = 0; kk < static_cast<long long>(layers); ++kk)
    for (const auto& [ou, ov] : section) {
      Vec3d p = b.base;
      p[b.axis] += (double(kk) + 0.5) * dx;
      p[u] += ou;
      p[v] += ov;
      pts.push_back(p);
    }
  return pts;
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
void clip_to_symmetry(const CaseSpec& spec, std::vector<std::vector<Vec3d>>& pts, double dx) {
  const double eps = 1e-9 * dx;
  const std::size_t nb = spec.bodies.size();
  std::vector<int> side(spec.symmetry.size(), 0);
  auto where = [&](std::size_t s) {
    const SymmetryPlaneSpec& plane = spec.symmetry[s];
    return std::string(1, axis_name(plane.axis)) + " = " + format_quantity(plane.position, Dimension::Length) +
           " (boundaries.symmetry[" + std::to_string(s) + "])";
  };
  for (std::size_t s = 0; s < spec.symmetry.size(); ++s) {
    const SymmetryPlaneSpec& plane = spec.symmetry[s];
    const int a = plane.axis;
    if (a < 0 || a > 2)
      throw CaseError(spec.source_file, plane.line, "boundaries.symmetry[" + std::to_string(s) + "].axis",
                      "must be x, y or z");
    std::size_t first_body = nb;  // the first body wholly on one side decides the side
    std::size_t plus = 0, minus = 0;  // particles on either side, for when every body reaches across
    for (std::size_t k = 0; k < nb; ++k) {
      std::size_t above = 0, below = 0;
      for (const Vec3d& p : pts[k]) {
        if (p[a] > plane.position + eps) ++above;
        if (p[a] < plane.position - eps) ++below;
      }
      plus += above;
      minus += below;
      const int this_side = above == pts[k].size() ? 1 : (below == pts[k].size() ? -1 : 0);
      if (this_side == 0 || pts[k].empty()) continue;
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
  if (spec.symmetry.empty()) return;

  auto model_side = [&]() {
    std::string out;
    for (std::size_t s = 0; s < spec.symmetry.size(); ++s)
      out += (out.empty() ? "" : ", ") + std::string(1, axis_name(spec.symmetry[s].axis)) +
             (side[s] > 0 ? " > " : " < ") + format_quantity(spec.symmetry[s].position, Dimension::Length);
    return out;
  };
  const double min_d = 0.25 * dx;
  for (std::size_t k = 0; k < nb; ++k) {
    std::vector<Vec3d> kept;
    kept.reserve(pts[k].size());
    for (const Vec3d& p : pts[k]) {
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
      kept.push_back(p);
    }
    if (kept.empty() && !pts[k].empty())
      throw CaseError(spec.source_file, spec.bodies[k].line, body_key(k),
                      body_name(spec, k) + " would be clipped to nothing: none of its particles lies on the model "
                                           "side of every symmetry plane (" + model_side() +
                          "); move it, or remove it from the model");
    pts[k] = std::move(kept);
  }
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

Scene build_scene(const CaseSpec& spec) {
  const double dx = spec.numerics.spacing;
  if (!(dx > 0) || !std::isfinite(dx))
    throw CaseError(spec.source_file, spec.numerics.spacing_line, "numerics.spacing", "must be greater than zero");
  if (spec.bodies.empty()) throw CaseError(spec.source_file, 0, "bodies", "the case has no bodies");

  Scene scene;
  scene.spec = spec;
  for (const MaterialSpec& m : spec.materials) scene.materials.push_back(m.params);

  // Lattices first, so that the symmetry planes can be decided from every body and clip them.
  std::vector<std::vector<Vec3d>> pts(spec.bodies.size());
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
    pts[k] = lattice(spec, k, dx);
    if (pts[k].empty())
      throw CaseError(spec.source_file, b.line, body_key(k), body_name(spec, k) + " holds no particle at this spacing");
  }
  clip_to_symmetry(scene.spec, pts, dx);

  ParticleSet& ps = scene.particles;
  std::vector<std::size_t> first{0};  // particles of body k are [first[k], first[k+1])
  std::vector<Box3> bounds;            // bounding boxes of the bodies' particles
  const double h = spec.numerics.h_factor * dx;
  for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
    const BodySpec& b = scene.spec.bodies[k];
    const MaterialParams<double>& mat = spec.materials[b.material_index].params;
    const double mass = mat.eos.rho0 * dx * dx * dx;
    const std::size_t n0 = ps.size();
    ps.resize(n0 + pts[k].size());
    Box3 box{pts[k][0], pts[k][0]};
    for (std::size_t i = 0; i < pts[k].size(); ++i) {
      const Vec3d& q = pts[k][i];
      const std::size_t p = n0 + i;
      ps.pos[p] = q;
      ps.vel[p] = b.velocity;
      ps.mass[p] = mass;
      ps.rho[p] = mat.eos.rho0;
      ps.energy[p] = 0;
      ps.pressure[p] = 0;  // every EOS gives P = 0 at rho = rho0, e = 0
      ps.h[p] = h;
      ps.dev_stress[p] = Sym3d::zero();
      ps.plastic_strain[p] = 0;
      ps.damage[p] = 0;
      ps.temperature[p] = mat.room_temperature;
      ps.bulking_pressure[p] = 0;
      ps.body[p] = static_cast<std::int32_t>(k);
      ps.material[p] = b.material_index;
      ps.fixed[p] = 0;
      for (int a = 0; a < 3; ++a) box.lo[a] = std::min(box.lo[a], q[a]), box.hi[a] = std::max(box.hi[a], q[a]);
    }
    first.push_back(ps.size());
    bounds.push_back(box);

    BodyInfo info;
    info.name = b.name;
    info.material = b.material_index;
    info.particle_count = pts[k].size();  // after clipping by the symmetry planes
    info.initial_mass = mass * double(pts[k].size());
    scene.bodies.push_back(info);
  }
  if (ps.size() == 0) throw CaseError(spec.source_file, 0, "bodies", "the case holds no particle");

  check_overlaps(scene.spec, ps, first, bounds, dx);
  mark_fixed(scene.spec, ps, first, dx);
  resolve_contacts(scene.spec);
  return scene;
}

}  // namespace impactsph
