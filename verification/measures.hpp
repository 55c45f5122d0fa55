// Error measures of the analytic cases against their closed forms, and the cost of each run. One
// library for the CTest verifications (analytic_*.cpp) and `impactsph verify`, so a test and the
// convergence report measure the same thing the same way.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/case_observables.hpp"
#include "common/observables.hpp"
#include "common/scene.hpp"
#include "common/stepper.hpp"

namespace impactsph::verification {

// What a run cost: particles x steps over the wall time of the stepping loop.
struct RunCost {
  double spacing = 0;  // m
  std::size_t particles = 0;
  long steps = 0;
  double wall_s = 0;
  double particle_steps() const { return static_cast<double>(particles) * static_cast<double>(steps); }
};

// cases/elastic-wave: a 20 mm flyer at 20 m/s strikes an 80 mm bar of the same elastic steel under
// uniaxial strain. Closed forms of linear elasticity: c_L = sqrt((K + 4G/3)/rho),
// particle velocity v = 10 m/s behind the front, stress rho c_L v.
struct ElasticWaveExact {
  static constexpr double rho = 7850, youngs = 200e9, poisson = 0.33;  // kg/m^3, Pa, -
  static constexpr double v = 10.0;                                   // m/s
  static constexpr double flyer = 20e-3, bar = 100e-3;                // m
  static double c_l();                                                // m/s, 6144
  static double stress() { return rho * c_l() * v; }                  // Pa, 482.3 MPa
};

struct ElasticWaveMeasure {
  double speed = 0, speed_stderr = 0;  // m/s, fitted speed of the half-amplitude point over 4..end us
  double stress = 0;                   // Pa, mean -sigma_xx 10..30 mm behind the front at the end
  double velocity_l1 = 0;              // L1 error of v_x(x) against the exact rectangle, relative to v 2 L_flyer
  double energy_drift = 0;             // (E_end - E_0)/E_0
  double momentum_error = 0;           // |p_end - p_0| / |p_0|
  RunCost cost;
  double speed_error() const { return speed / ElasticWaveExact::c_l() - 1; }
  double stress_error() const { return stress / ElasticWaveExact::stress() - 1; }
};
// Runs the case with the reference solver and measures it with an ElasticWaveProbe.
ElasticWaveMeasure measure_elastic_wave(const std::string& case_file, const std::string& spacing,
                                        const std::vector<std::string>& sets = {});

// The elastic-wave measures of one run of any solver: sample() after every step, finish() at the end.
// measure_elastic_wave drives it with the reference; `impactsph verify` with the reference and the gpu
// port stepped side by side, so every solver's errors are measured by the same code.
class ElasticWaveProbe {
 public:
  // Takes the initial totals of `scene`'s particles: construct it after the solver, before the first step.
  explicit ElasticWaveProbe(const Scene& scene);
  void sample(const ParticleSet& p, double t);  // t: the time after the step
  ElasticWaveMeasure finish(const ParticleSet& p, const RunCost& cost) const;

 private:
  double dx_, end_, next_sample_ = 4e-6;
  int slabs_;
  Totals t0_;
  std::vector<double> times_, fronts_;
};

// cases/hugoniot-4340: symmetric plate impact at `impact_speed` (each plate at V/2), hydrodynamic.
// Rankine-Hugoniot with Us = c0 + s up, up = V/2, P = rho0 Us up (Steinberg 4340: 7810, 4578, 1.33).
struct HugoniotExact {
  static constexpr double rho0 = 7810, c0 = 4578, s = 1.33;
  static double us(double impact_speed) { return c0 + s * impact_speed / 2; }
  static double pressure(double impact_speed) { return rho0 * us(impact_speed) * impact_speed / 2; }
};

struct HugoniotMeasure {
  double impact_speed = 0;    // m/s, closing speed V
  double us = 0;              // m/s, fitted front speed + up
  double pressure = 0;        // Pa, mean over the inner 70 % of the shocked region at the end
  double momentum_ratio = 0;  // |sum m v| / sum m |v| at the end (exactly 0 for the symmetric impact)
  double energy_drift = 0;
  RunCost cost;
  double us_error() const { return us / HugoniotExact::us(impact_speed) - 1; }
  double pressure_error() const { return pressure / HugoniotExact::pressure(impact_speed) - 1; }
};
// Called with the scene at the end of a run and the time reached (s): a caller's look at the final state.
using AtEnd = std::function<void(const Scene& scene, double time)>;

// `sets` are further case-file overrides (e.g. another dissipation form).
HugoniotMeasure measure_hugoniot(const std::string& case_file, const std::string& spacing, double impact_speed,
                                 const AtEnd& at_end = {}, const std::vector<std::string>& sets = {});

// The solver of a run, made for its scene.
using MakeStepper = std::function<std::unique_ptr<Stepper>(const Scene& scene)>;

// Runs a case through the run driver (so a case with stop_when_settled ends when its residual velocity
// is steady) into `out_dir`, quietly, and measures its [observables]. The solver is the reference unless
// `make` gives another (the gpu port).
struct ObservableRun {
  CaseObservables observables;
  RunCost cost;
  double energy_drift = 0;  // (E_end + contact work - E_0)/E_0
  std::string solver;       // as the solver names itself
};
ObservableRun run_observables(const std::string& case_file, const std::string& spacing,
                              const std::vector<std::string>& sets, const std::string& out_dir,
                              const AtEnd& at_end = {}, const MakeStepper& make = {});

}  // namespace impactsph::verification
