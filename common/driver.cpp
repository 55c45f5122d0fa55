#include "common/driver.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/checkpoint.hpp"
#include "common/errors.hpp"
#include "common/output.hpp"
#include "common/scoped_signals.hpp"

namespace impactsph {

namespace {

std::atomic<int> g_stop_signal{0};
extern "C" void on_stop_signal(int sig) { g_stop_signal.store(sig); }

// Installs the SIGINT/SIGTERM handlers for the lifetime of a run and restores the old ones after.
// Not for concurrent runs (the handlers and the flag are process-wide): those pass install = false.
class StopSignals {
 public:
  explicit StopSignals(bool install) {
    if (!install) return;
    g_stop_signal.store(0);
    guard_ = std::make_unique<ScopedSignals>(on_stop_signal);
  }
  int received() const { return guard_ ? g_stop_signal.load() : 0; }

 private:
  std::unique_ptr<ScopedSignals> guard_;  // null when not installed
};

std::string format_seconds(double s) {
  char buf[64];
  if (s < 1e-6) std::snprintf(buf, sizeof buf, "%.3g ns", s * 1e9);
  else if (s < 1e-3) std::snprintf(buf, sizeof buf, "%.4g us", s * 1e6);
  else if (s < 1.0) std::snprintf(buf, sizeof buf, "%.4g ms", s * 1e3);
  else std::snprintf(buf, sizeof buf, "%.4g s", s);
  return buf;
}

std::string format_wall(double s) {
  char buf[64];
  const long t = static_cast<long>(std::lround(s));
  if (t >= 3600) std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t / 60) % 60);
  else if (t >= 60) std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  else std::snprintf(buf, sizeof buf, "%lds", t);
  return buf;
}

}  // namespace

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(colon + 2);
    }
  }
  return "unknown";
}

