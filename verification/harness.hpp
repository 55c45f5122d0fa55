// Shared helpers of the verification programs: load a case with overrides, run the reference solver
// while sampling, reduce particle fields to profiles along a line, fit straight lines (GSL).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "common/scene.hpp"
#include "reference/solver.hpp"

namespace impactsph::verification {

std::string case_path(const std::string& name);  // cases/<name>/case.toml
Scene load_case(const std::string& name, const std::string& spacing, const std::vector<std::string>& sets = {});

// Runs to `end` with the reference solver; `sample(time)` is called after every step.
// Returns the number of steps.
long run_reference(Scene& scene, reference::ReferenceSolver& solver, double end,
                   const std::function<void(double)>& sample = {});

// Mean of `value(i)` over the particles in each slab [x0 + k dx, x0 + (k+1) dx) along `axis`.
struct Profile {
  std::vector<double> x;      // slab centres, m
  std::vector<double> value;  // slab means
};
Profile slab_profile(const ParticleSet& p, int axis, double x0, double dx, int slabs,
                     const std::function<double(std::size_t)>& value);

// Position where the profile first falls through `level` scanning from the right end to the left
// (the leading edge of a wave running in +x), by linear interpolation; NaN if it never does.
double leading_crossing(const Profile& prof, double level);
// Position where the profile first rises through `level` scanning left to right.
double first_rise(const Profile& prof, double level);

struct LineFit {
  double intercept, slope, slope_stderr;
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace impactsph::verification
