// Scene: the particles of a case plus what the solvers need to advance them.
#pragma once
#include <string>
#include <vector>

#include "common/case_spec.hpp"

namespace impactsph {

// One size of a body as the case gives it and as its lattice makes it, both for the whole physical body
// (a body cut by symmetry planes is mirrored back to whole).
struct BodySize {
  std::string name;      // "x", "y", "z" (box extents), "length", "diameter"
  double specified = 0;  // m
  double generated = 0;  // m
};

struct BodyInfo {
  std::string name;
  int material = -1;
  std::size_t particle_count = 0;  // of the model, after clipping by the symmetry planes
  double initial_mass = 0;         // kg, of the model
  // The body as specified and as generated, whole (symmetry_multiplicity copies of the model).
  double specified_mass = 0;       // kg, rho0 V of the shape
  double generated_mass = 0;       // kg
  std::vector<BodySize> sizes;     // box: x, y, z; cylinder: length, diameter; sphere: diameter
  Vec3d lattice_spacing{0, 0, 0};  // m, mean width of the lattice cells along x, y, z (of the fine ones)
  // A body at two resolutions (BodySpec::coarse_ratio): its particles in the coarse region and their cells.
  std::size_t coarse_particle_count = 0;
  Vec3d coarse_lattice_spacing{0, 0, 0};  // m, mean width of the coarse cells along x, y, z
  double max_stretch = 0;          // largest |cell width / spacing - 1| over the axes (the lattice's stretch)
  double outer_centre_radius = 0;  // m, cylinder: largest distance of a particle centre from its axis, as built
  double mass_scale = 1;           // particle mass over rho0 x cell volume: 1 where the lattice fits the shape
  std::vector<std::string> warnings;  // what `impactsph check` and `run` print about the body's geometry
};

struct Scene {
  CaseSpec spec;
  ParticleSet particles;
  std::vector<BodyInfo> bodies;
  // Indexed like spec.materials, then one copy for the coarse part of each two-resolution body (its
  // constants that follow the smoothing length set for the coarse one; BodySpec::coarse_ratio).
  std::vector<MaterialParams<double>> materials;
};

// Builds the particles of each body on a lattice fitted to its shape at about spec.numerics.spacing (see
// scene.cpp); throws CaseError when the geometry is impossible (bodies that overlap, a body thinner than
// two particles, ...).
Scene build_scene(const CaseSpec& spec);

// The volume of a body's shape as specified, m^3 (a cylinder's nose included; a mesh's enclosed volume).
double shape_volume(const BodySpec& b);

// How many copies of a body's model make the whole body: 2 for each symmetry plane that cuts its shape.
int symmetry_multiplicity(const CaseSpec& spec, int body);

}  // namespace impactsph
