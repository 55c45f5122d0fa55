// Scene builder: fills each body of a CaseSpec with particles on a regular cubic lattice of spacing dx,
// then checks the geometry (overlaps, symmetry planes, fixed regions) and throws CaseError naming the
// body or boundary when it is impossible. Particles are stored body by body in file order, each body in
// lattice order (the first cross-section axis fastest, the third slowest), so the same case always gives
// the same particle numbering (design.md, "Deterministic").
//
// Lattices:
//   box:      points min + (i + 1/2) dx per axis, i < floor(extent/dx); an extent that is not a multiple
//             of dx leaves a gap of equal width at both faces (the lattice is centred in the box).
//   cylinder: layers at base + (k + 1/2) dx along the axis, k < round(length/dx); in each layer a square
//             lattice at offsets (i + 1/2) dx from the axis, kept where the distance to the axis is at
//             most the radius. Every particle centre lies inside its shape.
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

// The model lies on one side of every symmetry plane (either side; two planes on one axis bound a
// channel); the solver mirrors the particles near the plane to the other side. A particle on the plane,
// a body across it, or bodies on both sides of it would overlap their own mirror images.
void check_symmetry(const CaseSpec& spec, const std::vector<std::size_t>& first,
                    const std::vector<Box3>& bounds, double dx) {
  const double eps = 1e-9 * dx;
  for (std::size_t s = 0; s < spec.symmetry.size(); ++s) {
    const SymmetryPlaneSpec& plane = spec.symmetry[s];
    const int a = plane.axis;
    if (a < 0 || a > 2)
      throw CaseError(spec.source_file, 0, "boundaries.symmetry[" + std::to_string(s) + "].axis",
                      "must be x, y or z");
    const std::string axis(1, axis_name(a));
    const std::string where = axis + " = " + format_quantity(plane.position, Dimension::Length) +
                              " (boundaries.symmetry[" + std::to_string(s) + "])";
    std::size_t first_body = spec.bodies.size();  // the first body with particles decides the side
    int side = 0;
    for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
      if (first[k] == first[k + 1]) continue;
      const double lo = bounds[k].lo[a], hi = bounds[k].hi[a];
      const int this_side = lo > plane.position + eps ? 1 : (hi < plane.position - eps ? -1 : 0);
      if (this_side == 0)
        throw CaseError(spec.source_file, 0, body_key(k),
                        body_name(spec, k) + " reaches across the symmetry plane " + where + ": its particles span " +
                            axis + " from " + format_quantity(lo, Dimension::Length) + " to " +
                            format_quantity(hi, Dimension::Length) +
                            "; the model must lie on one side of the plane (its mirror image is the other side)");
      if (first_body == spec.bodies.size()) {
        first_body = k;
        side = this_side;
      } else if (this_side != side) {
        throw CaseError(spec.source_file, 0, body_key(k),
                        body_name(spec, k) + " lies on the other side of the symmetry plane " + where + " from " +
                            body_label(spec, first_body) + "; the model must lie on one side of the plane");
      }
    }
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
      throw CaseError(spec.source_file, 0, key + ".body", "no body named \"" + r.body + "\"; bodies: " + names);
    }
    if (selected == 0) {
      const std::string region =
          r.kind == FixedRegionSpec::Kind::Box
              ? "the box from " + point(r.box_min) + " to " + point(r.box_max)
              : "the outside of the cylinder of radius " + format_quantity(r.radius, Dimension::Length) + " about the " +
                    std::string(1, axis_name(r.axis)) + " axis through " + point(r.axis_point);
      throw CaseError(spec.source_file, 0, key,
                      "selects no particle: " + region + " holds none of the particles of " +
                          (r.body.empty() ? std::string("any body") : "\"" + r.body + "\"") + ", which lie from " +
                          point(candidates.lo) + " to " + point(candidates.hi));
    }
  }
}

}  // namespace

Scene build_scene(const CaseSpec& spec) {
  const double dx = spec.numerics.spacing;
  if (!(dx > 0) || !std::isfinite(dx))
    throw CaseError(spec.source_file, 0, "numerics.spacing", "must be greater than zero");
  if (spec.bodies.empty()) throw CaseError(spec.source_file, 0, "bodies", "the case has no bodies");

  Scene scene;
  scene.spec = spec;
  for (const MaterialSpec& m : spec.materials) scene.materials.push_back(m.params);

  ParticleSet& ps = scene.particles;
  std::vector<std::size_t> first{0};  // particles of body k are [first[k], first[k+1])
  std::vector<Box3> bounds;            // bounding boxes of the bodies' particles
  const double h = spec.numerics.h_factor * dx;
  for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
    BodySpec& b = scene.spec.bodies[k];
    // A CaseSpec built in code may name its material without the index.
    if (b.material_index < 0 || b.material_index >= static_cast<int>(spec.materials.size())) {
      const auto it = std::find_if(spec.materials.begin(), spec.materials.end(),
                                   [&](const MaterialSpec& m) { return m.name == b.material; });
      if (it == spec.materials.end())
        throw CaseError(spec.source_file, 0, body_key(k) + ".material", "no material named \"" + b.material + "\"");
      b.material_index = static_cast<int>(it - spec.materials.begin());
    }
    const MaterialParams<double>& mat = spec.materials[b.material_index].params;
    if (!(mat.eos.rho0 > 0))
      throw CaseError(spec.source_file, 0, "materials." + b.material + ".density", "must be greater than zero");

    const std::vector<Vec3d> pts = lattice(spec, k, dx);
    if (pts.empty())
      throw CaseError(spec.source_file, 0, body_key(k), body_name(spec, k) + " holds no particle at this spacing");
    const double mass = mat.eos.rho0 * dx * dx * dx;
    const std::size_t n0 = ps.size();
    ps.resize(n0 + pts.size());
    Box3 box{pts[0], pts[0]};
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const std::size_t p = n0 + i;
      ps.pos[p] = pts[i];
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
      ps.body[p] = static_cast<std::int32_t>(k);
      ps.material[p] = b.material_index;
      ps.fixed[p] = 0;
      for (int a = 0; a < 3; ++a) box.lo[a] = std::min(box.lo[a], pts[i][a]), box.hi[a] = std::max(box.hi[a], pts[i][a]);
    }
    first.push_back(ps.size());
    bounds.push_back(box);

    BodyInfo info;
    info.name = b.name;
    info.material = b.material_index;
    info.particle_count = pts.size();
    info.initial_mass = mass * double(pts.size());
    scene.bodies.push_back(info);
  }
  if (ps.size() == 0) throw CaseError(spec.source_file, 0, "bodies", "the case holds no particle");

  check_overlaps(scene.spec, ps, first, bounds, dx);
  check_symmetry(scene.spec, first, bounds, dx);
  mark_fixed(scene.spec, ps, first, dx);
  return scene;
}

}  // namespace impactsph