namespace {

// Particles whose kernel-correction matrix was ill-conditioned (solver falls back to the uncorrected
// gradient), counted over the steps of this process (a restart counts from the restart).
struct FallbackCount {
  std::size_t last = 0, max_per_step = 0;
  std::uint64_t total = 0;  // particle-steps
};

nlohmann::json vec_json(Vec3d v) { return nlohmann::json::array({v.x, v.y, v.z}); }

void write_summary(const Scene& scene, const Stepper& stepper, const RunOptions& opt, const RunResult& r,
                   const FallbackCount& fallbacks) {
  nlohmann::json j;
  j["case"] = scene.spec.name;
  j["case_file"] = scene.spec.source_file;
  j["command_line"] = opt.command_line;
  j["solver"] = stepper.name();
  j["hardware"] = {{"cpu", cpu_model()}, {"threads", opt.threads}};
  j["particles"] = scene.particles.size();
  j["spacing_m"] = scene.spec.numerics.spacing;
  j["smoothing_length_m"] = scene.spec.numerics.spacing * scene.spec.numerics.h_factor;
  j["steps"] = r.clock.step;
  j["simulated_time_s"] = r.clock.time;
  j["end_time_s"] = scene.spec.time.end;
  j["completed"] = !r.interrupted;
  j["wall_time_s"] = r.wall_seconds;
  j["particle_steps_per_second"] = r.particle_steps_per_second;
  j["mean_neighbours"] = r.mean_neighbours;
  j["fingerprint"] = opt.fingerprint;
  j["correction_fallbacks_last_step"] = fallbacks.last;
  j["correction_fallbacks"] = {{"particle_steps", fallbacks.total}, {"max_per_step", fallbacks.max_per_step}};
  nlohmann::json bodies = nlohmann::json::array();
  for (std::size_t k = 0; k < r.bodies.size(); ++k) {
    const BodySummary& b = r.bodies[k];
    const BodyInfo& info = scene.bodies[k];
    nlohmann::json specified{{"mass_kg", info.specified_mass}}, generated{{"mass_kg", info.generated_mass}};
    for (const BodySize& size : info.sizes) {
      specified[size.name + "_m"] = size.specified;
      generated[size.name + "_m"] = size.generated;
    }
    generated["lattice_spacing_m"] = vec_json(info.lattice_spacing);
    if (info.coarse_particle_count > 0) {
      generated["coarse_particles"] = info.coarse_particle_count;
      generated["coarse_lattice_spacing_m"] = vec_json(info.coarse_lattice_spacing);
    }
    generated["max_stretch"] = info.max_stretch;
    generated["mass_scale"] = info.mass_scale;
    bodies.push_back({{"name", info.name},
                      {"particles", b.particles},
                      {"specified", specified},
                      {"generated", generated},
                      {"geometry_warnings", info.warnings},
                      {"initial_mass_kg", info.initial_mass},
                      {"mass_kg", b.mass},
                      {"velocity_m_s", vec_json(b.velocity)},
                      {"speed_m_s", norm(b.velocity)},
                      {"kinetic_energy_J", b.kinetic_energy},
                      {"internal_energy_J", b.internal_energy},
                      {"plastic_work_J", b.plastic_work},
                      {"damaged_mass_fraction", b.damaged_fraction}});
  }
  j["bodies"] = bodies;
  // Kinetic + internal energy plus the kinetic energy the penalty contacts took is conserved.
  const double e0 = r.initial_totals.total_energy();
  const double e1 = r.final_totals.total_energy() + r.clock.contact_work;
  j["totals"] = {{"initial_momentum_kg_m_s", vec_json(r.initial_totals.momentum)},
                 {"final_momentum_kg_m_s", vec_json(r.final_totals.momentum)},
                 {"initial_energy_J", e0},
                 {"final_energy_J", e1},
                 {"contact_energy_J", r.clock.contact_work},
                 {"energy_drift_relative", e0 != 0 ? (e1 - e0) / std::abs(e0) : 0.0}};
  // Where the initial kinetic energy went: plastic work (sum m w_p), and the rest of the internal energy
  // gained, which is the artificial viscosity's heat plus the elastic and compression energy still stored
  // (small once the bodies are at rest): cases/taylor-bar/README.md, "Where the energy goes".
  const double k0 = r.initial_totals.kinetic_energy;
  const double gained = r.final_totals.internal_energy - r.initial_totals.internal_energy;
  const double plastic = r.final_totals.plastic_work - r.initial_totals.plastic_work;
  j["energy_partition"] = {{"initial_kinetic_energy_J", k0},
                           {"plastic_work_J", plastic},
                           {"other_internal_energy_J", gained - plastic},
                           {"plastic_work_share", k0 > 0 ? plastic / k0 : 0.0},
                           {"other_internal_share", k0 > 0 ? (gained - plastic) / k0 : 0.0}};
  nlohmann::json obs = nlohmann::json::object(), units = nlohmann::json::object();
  for (const ObservableRow& row : observable_rows(r.observables)) {
    if (row.kind == ObservableRow::Kind::Flag) obs[row.name] = row.value != 0;
    else if (row.kind == ObservableRow::Kind::TimeOrNever && row.value < 0) obs[row.name] = nullptr;
    else obs[row.name] = row.value;
    units[row.name] = row.si_unit;
  }
  j["observables"] = obs;
  j["observable_units"] = units;
  j["settled"] = r.settled;
  j["stopped_early"] = !r.settled ? nlohmann::json(nullptr)
                       : r.held  ? nlohmann::json("held: the projectile stopped or moved back, and no target particle "
                                                  "failed, for a settle window")
                                 : nlohmann::json("settled: the residual velocity was steady for a settle window");
  write_text_atomic(opt.out_dir / "summary.json", j.dump(2) + "\n");
}

}  // namespace

std::filesystem::path checkpoint_path(const std::filesystem::path& out_dir) { return out_dir / "checkpoint.bin"; }

// The step to take (s) with `remaining` (s) left to the end time and the stable step dt: dt itself, or the
// remainder when it is shorter; a remainder between one and one and a half stable steps is split in two
// halves, so that no step is a sliver: the penalty contact's spring is stiff in 1/dt^2 (common/contact.hpp),
// and the leapfrog carries the last evaluation's forces into the next step.
double end_step(double dt, double remaining) {
  if (remaining <= dt) return remaining;
  if (remaining < 1.5 * dt) return 0.5 * remaining;
  return dt;
}

