// Scene: the particles of a case plus what the solvers need to advance them.
#pragma once
#include <string>
#include <vector>

#include "common/case_spec.hpp"

namespace impactsph {

struct BodyInfo {
  std::string name;
  int material = -1;
  std::size_t particle_count = 0;
  double initial_mass = 0;  // kg
};

struct Scene {
  CaseSpec spec;
  ParticleSet particles;
  std::vector<BodyInfo> bodies;
  std::vector<MaterialParams<double>> materials;  // indexed like spec.materials
};

// Builds the particles on a regular cubic lattice at spec.numerics.spacing; throws CaseError when the
// geometry is impossible (bodies that overlap, a body thinner than two particles, ...).
Scene build_scene(const CaseSpec& spec);

}  // namespace impactsph
