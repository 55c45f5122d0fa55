// impactsph verify, the runs: the analytic cases over spacings, the reference and the gpu port side by side,
// the validation cases against their experiments (app/verify_parts.hpp).
#include "app/verify_parts.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "app/gnuplot.hpp"
#include "app/picture.hpp"
#include "app/run_args.hpp"
#include "app/solver_choice.hpp"
#include "common/case_file.hpp"
#include "common/driver.hpp"
#include "common/expected.hpp"
#include "gpu/solver.hpp"
#include "verification/fe2d/fe2d.hpp"

namespace impactsph::verify_detail {

// ---------------------------------------------------------------------------------------------------
// The studies

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Runs `file` at `h` with the reference and the gpu port in each of `precisions` stepped side by side,
// as verification/crosscheck does: every solver takes the reference's CFL step (clamped to the end
// time), so the fields are compared at the same times. Each solver computes its own CFL step too (a run
// of its own would take it; it counts in its wall time) and the largest deviation of the port's from the
// reference's is reported. The port copies its state to the host after every step (its default, as in
// crosscheck). With `wave` each solver's particles are measured by an ElasticWaveProbe, the code of
// measure_elastic_wave. Stops at the end time, or after `max_steps` steps when that is positive.
SideBySide side_by_side(const std::string& what, const std::string& file, const std::string& h,
                        const std::vector<std::string>& sets, const std::vector<gpu::Precision>& precisions,
                        bool wave, long max_steps, const verification::AtEnd& at_end) {
  struct Live {
    Scene scene;
    std::unique_ptr<Stepper> solver;
    std::unique_ptr<verification::ElasticWaveProbe> probe;
    Side side;
  };
  const Scene scene = build_scene(load_case_file(file, sets, h));
  const std::vector<Vec3d> x0 = scene.particles.pos;
  std::vector<std::unique_ptr<Live>> live;
  auto add = [&](const std::string& backend, const std::string& precision) {
    auto l = std::make_unique<Live>();
    l->scene = scene;
    l->solver = make_stepper(l->scene, backend, precision);
    if (wave) l->probe = std::make_unique<verification::ElasticWaveProbe>(l->scene);
    l->side.backend = backend;
    l->side.precision = precision;
    l->side.name = l->solver->name();
    live.push_back(std::move(l));
  };
  add("reference", "double");
  for (const gpu::Precision pr : precisions) add("gpu", gpu::precision_name(pr));

  Live& ref = *live[0];
  const double end = scene.spec.time.end;
  double t = 0;
  long steps = 0;
  while (t < end * (1 - 1e-12) && (max_steps <= 0 || steps < max_steps)) {
    auto c0 = std::chrono::steady_clock::now();
    const double dt_ref = ref.solver->stable_time_step(ref.scene.particles);
    const double dt = std::min(dt_ref, end - t);
    ref.solver->step(ref.scene.particles, dt);
    ref.side.wall_s += seconds_since(c0);
    for (std::size_t k = 1; k < live.size(); ++k) {
      Live& l = *live[k];
      c0 = std::chrono::steady_clock::now();
      const double own = l.solver->stable_time_step(l.scene.particles);
      l.solver->step(l.scene.particles, dt);
      l.solver->copy_to_host(l.scene.particles);  // the probe reads the particles after every step
      l.side.wall_s += seconds_since(c0);
      l.side.dt_deviation = std::max(l.side.dt_deviation, std::abs(own / dt_ref - 1));
    }
    t += dt;
    ++steps;
    for (const auto& l : live)
      if (l->probe) l->probe->sample(l->scene.particles, t);
  }

  SideBySide r;
  r.what = what;
  r.spacing = scene.spec.numerics.spacing;
  r.end_time = t;
  r.particles = scene.particles.size();
  r.steps = steps;
  r.wave = wave;
  for (std::size_t k = 0; k < live.size(); ++k) {
    Live& l = *live[k];
    if (wave) l.side.wave = l.probe->finish(l.scene.particles, {r.spacing, r.particles, steps, l.side.wall_s});
    if (k > 0) l.side.diff = verification::compare_fields(l.scene.particles, ref.scene.particles, x0);
    if (k == 0) r.ref = l.side;
    else r.ports.push_back(l.side);
  }
  if (at_end) at_end(ref.scene, t);
  return r;
}

// The elastic-wave errors of one solver of a side-by-side run, as points of the report.
void wave_points(Report& r, const Side& s) {
  const verification::ElasticWaveMeasure& m = s.wave;
  auto point = [&](const char* series, double value) {
    Point p{series, m.cost.spacing, value, m.cost};
    p.backend = s.backend;
    p.precision = s.precision;
    p.solver = s.name;
    r.errors.push_back(p);
  };
  point("elastic wave: velocity profile L1", m.velocity_l1);
  point("elastic wave: wave speed", m.speed_error());
  point("elastic wave: stress amplitude", m.stress_error());
  Point label;
  label.backend = s.backend;
  label.precision = s.precision;
  label.solver = s.name;
  progress(s.backend == "reference" ? "elastic wave" : "elastic wave, " + solver_label(label), m.cost,
           "L1 " + fmt("%.4f", m.velocity_l1) + ", speed " + fmt("%+.3f %%", 100 * m.speed_error()) + ", stress " +
               fmt("%+.2f %%", 100 * m.stress_error()));
}

// The spacings at which the gpu port runs beside the reference, double and float: the fast suite stops
// at 0.8 mm (2 x 1e6 particle-steps of the port; 0.5 mm would add 2 x 6.6e6, about as long as the
// reference's own 0.5 mm run twice over) and the smoke suite runs it at 2 mm only.
std::vector<std::string> port_spacings(const std::string& suite) {
  if (suite == "smoke") return {"2 mm"};
  if (suite == "fast") return {"2 mm", "1 mm", "0.8 mm"};
  return {"2 mm", "1 mm", "0.8 mm", "0.5 mm"};
}

void elastic_wave(Report& r, const std::string& cases, const std::string& suite) {
  const bool full = suite == "full", smoke = suite == "smoke";
  // A spacing must divide the 4 mm section, the 20 mm flyer and the 80 mm bar, or the lattice leaves gaps
  // at the faces (cases/elastic-wave-convergence/case.toml).
  const std::string file = cases + "/elastic-wave-convergence/case.toml";
  std::vector<const char*> spacings{"2 mm", "1 mm", "0.8 mm"};
  if (!smoke) spacings.push_back("0.5 mm");
  if (full) spacings.push_back("0.4 mm");  // 16e6 particle-steps: 2 to 5 minutes on one core
  const std::vector<std::string> with_port = port_spacings(suite);
  for (const char* h : spacings) {
    const bool port = std::find(with_port.begin(), with_port.end(), h) != with_port.end();
    try {
      const SideBySide sb =
          side_by_side("elastic wave", file, h, {"output.vtu=false"},
                       port ? std::vector<gpu::Precision>{gpu::Precision::Double, gpu::Precision::Float}
                            : std::vector<gpu::Precision>{},
                       true, 0,
                       std::string(h) == spacings.back()
                           ? picture_at_end(r, std::string("elastic wave at ") + h, "picture_elastic_wave",
                                            PictureField::Speed)
                           : verification::AtEnd{});
      wave_points(r, sb.ref);
      for (const Side& s : sb.ports) wave_points(r, s);
      if (port) r.cross.push_back(sb);
    } catch (const std::exception& e) {
      ++r.failures;
      r.skipped.push_back({std::string("elastic wave at ") + h, std::string("failed: ") + e.what()});
    }
  }
}

// The coarse plate impact (cases/plate-8mm at 2.5 mm, 298 m/s), the first 100 steps, reference against
// the gpu port in double and float (as the crosscheck test double_plate_100_steps): contact, plasticity
// and damage, which the elastic wave does not exercise.
void plate_side_by_side(Report& r, const std::string& cases) {
  const std::string what = "8 mm plate, 298 m/s, first 100 steps";
  try {
    const SideBySide sb = side_by_side(what, cases + "/plate-8mm/case.toml", "2.5 mm", {"output.vtu=false"},
                                       {gpu::Precision::Double, gpu::Precision::Float}, false, 100);
    for (const Side& s : sb.ports)
      std::printf("  %-44s %8s mm %8zu particles %6ld steps %8.1f s  %s; reference %.1f s\n", what.c_str(),
                  mm(sb.spacing).c_str(), sb.particles, sb.steps, s.wall_s, s.name.c_str(), sb.ref.wall_s);
    r.cross.push_back(sb);
  } catch (const std::exception& e) {
    ++r.failures;
    r.skipped.push_back({what + " (reference against the gpu port)", std::string("failed: ") + e.what()});
  }
}

void hugoniot(Report& r, const std::string& cases, double speed) {
  const std::string file = cases + "/hugoniot-4340/case.toml";
  const std::string tag = "Hugoniot " + fmt("%.0f", speed) + " m/s";
  // A spacing must divide the 1.5 mm section and the 10 mm plates (no gap at the impact face): 3 to 15
  // particles across.
  for (const char* h : {"0.5 mm", "0.25 mm", "0.125 mm", "0.1 mm"}) {
    try {
      const verification::HugoniotMeasure m = verification::measure_hugoniot(
          file, h, speed,
          speed == 1000 && std::string(h) == "0.1 mm"
              ? picture_at_end(r, tag + " at " + h, "picture_hugoniot", PictureField::Pressure)
              : verification::AtEnd{});
      r.errors.push_back({tag + ": shock pressure", m.cost.spacing, m.pressure_error(), m.cost});
      r.errors.push_back({tag + ": shock speed", m.cost.spacing, m.us_error(), m.cost});
      progress(tag, m.cost, "P " + fmt("%+.2f %%", 100 * m.pressure_error()) + ", Us " + fmt("%+.2f %%", 100 * m.us_error()));
    } catch (const std::exception& e) {
      ++r.failures;
      r.skipped.push_back({tag + " at " + h, std::string("failed: ") + e.what()});
    }
  }
}

Experiments read_experiments(const std::string& cases) {
  Experiments x;
  const ExpectedAnswers bar = read_expected(cases + "/taylor-bar/expected.toml");
  x.taylor_length = bar.value("final_length", Dimension::Length);
  x.taylor_length_tolerance = bar.tolerance("final_length");
  x.taylor_diameter = bar.value("impact_face_diameter", Dimension::Length);
  const ExpectedAnswers plate = read_expected(cases + "/plate-8mm/expected.toml");
  x.plate_curve = {plate.value("recht_ipson_a", Dimension::Dimensionless),
                   plate.value("recht_ipson_p", Dimension::Dimensionless),
                   plate.value("ballistic_limit", Dimension::Velocity)};
  const ExpectedAnswers tile = read_expected(cases + "/ceramic-tile/expected.toml");
  x.tile_velocity = tile.value("residual_velocity", Dimension::Velocity);
  x.tile_velocity_tolerance = tile.tolerance("residual_velocity");
  x.tile_mass = tile.value("residual_mass", Dimension::Mass);
  x.tile_mass_tolerance = tile.tolerance("residual_mass");
  return x;
}

std::vector<Observable> validation_observables() {
  return {{"Taylor bar: final length", g_experiments.taylor_length, 1e3, "mm", "%.3f"},
          {"Taylor bar: impact-face diameter", g_experiments.taylor_diameter, 1e3, "mm", "%.3f"},
          {"8 mm plate at 298 m/s: residual velocity", recht_ipson(g_experiments.plate_curve, kPlateSpeed), 1, "m/s", "%.2f"},
          {"ceramic tile: residual velocity", g_experiments.tile_velocity, 1, "m/s", "%.2f"},
          {"ceramic tile: residual mass", g_experiments.tile_mass, 1e3, "g", "%.3f"}};
}
Observable validation_observable(const std::string& series) {
  for (const Observable& o : validation_observables())
    if (o.series == series) return o;
  throw std::logic_error("no experiment for " + series);
}


std::vector<Solver> port_solvers() {
  std::vector<Solver> out;
  for (const gpu::Precision pr : {gpu::Precision::Double, gpu::Precision::Float})
    out.push_back({"gpu", gpu::precision_name(pr), [pr](const Scene& s) { return make_stepper(s, "gpu", gpu::precision_name(pr)); }});
  return out;
}

// The point of one observable of a run of `solver`.
Point observable_point(const std::string& series, double value, const verification::ObservableRun& o,
                       const Solver& solver) {
  Point p{series, o.cost.spacing, value, o.cost};
  p.backend = solver.backend;
  p.precision = solver.precision;
  p.solver = o.solver;
  return p;
}

// Runs `file` at `h` through the run driver with the reference and, when `port`, the gpu port in double
// and float, each into runs/<stem>-<h>[-gpu-<precision>]; `record` makes the report's points of a run
// and returns its progress line. `at_end` looks at the reference's run. A failed run goes to Skipped.
// Returns the reference's run, if it did not fail.
std::optional<verification::ObservableRun> validation_runs(
    Report& r, const std::string& what, const std::string& file, const std::string& h,
    const std::vector<std::string>& sets, const fs::path& runs, const std::string& stem, bool port,
    const verification::AtEnd& at_end,
    const std::function<std::string(const verification::ObservableRun&, const Solver&)>& record) {
  std::optional<verification::ObservableRun> reference;
  std::vector<Solver> solvers{Solver{}};
  if (port)
    for (const Solver& s : port_solvers()) solvers.push_back(s);
  for (const Solver& s : solvers) {
    const bool ref = s.backend == "reference";
    const std::string dir = stem + "-" + h + (ref ? "" : "-gpu-" + s.precision);
    Point label;
    label.backend = s.backend;
    label.precision = s.precision;
    try {
      const verification::ObservableRun o = verification::run_observables(file, h, sets, (runs / dir).string(),
                                                                          ref ? at_end : verification::AtEnd{}, s.make);
      label.solver = o.solver;
      if (ref) reference = o;
      const std::string line = record(o, s);
      progress(ref ? what : what + ", " + solver_label(label), o.cost, line);
    } catch (const std::exception& e) {
      ++r.failures;
      r.skipped.push_back(
          {what + " at " + h + (ref ? "" : " (gpu port, " + s.precision + ")"), std::string("failed: ") + e.what()});
    }
  }
  return reference;
}

// The spacings of the validation cases in the full suite, and those at which the gpu port runs too
// (the coarsest, where its double and float runs cost least).
const std::vector<std::string> kTaylorSpacings{"1.27 mm", "0.8467 mm", "0.635 mm", "0.508 mm"};
constexpr int kTaylorFeElementsAcross = 32;
const std::vector<std::string> kTaylorPort{"1.27 mm", "0.8467 mm"};
const std::vector<std::string> kPlateSpacings{"4 mm", "2 mm", "1.6 mm", "1.3333333 mm"};
const std::vector<std::string> kPlatePort{"4 mm", "2 mm"};
const std::vector<std::string> kTileSpacings{"1.5875 mm", "1.27 mm"};
const std::vector<std::string> kTilePort{"1.5875 mm"};

bool contains(const std::vector<std::string>& v, const std::string& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

void taylor_bar(Report& r, const std::string& cases, const fs::path& runs, std::vector<Cfl>& cfl) {
  const std::string file = cases + "/taylor-bar/case.toml";
  // The same case by axisymmetric finite elements (verification/fe2d): the section's reference line beside the
  // experiment. 32 elements across the radius: within 0.1 % in length and 0.5 % in face of 16 across
  // (verification/reports/fe2d), about a minute on one core.
  try {
    const auto t0 = std::chrono::steady_clock::now();
    fe2d::Options numerics;
    numerics.elements_across = kTaylorFeElementsAcross;
    fe2d::Simulation sim(fe2d::bar_from_case(load_case_file(file)), numerics);
    sim.run();
    const fe2d::Observables o = fe2d::measure(sim);
    r.taylor_fe = {true, sim.nr(), sim.elements().size(), sim.steps(), o.final_length, o.impact_face_diameter,
                   seconds_since(t0)};
    std::printf("  %-44s %8d across %8zu elements %6ld steps %8.1f s  L %s mm, D %s mm\n", "Taylor bar, finite elements",
                sim.nr(), sim.elements().size(), sim.steps(), r.taylor_fe.wall_s, mm(o.final_length).c_str(),
                mm(o.impact_face_diameter).c_str());
    std::fflush(stdout);
  } catch (const std::exception& e) {
    ++r.failures;
    r.skipped.push_back({"Taylor bar by finite elements", std::string("failed: ") + e.what()});
  }
  // A cylinder has round(L/h) layers of h: these spacings give the bar its 25.4 mm exactly (20 to 50 layers).
  for (const std::string& h : kTaylorSpacings) {
    const std::optional<verification::ObservableRun> ref = validation_runs(
        r, "Taylor bar", file, h, {"output.vtu=false"}, runs, "taylor-bar", contains(kTaylorPort, h),
        h == kTaylorSpacings.back()
            ? picture_at_end(r, "Taylor bar at " + h, "picture_taylor_bar", PictureField::PlasticStrain)
            : verification::AtEnd{},
        [&](const verification::ObservableRun& o, const Solver& s) {
          r.observables.push_back(observable_point("Taylor bar: final length", o.observables.final_length, o, s));
          r.observables.push_back(
              observable_point("Taylor bar: impact-face diameter", o.observables.impact_face_diameter_shifted, o, s));
          return "L " + mm(o.observables.final_length) + " mm, D " + mm(o.observables.impact_face_diameter_shifted) + " mm";
        });
    if (h != "0.8467 mm" || !ref) continue;
    try {
      const verification::ObservableRun half = verification::run_observables(
          file, h, {"output.vtu=false", "numerics.cfl=0.1"}, (runs / "taylor-bar-0.8467 mm-cfl0.1").string());
      progress(
          "Taylor bar, CFL 0.1", half.cost,
          "L " + mm(half.observables.final_length) + " mm, D " + mm(half.observables.impact_face_diameter_shifted) + " mm");
      cfl.push_back(
          {"Taylor bar at 0.8467 mm: final length", ref->observables.final_length, half.observables.final_length});
      cfl.push_back({"Taylor bar at 0.8467 mm: impact-face diameter", ref->observables.impact_face_diameter_shifted,
                     half.observables.impact_face_diameter_shifted});
    } catch (const std::exception& e) {
      ++r.failures;
      r.skipped.push_back({"Taylor bar at 0.8467 mm, CFL 0.1", std::string("failed: ") + e.what()});
    }
  }
}

void plate(Report& r, const std::string& cases, const fs::path& runs, std::vector<Cfl>& cfl) {
  const std::string file = cases + "/plate-8mm/case.toml";
  const std::string v = "projectile.velocity=" + fmt("%.0f", kPlateSpeed) + " m/s";
  const std::string series = "8 mm plate at 298 m/s: residual velocity";
  // Spacings that divide the 8 mm plate (a cylinder has round(L/h) layers; more would overlap the
  // projectile): 2 to 6 layers.
  for (const std::string& h : kPlateSpacings) {
    const std::optional<verification::ObservableRun> ref = validation_runs(
        r, "8 mm plate, 298 m/s", file, h, {"output.vtu=false", v}, runs, "plate-8mm", contains(kPlatePort, h),
        h == kPlateSpacings.back()
            ? picture_at_end(r, "8 mm plate at 298 m/s, " + h, "picture_plate_8mm", PictureField::PlasticStrain)
            : verification::AtEnd{},
        [&](const verification::ObservableRun& o, const Solver& s) {
          r.observables.push_back(observable_point(series, o.observables.residual_velocity, o, s));
          return "v_r " + fmt("%.2f m/s", o.observables.residual_velocity) +
                 (o.observables.settled_time < 0 ? " (not settled)" : "");
        });
    if (h != "2 mm" || !ref) continue;
    try {
      const verification::ObservableRun half = verification::run_observables(
          file, h, {"output.vtu=false", v, "numerics.cfl=0.1"}, (runs / "plate-8mm-2 mm-cfl0.1").string());
      progress("8 mm plate, CFL 0.1", half.cost, "v_r " + fmt("%.2f m/s", half.observables.residual_velocity));
      cfl.push_back({"8 mm plate at 2 mm, 298 m/s: residual velocity", ref->observables.residual_velocity,
                     half.observables.residual_velocity});
    } catch (const std::exception& e) {
      ++r.failures;
      r.skipped.push_back({"8 mm plate at 2 mm, CFL 0.1", std::string("failed: ") + e.what()});
    }
  }
}

// cases/ceramic-tile as committed (PAM contact, CFL 0.3, 60 us) at spacings 12.7 mm / k (k = 8, 10), at
// which the tile's lattice is cubic; 1.0583 mm (k = 12, 4.6e7 particle-steps) would double the tile's
// cost, and the case's own 0.79375 mm (k = 16, 1.5e8) would take longer than the rest of the suite.
void ceramic_tile(Report& r, const std::string& cases, const fs::path& runs) {
  const std::string file = cases + "/ceramic-tile/case.toml";
  for (const std::string& h : kTileSpacings)
    validation_runs(
        r, "ceramic tile", file, h, {"output.vtu=false"}, runs, "ceramic-tile", contains(kTilePort, h),
        h == kTileSpacings.back()
            ? picture_at_end(r, "ceramic tile at " + h, "picture_ceramic_tile", PictureField::Damage)
            : verification::AtEnd{},
        [&](const verification::ObservableRun& o, const Solver& s) {
          r.observables.push_back(
              observable_point("ceramic tile: residual velocity", o.observables.residual_velocity, o, s));
          r.observables.push_back(observable_point("ceramic tile: residual mass", o.observables.residual_mass, o, s));
          return "v_r " + fmt("%.2f m/s", o.observables.residual_velocity) + ", m_r " +
                 fmt("%.3f g", o.observables.residual_mass * 1e3);
        });
}

}  // namespace impactsph::verify_detail
