// Observables per body and in total (host only; ghosts are never in a ParticleSet).
#pragma once
#include <string>
#include <vector>

#include "common/damage.hpp"
#include "common/particle_set.hpp"

namespace impactsph {

struct BodySummary {
  std::size_t particles = 0;
  double mass = 0;                // kg
  Vec3d velocity{0, 0, 0};        // mass-weighted mean velocity, m/s
  double kinetic_energy = 0;      // J
  double internal_energy = 0;     // J (sum m e)
  double plastic_work = 0;        // J (sum m w_p): the part of the internal energy that plastic flow did
  double damaged_fraction = 0;    // mass fraction with D >= kFailedDamage
};

struct Totals {
  Vec3d momentum{0, 0, 0};  // kg m/s
  double kinetic_energy = 0;
  double internal_energy = 0;
  double plastic_work = 0;  // J, part of internal_energy
  double total_energy() const { return kinetic_energy + internal_energy; }
};

// Serial sums in particle order, so the figures are the same bits for any thread count.
inline std::vector<BodySummary> summarise_bodies(const ParticleSet& p, std::size_t body_count) {
  std::vector<BodySummary> out(body_count);
  std::vector<Vec3d> momentum(body_count, Vec3d{0, 0, 0});
  for (std::size_t i = 0; i < p.size(); ++i) {
    BodySummary& b = out[static_cast<std::size_t>(p.body[i])];
    const double m = p.mass[i];
    b.particles += 1;
    b.mass += m;
    momentum[static_cast<std::size_t>(p.body[i])] += m * p.vel[i];
    b.kinetic_energy += 0.5 * m * norm2(p.vel[i]);
    b.internal_energy += m * p.energy[i];
    b.plastic_work += m * p.plastic_work[i];
    if (p.damage[i] >= kFailedDamage) b.damaged_fraction += m;
  }
  for (std::size_t k = 0; k < body_count; ++k) {
    if (out[k].mass > 0) {
      out[k].velocity = (1.0 / out[k].mass) * momentum[k];
      out[k].damaged_fraction /= out[k].mass;
    }
  }
  return out;
}

inline Totals summarise_totals(const ParticleSet& p) {
  Totals t;
  for (std::size_t i = 0; i < p.size(); ++i) {
    t.momentum += p.mass[i] * p.vel[i];
    t.kinetic_energy += 0.5 * p.mass[i] * norm2(p.vel[i]);
    t.internal_energy += p.mass[i] * p.energy[i];
    t.plastic_work += p.mass[i] * p.plastic_work[i];
  }
  return t;
}

}  // namespace impactsph
