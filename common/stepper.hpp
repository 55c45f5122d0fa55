// What the run driver needs of a solver: the reference and the gpu port both implement it, so the
// driver, the observers and the writers are shared and every comparison is like for like.
#pragma once
#include <string>

#include "common/particle_set.hpp"

namespace impactsph {

struct StepStats {
  double mean_neighbours = 0;            // mean neighbour count of the real particles
  std::size_t correction_fallbacks = 0;  // particles whose L_i was ill-conditioned (last evaluation)
  std::size_t ghosts = 0;                // mirror particles of the symmetry planes
  double contact_work = 0;               // kinetic energy the penalty contacts took in the step, J
};

class Stepper {
 public:
  virtual ~Stepper() = default;
  virtual std::string name() const = 0;
  // The CFL time step of the current state (F eq 5.1), s.
  virtual double stable_time_step(const ParticleSet& p) = 0;
  // Advances p by dt. On divergence throws DivergenceError and leaves p at its state before the step.
  virtual void step(ParticleSet& p, double dt) = 0;
  virtual StepStats last_stats() const = 0;
  // Brings p up to date when the solver keeps the particles elsewhere between steps (the gpu port, in
  // device memory); the driver calls it before it reads them. The reference updates p in every step.
  virtual void copy_to_host(ParticleSet&) {}
};

}  // namespace impactsph
