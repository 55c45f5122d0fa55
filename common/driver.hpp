// The run driver shared by both solvers: time loop, observers, writers, checkpoints, progress line and
// a clean stop on SIGINT/SIGTERM (host only).
#pragma once
#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "common/case_observables.hpp"
#include "common/observables.hpp"
#include "common/run_state.hpp"
#include "common/scene.hpp"
#include "common/stepper.hpp"

namespace impactsph {

struct RunOptions {
  std::filesystem::path out_dir = "out";
  bool quiet = false;            // no progress line and no banner
  int threads = 1;               // reported in summary.json
  std::string fingerprint;       // identifies case + overrides; a restart must match it
  bool restart = false;          // continue from out_dir/checkpoint.bin
  std::vector<std::string> command_line;  // recorded in summary.json
  // Catch SIGINT/SIGTERM for a clean stop. Handlers are process-wide: callers running several
  // simulations on threads pass false and handle the signals themselves.
  bool install_signal_handlers = true;
  // Read after every step when set: true stops the run as a signal would (checkpoint, interrupted).
  // For callers that handle the signals themselves.
  const std::atomic<bool>* stop = nullptr;
};

struct RunResult {
  RunClock clock;
  bool interrupted = false;
  double wall_seconds = 0;           // this process and the runs it continues
  double particle_steps_per_second = 0;
  double mean_neighbours = 0;
  std::vector<BodySummary> bodies;   // at the end
  Totals initial_totals, final_totals;
  CaseObservables observables;       // what the case's [observables] asks for, at the end
  bool settled = false;              // ended early, its verdict known (stop_when_settled): the residual
                                     // velocity was steady, or the target held the projectile
  bool held = false;                 // the target held the projectile (track_held)
};

// Runs scene.particles from the start (or the checkpoint) to spec.time.end. Throws DivergenceError after
// writing the last good state (frame and checkpoint) when the run diverges.
RunResult run_simulation(Scene& scene, Stepper& stepper, const RunOptions& options);

// The CPU model of this machine (/proc/cpuinfo "model name"), or "unknown".
std::string cpu_model();

// The step the driver takes with `remaining` (s) left to the end time and the stable step dt (s): no sliver.
double end_step(double dt, double remaining);

// The name of the checkpoint file inside an output folder.
std::filesystem::path checkpoint_path(const std::filesystem::path& out_dir);

}  // namespace impactsph