RunResult run_simulation(Scene& scene, Stepper& stepper, const RunOptions& opt) {
  namespace fs = std::filesystem;
  fs::create_directories(opt.out_dir);
  const TimeSpec& ts = scene.spec.time;
  const double frame_interval = ts.frame_interval > 0 ? ts.frame_interval : ts.output_interval;
  ParticleSet& p = scene.particles;

  std::vector<std::string> body_names;
  for (const BodyInfo& b : scene.bodies) body_names.push_back(b.name);
  HistoryWriter history(opt.out_dir, body_names);
  const bool observing = scene.spec.observables.projectile_index >= 0;
  ObservableHistory observed(opt.out_dir, observing ? observable_rows(measure_observables(scene, p))
                                                    : std::vector<ObservableRow>{});
  FrameSeriesWriter frames(opt.out_dir, "particles");

  RunResult result;
  RunClock& clock = result.clock;
  if (opt.restart) {
    CheckpointData data = read_checkpoint(checkpoint_path(opt.out_dir));
    if (data.fingerprint != opt.fingerprint)
      throw std::runtime_error("the checkpoint in " + opt.out_dir.string() +
                               " was written by a different case or different overrides; restart with the same "
                               "case file, --spacing and --set values, or start afresh without --restart");
    if (data.particles.size() != p.size())
      throw std::runtime_error("the checkpoint holds " + std::to_string(data.particles.size()) +
                               " particles but the case builds " + std::to_string(p.size()));
    p = std::move(data.particles);
    clock = data.clock;
    history.load_existing(clock.time);
    if (observing) observed.load_existing(clock.time);
    frames.truncate_after(clock.frame);
  } else {
    frames.truncate_after(0);  // a fresh run into an existing folder starts a new series
    clock.next_output = 0;
    clock.next_frame = 0;
    clock.next_checkpoint = ts.checkpoint_interval;  // periodic checkpoints only where the interval is set
  }
  if (!opt.restart) {
    const Totals t0 = summarise_totals(p);
    clock.initial_momentum = t0.momentum;
    clock.initial_kinetic_energy = t0.kinetic_energy;
    clock.initial_internal_energy = t0.internal_energy;
  }
  result.initial_totals.momentum = clock.initial_momentum;
  result.initial_totals.kinetic_energy = clock.initial_kinetic_energy;
  result.initial_totals.internal_energy = clock.initial_internal_energy;

  const bool tty = isatty(fileno(stderr)) != 0;
  const bool progress = !opt.quiet && tty;
  StopSignals signals(opt.install_signal_handlers);
  const auto wall_start = std::chrono::steady_clock::now();
  auto last_progress = wall_start;
  const double wall_before = clock.wall_seconds;
  const std::int64_t steps_before = clock.step;
  const double time_at_start = clock.time;
  double first_dt = 0;
  const double time_eps = 1e-12 * ts.end;
  FallbackCount fallbacks;

  bool impact_over = false;  // settled, and nothing more to come (impact_is_over), at the last row
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count(); };
  // The time of the last history row and of the last frame, so that the forced observation at the end does
  // not write a second row or frame at a time that has one.
  double last_row_time = history.rows() > 0 ? history.last_time() : -1.0;
  double last_frame_time = frames.frames().empty() ? -1.0 : frames.frames().back().time;
  auto observe = [&](bool force) {
    const bool row = (force && clock.time > last_row_time + time_eps) || clock.time >= clock.next_output - time_eps;
    const bool frame = scene.spec.output.vtu && ((force && clock.time > last_frame_time + time_eps) ||
                                                 clock.time >= clock.next_frame - time_eps);
    if (row || frame) stepper.copy_to_host(p);
    if (row) {
      last_row_time = clock.time;
      if (ts.output_interval > 0)
        while (clock.next_output <= clock.time + time_eps) clock.next_output += ts.output_interval;
      const Totals totals = summarise_totals(p);
      if (scene.spec.output.csv) {
        history.append(clock.time, summarise_bodies(p, scene.bodies.size()), totals);
        history.flush();
      }
      const double e0 = result.initial_totals.total_energy();
      const double e = totals.total_energy() + clock.contact_work;
      if (e0 > 0 && e > 1.5 * e0)
        throw DivergenceError("total energy grew from " + std::to_string(e0) + " J to " + std::to_string(e) +
                              " J at t = " + format_seconds(clock.time) +
                              ": the run is unstable; try a smaller numerics.cfl");
      if (observing) {
        CaseObservables o = measure_observables(scene, p);
        track_settling(scene.spec.observables, clock.time, o.residual_velocity, clock);
        track_held(scene.spec.observables, clock.time, o, clock);
        impact_over = (clock.settled_time >= 0 && impact_is_over(scene.spec.observables, o)) || clock.held_time >= 0;
        if (scene.spec.output.csv) {
          o.settled_time = verdict_time(clock);
          observed.append(clock.time, observable_rows(o));
          observed.flush();
        }
      }
    }
    if (frame) {
      last_frame_time = clock.time;
      while (clock.next_frame <= clock.time + time_eps) clock.next_frame += frame_interval;
      frames.write_frame(clock.time, clock.frame, p, scene.materials);
      ++clock.frame;
    }
  };
  auto save = [&] {
    stepper.copy_to_host(p);
    clock.wall_seconds = wall_before + elapsed();
    write_checkpoint(checkpoint_path(opt.out_dir), p, clock, opt.fingerprint);
  };

  try {
    observe(false);
    while (clock.time < ts.end - time_eps) {
      double dt = stepper.stable_time_step(p);
      if (first_dt == 0) first_dt = dt;
      if (!(dt > 1e-4 * first_dt))
        throw DivergenceError("the time step collapsed from " + format_seconds(first_dt) + " to " + format_seconds(dt) +
                              " at t = " + format_seconds(clock.time) + " (a particle is being crushed or flies off)");
      dt = end_step(dt, ts.end - clock.time);
      stepper.step(p, dt);
      clock.time += dt;
      ++clock.step;
      const StepStats st = stepper.last_stats();
      clock.neighbour_sum += st.mean_neighbours;
      clock.contact_work += st.contact_work;
      fallbacks.last = st.correction_fallbacks;
      fallbacks.total += st.correction_fallbacks;
      fallbacks.max_per_step = std::max(fallbacks.max_per_step, st.correction_fallbacks);
      observe(false);
      if (ts.checkpoint_interval > 0 && clock.time >= clock.next_checkpoint - time_eps) {
        while (clock.next_checkpoint <= clock.time + time_eps) clock.next_checkpoint += ts.checkpoint_interval;
        save();
      }
      if (signals.received() || (opt.stop && opt.stop->load())) {
        result.interrupted = true;
        break;
      }
      if (scene.spec.observables.stop_when_settled && impact_over) {
        result.settled = true;
        break;
      }
      if (progress) {
        const auto now = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(now - last_progress).count() > 0.5) {
          last_progress = now;
          const double frac = clock.time / ts.end;
          const double done_here = clock.time - time_at_start;
          const double eta = done_here > 0 ? elapsed() * (ts.end - clock.time) / done_here : 0.0;
          std::fprintf(stderr, "\r  t = %s / %s  step %lld  dt = %s  %5.1f%%  ETA %s   ", format_seconds(clock.time).c_str(),
                       format_seconds(ts.end).c_str(), static_cast<long long>(clock.step), format_seconds(dt).c_str(),
                       100 * frac, format_wall(eta).c_str());
          std::fflush(stderr);
        }
      }
    }
  } catch (const DivergenceError&) {
    if (progress) std::fprintf(stderr, "\n");
    // p still holds the last good state: keep it for inspection and restart.
    stepper.copy_to_host(p);
    if (clock.time > last_frame_time + time_eps) {  // also with output.vtu off: the state to inspect
      frames.write_frame(clock.time, clock.frame, p, scene.materials);
      ++clock.frame;
    }
    save();
    throw;
  }
  if (progress) std::fprintf(stderr, "\n");
  if (!result.interrupted) observe(true);
  save();

  result.wall_seconds = wall_before + elapsed();
  const std::int64_t steps = clock.step;
  const double this_wall = elapsed();
  result.particle_steps_per_second =
      this_wall > 0 ? static_cast<double>(p.size()) * static_cast<double>(steps - steps_before) / this_wall : 0.0;
  result.mean_neighbours = steps > 0 ? clock.neighbour_sum / static_cast<double>(steps) : 0.0;
  result.bodies = summarise_bodies(p, scene.bodies.size());
  result.final_totals = summarise_totals(p);
  result.observables = measure_observables(scene, p);
  result.observables.settled_time = verdict_time(clock);
  result.held = clock.held_time >= 0;
  write_summary(scene, stepper, opt, result, fallbacks);
  return result;
}

}  // namespace impactsph
