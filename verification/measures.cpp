#include "verification/measures.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "common/case_file.hpp"
#include "common/driver.hpp"
#include "common/observables.hpp"
#include "verification/harness.hpp"

namespace impactsph::verification {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

double ElasticWaveExact::c_l() {
  const double bulk = youngs / (3 * (1 - 2 * poisson)), shear = youngs / (2 * (1 + poisson));
  return std::sqrt((bulk + 4 * shear / 3) / rho);
}

ElasticWaveProbe::ElasticWaveProbe(const Scene& scene)
    : dx_(scene.spec.numerics.spacing),
      end_(scene.spec.time.end),
      slabs_(static_cast<int>(std::lround(ElasticWaveExact::bar / dx_))),
      t0_(summarise_totals(scene.particles)) {}

void ElasticWaveProbe::sample(const ParticleSet& p, double t) {
  if (t < next_sample_) return;
  next_sample_ += 0.5e-6;
  times_.push_back(t);
  fronts_.push_back(leading_crossing(slab_profile(p, 0, 0.0, dx_, slabs_, [&](std::size_t i) { return p.vel[i].x; }),
                                     0.5 * ElasticWaveExact::v));
}

ElasticWaveMeasure ElasticWaveProbe::finish(const ParticleSet& p, const RunCost& cost) const {
  using X = ElasticWaveExact;
  const double dx = dx_, end = end_;
  const int slabs = slabs_;
  auto vx = [&](std::size_t i) { return p.vel[i].x; };
  ElasticWaveMeasure r;
  r.cost = cost;
  const LineFit fit = fit_line(times_, fronts_);

  // The pulse at `end`: the exact solution is v = X::v on [front - 2 L_flyer, front), zero elsewhere.
  const double front = X::flyer + X::c_l() * end;
  const Profile vprof = slab_profile(p, 0, 0.0, dx, slabs, vx);
  double l1 = 0;
  for (std::size_t k = 0; k < vprof.x.size(); ++k) {
    const double exact = (vprof.x[k] >= front - 2 * X::flyer && vprof.x[k] < front) ? X::v : 0.0;
    l1 += std::abs(vprof.value[k] - exact) * dx;
  }
  const Profile sprof =
      slab_profile(p, 0, 0.0, dx, slabs, [&](std::size_t i) { return p.pressure[i] - p.dev_stress[i].xx; });
  double stress = 0;
  int n = 0;
  for (std::size_t k = 0; k < sprof.x.size(); ++k)
    if (sprof.x[k] > front - 30e-3 && sprof.x[k] < front - 10e-3) {
      stress += sprof.value[k];
      ++n;
    }
  const Totals t1 = summarise_totals(p);
  r.speed = fit.slope;
  r.speed_stderr = fit.slope_stderr;
  r.stress = stress / n;
  r.velocity_l1 = l1 / (X::v * 2 * X::flyer);
  r.energy_drift = (t1.total_energy() - t0_.total_energy()) / t0_.total_energy();
  r.momentum_error = norm(t1.momentum - t0_.momentum) / norm(t0_.momentum);
  return r;
}

ElasticWaveMeasure measure_elastic_wave(const std::string& case_file, const std::string& spacing,
                                        const std::vector<std::string>& sets) {
  Scene scene = build_scene(load_case_file(case_file, sets, spacing));
  const double dx = scene.spec.numerics.spacing;
  const auto t_start = std::chrono::steady_clock::now();
  reference::ReferenceSolver solver(scene);
  ElasticWaveProbe probe(scene);
  const long steps = run_reference(scene, solver, scene.spec.time.end,
                                   [&](double t) { probe.sample(scene.particles, t); });
  return probe.finish(scene.particles, {dx, scene.particles.size(), steps, seconds_since(t_start)});
}

HugoniotMeasure measure_hugoniot(const std::string& case_file, const std::string& spacing, double impact_speed,
                                 const AtEnd& at_end, const std::vector<std::string>& sets) {
  using X = HugoniotExact;
  const double up = impact_speed / 2, p_rh = X::pressure(impact_speed);
  char speed[64];
  std::snprintf(speed, sizeof speed, "%.10g m/s", up);
  std::vector<std::string> all_sets = {std::string("flyer.velocity=") + speed, std::string("target.velocity=") + speed};
  all_sets.insert(all_sets.end(), sets.begin(), sets.end());
  Scene scene = build_scene(load_case_file(case_file, all_sets, spacing));
  const double dx = scene.spec.numerics.spacing;
  const auto t_start = std::chrono::steady_clock::now();
  reference::ReferenceSolver solver(scene);
  const Totals t0 = summarise_totals(scene.particles);
  const double momentum_scale = t0.kinetic_energy / up;  // sum m |v|
  const int slabs = static_cast<int>(std::lround(20e-3 / dx));
  auto pressure = [&](std::size_t i) { return scene.particles.pressure[i]; };

  // The shocked material is at rest: the front in the target runs at Us - up; its half-pressure point
  // is fitted over time.
  std::vector<double> times, fronts;
  double next_sample = 0.3e-6;
  const double end = scene.spec.time.end;
  const long steps = run_reference(scene, solver, end, [&](double t) {
    if (t < next_sample) return;
    next_sample += 0.1e-6;
    times.push_back(t);
    fronts.push_back(leading_crossing(slab_profile(scene.particles, 0, -10e-3, dx, slabs, pressure), 0.5 * p_rh));
  });
  HugoniotMeasure r;
  r.impact_speed = impact_speed;
  r.cost = {dx, scene.particles.size(), steps, seconds_since(t_start)};
  const LineFit fit = fit_line(times, fronts);
  r.us = fit.slope + up;

  const double front = fronts.back();
  const Profile prof = slab_profile(scene.particles, 0, -10e-3, dx, slabs, pressure);
  double p_sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < prof.x.size(); ++k)
    if (std::abs(prof.x[k]) < 0.7 * front) {
      p_sum += prof.value[k];
      ++n;
    }
  r.pressure = p_sum / n;
  const Totals t1 = summarise_totals(scene.particles);
  r.momentum_ratio = norm(t1.momentum) / momentum_scale;
  r.energy_drift = (t1.total_energy() - t0.total_energy()) / t0.total_energy();
  if (at_end) at_end(scene, end);
  return r;
}

ObservableRun run_observables(const std::string& case_file, const std::string& spacing,
                              const std::vector<std::string>& sets, const std::string& out_dir,
                              const AtEnd& at_end, const MakeStepper& make) {
  Scene scene = build_scene(load_case_file(case_file, sets, spacing));
  const std::unique_ptr<Stepper> solver =
      make ? make(scene) : std::make_unique<reference::ReferenceSolver>(scene);
  RunOptions opt;
  opt.out_dir = out_dir;
  opt.quiet = true;
  opt.threads = omp_get_max_threads();
  opt.install_signal_handlers = false;
  const RunResult res = run_simulation(scene, *solver, opt);
  ObservableRun r;
  r.solver = solver->name();
  r.cost = {scene.spec.numerics.spacing, scene.particles.size(), static_cast<long>(res.clock.step), res.wall_seconds};
  r.observables = res.observables;
  const double e0 = res.initial_totals.total_energy();
  r.energy_drift = (res.final_totals.total_energy() + res.clock.contact_work - e0) / e0;
  if (at_end) at_end(scene, res.clock.time);
  return r;
}

}  // namespace impactsph::verification
