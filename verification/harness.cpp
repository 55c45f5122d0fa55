#include "verification/harness.hpp"

#include <gsl/gsl_fit.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/case_file.hpp"

namespace impactsph::verification {

std::string case_path(const std::string& name) { return std::string(IMPACTSPH_CASES) + "/" + name + "/case.toml"; }

Scene load_case(const std::string& name, const std::string& spacing, const std::vector<std::string>& sets) {
  return build_scene(load_case_file(case_path(name), sets, spacing));
}

long run_reference(Scene& scene, reference::ReferenceSolver& solver, double end,
                   const std::function<void(double)>& sample) {
  double t = 0;
  long steps = 0;
  while (t < end * (1 - 1e-12)) {
    const double dt = std::min(solver.stable_time_step(scene.particles), end - t);
    solver.step(scene.particles, dt);
    t += dt;
    ++steps;
    if (sample) sample(t);
  }
  return steps;
}

Profile slab_profile(const ParticleSet& p, int axis, double x0, double dx, int slabs,
                     const std::function<double(std::size_t)>& value) {
  Profile prof;
  std::vector<double> sum(static_cast<std::size_t>(slabs), 0.0);
  std::vector<int> count(static_cast<std::size_t>(slabs), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int k = static_cast<int>(std::floor((p.pos[i][axis] - x0) / dx));
    if (k < 0 || k >= slabs) continue;
    sum[static_cast<std::size_t>(k)] += value(i);
    ++count[static_cast<std::size_t>(k)];
  }
  for (int k = 0; k < slabs; ++k) {
    if (count[static_cast<std::size_t>(k)] == 0) continue;
    prof.x.push_back(x0 + (k + 0.5) * dx);
    prof.value.push_back(sum[static_cast<std::size_t>(k)] / count[static_cast<std::size_t>(k)]);
  }
  return prof;
}

double leading_crossing(const Profile& prof, double level) {
  for (std::size_t k = prof.x.size() - 1; k > 0; --k) {
    const double a = prof.value[k - 1], b = prof.value[k];
    if (a >= level && b < level) return prof.x[k - 1] + (level - a) / (b - a) * (prof.x[k] - prof.x[k - 1]);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double first_rise(const Profile& prof, double level) {
  for (std::size_t k = 1; k < prof.x.size(); ++k) {
    const double a = prof.value[k - 1], b = prof.value[k];
    if (a < level && b >= level) return prof.x[k - 1] + (level - a) / (b - a) * (prof.x[k] - prof.x[k - 1]);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size() || x.size() < 3) throw std::invalid_argument("fit_line needs at least 3 points");
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  return {c0, c1, std::sqrt(cov11)};
}

}  // namespace impactsph::verification
