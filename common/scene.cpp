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
// and h = h_factor dx. A body with a coarse region ([bodies.coarse], two_resolution_lattice) is the same
// lattice with its complete blocks of ratio^3 cells in the region merged into one; its particles' h
// follows their own spacing, and its coarse part takes a copy of the material (Scene::materials).
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
#include "common/scene_parts.hpp"
#include "common/units.hpp"

namespace impactsph {

using namespace scene_detail;

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

  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300}, width{0, 0, 0}, coarse_width{0, 0, 0};
  double stretch = 0;
  std::size_t coarse = 0;
  for (std::size_t i = 0; i < lat.pts.size(); ++i) {
    const bool is_coarse = lat.spacing[i] > dx;
    coarse += is_coarse ? 1 : 0;
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], lat.pts[i][a] - 0.5 * lat.cell[i][a]);
      hi[a] = std::max(hi[a], lat.pts[i][a] + 0.5 * lat.cell[i][a]);
      (is_coarse ? coarse_width : width)[a] += lat.cell[i][a];
      stretch = std::max(stretch, std::abs(lat.cell[i][a] / lat.spacing[i] - 1));
    }
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
  info.lattice_spacing = width * (1.0 / double(lat.pts.size() - coarse));
  info.coarse_particle_count = coarse;
  if (coarse > 0) info.coarse_lattice_spacing = coarse_width * (1.0 / double(coarse));
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
    // model's layer mirrored by the symmetry planes along the cross-section axes. A layer's area is that of
    // every cell it passes through (the fine and the coarse cells of a two-resolution body).
    std::map<double, double> layer_area;  // m^2, by the layer's centre on the axis
    if (coarse == 0) {
      for (std::size_t i = 0; i < lat.pts.size(); ++i) layer_area[lat.pts[i][b.axis]] += lat.cell[i][u] * lat.cell[i][v];
    } else {
      for (std::size_t i = 0; i < lat.pts.size(); ++i) layer_area[lat.pts[i][b.axis]] = 0;
      // A cell spans [lo, hi) along the axis, its faces moved by rounding's worth so that a layer on a face
      // counts the cell on one side only.
      for (auto& [centre, area] : layer_area)
        for (std::size_t i = 0; i < lat.pts.size(); ++i) {
          const double w = lat.cell[i][b.axis], eps = 1e-9 * w;
          const double lo = lat.pts[i][b.axis] - 0.5 * w - eps, hi = lat.pts[i][b.axis] + 0.5 * w - eps;
          if (centre >= lo && centre < hi) area += lat.cell[i][u] * lat.cell[i][v];
        }
    }
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
  // Damage constants that follow from the case's initial smoothing length h0 = h_factor x spacing (a
  // fracture-energy criterion fails at Gamma / (k h0), common/models/damage_fracture_energy.hpp).
  for (const MaterialSpec& m : spec.materials) {
    MaterialParams<double> params = m.params;
    set_damage_smoothing_length(params.damage, spec.numerics.h_factor * spec.numerics.spacing);
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
    if (b.coarse_ratio > 1) {
      lattices[k] = two_resolution_lattice(scene.spec, k, dx);
    } else {
      lattices[k] = lattice(scene.spec, k, dx);
      lattices[k].spacing.assign(lattices[k].pts.size(), dx);
    }
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
  for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
    const BodySpec& b = scene.spec.bodies[k];
    const MaterialParams<double>& mat = spec.materials[b.material_index].params;
    const BodyLattice& lat = lattices[k];
    // The coarse part of a two-resolution body takes a copy of its material whose constants follow its
    // smoothing length (the fracture energy's critical work, common/models/damage_fracture_energy.hpp).
    int coarse_material = b.material_index;
    if (b.coarse_ratio > 1) {
      MaterialParams<double> params = mat;
      set_damage_smoothing_length(params.damage, spec.numerics.h_factor * b.coarse_ratio * dx);
      coarse_material = static_cast<int>(scene.materials.size());
      scene.materials.push_back(params);
    }
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
      ps.h[p] = spec.numerics.h_factor * lat.spacing[i];
      ps.dev_stress[p] = Sym3d::zero();
      ps.plastic_strain[p] = 0;
      ps.plastic_work[p] = 0;
      ps.damage[p] = 0;
      ps.temperature[p] = mat.room_temperature;
      ps.bulking_pressure[p] = 0;
      ps.body[p] = static_cast<std::int32_t>(k);
      ps.material[p] = lat.spacing[i] > dx ? coarse_material : b.material_index;
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
