// Where a run stands: everything besides the particles that a checkpoint must hold so that a restarted
// run continues bit for bit.
#pragma once
#include <cstdint>

#include "common/particle_set.hpp"

namespace impactsph {

struct RunClock {
  double time = 0;              // simulated time, s
  std::int64_t step = 0;        // steps taken
  std::int64_t frame = 0;       // VTU frames written
  double next_output = 0;       // next observables row, s
  double next_frame = 0;        // next VTU frame, s
  double next_checkpoint = 0;   // next periodic checkpoint, s
  double wall_seconds = 0;      // wall time spent stepping before this (restarted) process, s
  double neighbour_sum = 0;     // sum over steps of the mean neighbour count, for the summary
  Vec3d initial_momentum{0, 0, 0};      // totals at t = 0, kg m/s
  double initial_kinetic_energy = 0;    // J
  double initial_internal_energy = 0;   // J
  double contact_work = 0;              // kinetic energy taken by penalty contacts so far, J
  // Settling of the residual velocity (case_observables.hpp, track_settling).
  double settle_initial_velocity = 0;   // m/s, at the first observation
  double settle_window_start = -1;      // s, start of the current steady window; -1: impact not begun
  double settle_min = 0, settle_max = 0;  // m/s, range over the current window
  double settled_time = -1;             // s; -1: not settled
  std::int64_t settle_observations = 0;  // 64-bit: no padding, so a checkpoint holds no uninitialised bytes
  // A projectile held by its target (case_observables.hpp, track_held).
  double held_window_start = -1;        // s, since when it has been stopped or moving back with no target
                                        // particle failing; -1: not so
  double held_failed_fraction = 0;      // the target's failed mass fraction when that window began
  double held_time = -1;                // s, the start of a full such window: the verdict held is known; -1: not yet
};

}  // namespace impactsph
