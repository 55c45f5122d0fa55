// The observables a case asks for in [observables] (host only): Taylor bar shape, projectile residual
// velocity and mass, plug and perforation, and when the residual velocity settled. Masses are those of
// the whole physical body: a body cut by k symmetry planes is 2^k times its model.
#pragma once
#include <string>
#include <vector>

#include "common/run_state.hpp"
#include "common/scene.hpp"

namespace impactsph {

struct CaseObservables {
  bool taylor_bar = false;
  double final_length = 0;          // m, from the face (on the wall, or after it left the wall) to the far end
  double impact_face_diameter = 0;  // m, of the layer of particles on the wall: 2 (r_max + ds/2)
  // Two face measures without the lattice's bias (issue 19), both 2 R0 at t = 0:
  double impact_face_diameter_shifted = 0;  // m, 2 (r_max(t) + R0 - r_max(0)), r_max of the wall layer's centres
  double impact_face_diameter_area = 0;     // m, of the circle of the wall layer's area, sum (m/rho) / dz, whole bar
  bool projectile = false;
  double residual_velocity = 0;     // m/s, mass-weighted velocity along the initial direction
  double residual_mass = 0;         // kg, initial mass less the particles with D >= kFailedDamage (X section 3.1)
  double eroded_mass = 0;           // kg, the projectile particles with D >= kFailedDamage (initial less residual mass)
  bool target = false;
  double plug_mass = 0;             // kg, the heaviest piece of intact target cut off the clamped plate, leaving
  double plug_velocity = 0;         // m/s, its mass-weighted velocity along the impact direction
  double damage_fraction = 0;       // mass fraction of the target with D >= kFailedDamage (fully damaged)
  bool perforated = false;
  double settled_time = -1;         // s, since when the verdict is known (verdict_time); -1: not yet
};

CaseObservables measure_observables(const Scene& scene, const ParticleSet& p);

// One observable as a row: its name (the key in summary.json's "observables"), its value in SI, and how a
// person reads it (the unit, the factor from SI to that unit, the digits). The one list that the run's
// printout and summary.json are both written from, so that they cannot disagree.
struct ObservableRow {
  enum class Kind { Number, Flag, TimeOrNever };  // Flag: value 0 or 1; TimeOrNever: value < 0 is "never"
  std::string name;
  double value = 0;         // SI
  const char* unit = "";    // as printed
  double scale = 1;         // SI to unit
  int digits = 2;           // after the decimal point, as printed
  Kind kind = Kind::Number;
  const char* si_unit = ""; // the unit of value ("" for a number without one), as summary.json's
                            // "observable_units" gives it to its readers
};

// The rows of the observables the case asked for, in the order they are printed.
std::vector<ObservableRow> observable_rows(const CaseObservables& o);
// "residual_velocity: 232.58 m/s", "perforated: yes", "settled_time: not settled by the end time".
std::string format_observable(const ObservableRow& row);

// Tracks whether the residual velocity has settled (state kept in RunClock so a restart continues it):
// the velocity must first leave its initial value by more than the tolerance (the impact has begun),
// then stay within the tolerance for the settle window, and a projectile still moving must not be drifting
// fast enough to stop within ten windows (near the ballistic limit that is a stop in progress).
void track_settling(const ObservablesSpec& spec, double time, double residual_velocity, RunClock& clock);

// Tracks whether the target holds the projectile for good (state in RunClock): the projectile has stopped or
// moves back (residual velocity at most the settle tolerance), it has not perforated, and no target
// particle has failed, all through a settle window. Then held_time is the start of that window: nothing is
// left that could carry the projectile through, and a run with stop_when_settled ends there with the
// verdict "held" (the residual velocity it reports is the projectile's then, stopped or moving back).
void track_held(const ObservablesSpec& spec, double time, const CaseObservables& o, RunClock& clock);

// Since when the run's verdict is known (s): the residual velocity settled, or the target held the
// projectile; -1: not yet.
double verdict_time(const RunClock& clock);

// Whether a run whose residual velocity has settled has nothing more to show (stop_when_settled): the
// projectile perforated, or stopped or turned back (residual velocity <= the settle tolerance), or there
// is no target. A projectile that moves on steadily with a plate that has not let it through (the plate
// still dishing, a plug still being cut) is not done.
bool impact_is_over(const ObservablesSpec& spec, const CaseObservables& o);

}  // namespace impactsph
