// The scene builder's checks of a case's geometry: bodies that overlap, bodies across symmetry planes
// (clipped to the model side), fixed regions and contact pairs, each failure a CaseError naming the body or
// boundary and its line (common/scene_parts.hpp).
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
// planes becomes an exact quarter. A kept particle closer than a quarter of its spacing to a plane (one on
// the plane included) would lie closer than half of it to its own mirror image, the overlap rule between bodies.
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
      const double min_d = 0.25 * all.spacing[i];
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
      kept.spacing.push_back(all.spacing[i]);
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

}  // namespace impactsph::scene_detail
