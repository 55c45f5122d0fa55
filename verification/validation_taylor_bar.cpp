// Taylor bars (issues 3 and 19, CTest label `validation`: about an hour), each at 0.5, 0.4 and 0.3 mm with the
// case's own numerics. Targets:
// - cases/taylor-bar, OFHC copper at 190 m/s, against the same case by axisymmetric finite elements with the
//   same material model (verification/fe2d at 32 elements across the radius): the finite elements themselves
//   miss the experiment by more than its targets (verification/reports/fe2d/report.md), so the gap to the
//   experiment is the Johnson-Cook data's and the SPH is held to the finite-element answer: final length
//   within 2 % and impact-face diameter (the shifted measure, which follows the same material point as the
//   finite elements' face node) within 4 % at 0.3 mm, converging (the change from 0.4 to 0.3 mm smaller than
//   from 0.5 to 0.4 mm); the heat share (internal energy gained that is not plastic work, against the impact
//   energy) below 10 % at 0.4 and 0.3 mm. The experiment (cases/taylor-bar/expected.toml) is printed beside.
// - cases/taylor-bar-bilinear, the rate-independent benchmark: final length and foot radius of the
//   finite-element range with their targets (cases/taylor-bar-bilinear/expected.toml and reference.md)
//   at all three spacings and converging, peak plastic strain at least 2.5, and the rim consistency within
//   10 %: for the outer ring of the bottom lattice layer, the plastic strain against the hoop log-strain
//   ln(r/r0), which a continuum keeps at 1 or above (cases/taylor-bar/foot.py, which also gives the
//   non-affinity xi that this test does not assert).
// Both: energy drift below 0.5 %. Every figure is printed before it is asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/case_file.hpp"
#include "common/case_observables.hpp"
#include "common/expected.hpp"
#include "common/observables.hpp"
#include "verification/fe2d/fe2d.hpp"
#include "verification/harness.hpp"

namespace impactsph::verification {
namespace {

struct BarRun {
  CaseObservables o;
  double heat_share = 0;    // (internal energy gained - plastic work) / initial kinetic energy
  double energy_drift = 0;  // (E_end - E_0) / E_0
  double peak_plastic_strain = 0;
  double rim_consistency = 0;  // sum eps_p / sum ln(r/r0) over the bottom layer's outer ring
};

BarRun run_bar(const std::string& name, const std::string& spacing) {
  Scene scene = load_case(name, spacing);
  const ParticleSet& p = scene.particles;
  const double dx = scene.spec.numerics.spacing;
  // The rim: particles of the bottom layer (z < dx, the face on the plane z = 0) whose radius is within
  // dx of the outermost one's, with their initial radius.
  std::vector<std::size_t> rim;
  std::vector<double> r0;
  double r_out = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.pos[i][2] < dx) r_out = std::max(r_out, std::hypot(p.pos[i][0], p.pos[i][1]));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = std::hypot(p.pos[i][0], p.pos[i][1]);
    if (p.pos[i][2] < dx && r > r_out - dx) {
      rim.push_back(i);
      r0.push_back(r);
    }
  }
  const Totals t0 = summarise_totals(p);
  reference::ReferenceSolver solver(scene);
  const long steps = run_reference(scene, solver, scene.spec.time.end);
  const Totals t1 = summarise_totals(p);
  BarRun b;
  b.o = measure_observables(scene, p);
  b.heat_share = ((t1.internal_energy - t0.internal_energy) - (t1.plastic_work - t0.plastic_work)) /
                 t0.kinetic_energy;
  b.energy_drift = (t1.total_energy() - t0.total_energy()) / t0.total_energy();
  for (std::size_t i = 0; i < p.size(); ++i) b.peak_plastic_strain = std::max(b.peak_plastic_strain, p.plastic_strain[i]);
  double eps = 0, hoop = 0;
  for (std::size_t k = 0; k < rim.size(); ++k) {
    eps += p.plastic_strain[rim[k]];
    hoop += std::log(std::hypot(p.pos[rim[k]][0], p.pos[rim[k]][1]) / r0[k]);
  }
  b.rim_consistency = hoop > 0 ? eps / hoop : 0;
  std::printf("%s at %s: %zu particles, %ld steps: length %.3f mm, face %.3f mm (lattice) / %.3f mm (shifted) / "
              "%.3f mm (area), heat share %.1f %%, energy drift %.3f %%, peak plastic strain %.2f, rim consistency "
              "%.3f (%zu particles)\n",
              name.c_str(), spacing.c_str(), p.size(), steps, b.o.final_length * 1e3, b.o.impact_face_diameter * 1e3,
              b.o.impact_face_diameter_shifted * 1e3, b.o.impact_face_diameter_area * 1e3, 100 * b.heat_share,
              100 * b.energy_drift, b.peak_plastic_strain, b.rim_consistency, rim.size());
  return b;
}

const std::vector<std::string> kSpacings = {"0.5 mm", "0.4 mm", "0.3 mm"};

std::vector<BarRun> run_spacings(const std::string& name) {
  std::vector<BarRun> runs;
  for (const std::string& s : kSpacings) runs.push_back(run_bar(name, s));
  return runs;
}

// The case's expected answers (cases/NAME/expected.toml).
ExpectedAnswers expected(const std::string& name) {
  return read_expected(std::string(IMPACTSPH_CASES) + "/" + name + "/expected.toml");
}

// The change from the middle spacing to the finest is smaller than from the coarsest to the middle one.
void expect_converging(const std::string& what, double coarse, double middle, double fine) {
  std::printf("%s: %.3f / %.3f / %.3f mm, changes %.3f then %.3f mm\n", what.c_str(), coarse * 1e3, middle * 1e3, fine * 1e3,
              (middle - coarse) * 1e3, (fine - middle) * 1e3);
  EXPECT_LT(std::abs(fine - middle), std::abs(middle - coarse)) << what << " is not converging";
}
// Length and shifted face diameter of the three runs both converging.
void expect_shape_converging(const std::string& bar, const std::vector<BarRun>& r) {
  expect_converging(bar + " final length", r[0].o.final_length, r[1].o.final_length, r[2].o.final_length);
  expect_converging(bar + " face diameter (shifted)", r[0].o.impact_face_diameter_shifted,
                    r[1].o.impact_face_diameter_shifted, r[2].o.impact_face_diameter_shifted);
}

TEST(TaylorBar, CopperAgainstFiniteElements) {
  const ExpectedAnswers e = expected("taylor-bar");
  const double length = e.value("final_length", Dimension::Length), diameter = e.value("impact_face_diameter", Dimension::Length);
  fe2d::Options numerics;
  numerics.elements_across = 32;
  fe2d::Simulation fe(fe2d::bar_from_case(load_case_file(case_path("taylor-bar"))), numerics);
  fe.run();
  const fe2d::Observables answer = fe2d::measure(fe);
  std::printf("copper by finite elements at 32 across: length %.3f mm (%+.1f %% against the experiment's %.2f mm), "
              "face %.3f mm (%+.1f %% against %.2f mm)\n",
              answer.final_length * 1e3, 100 * (answer.final_length / length - 1), length * 1e3,
              answer.impact_face_diameter * 1e3, 100 * (answer.impact_face_diameter / diameter - 1), diameter * 1e3);
  const std::vector<BarRun> runs = run_spacings("taylor-bar");
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const BarRun& b = runs[k];
    std::printf("copper SPH at %s against the finite elements: length %+.1f %%, face %+.1f %%; against the experiment: "
                "length %+.1f %%, face %+.1f %%\n",
                kSpacings[k].c_str(), 100 * (b.o.final_length / answer.final_length - 1),
                100 * (b.o.impact_face_diameter_shifted / answer.impact_face_diameter - 1),
                100 * (b.o.final_length / length - 1), 100 * (b.o.impact_face_diameter_shifted / diameter - 1));
    if (k == 0) continue;
    EXPECT_LT(b.heat_share, 0.10) << "heat share at " << kSpacings[k];
    EXPECT_LT(std::abs(b.energy_drift), 0.005) << "energy drift at " << kSpacings[k];
  }
  EXPECT_NEAR(runs.back().o.final_length / answer.final_length, 1.0, 0.02) << "final length at " << kSpacings.back();
  EXPECT_NEAR(runs.back().o.impact_face_diameter_shifted / answer.impact_face_diameter, 1.0, 0.04)
      << "face diameter at " << kSpacings.back();
  expect_shape_converging("copper", runs);
}

TEST(TaylorBar, BilinearAgainstFiniteElement) {
  const ExpectedAnswers e = expected("taylor-bar-bilinear");
  const double length = e.value("final_length", Dimension::Length), foot_radius = e.value("foot_radius", Dimension::Length);
  const std::vector<BarRun> runs = run_spacings("taylor-bar-bilinear");
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const BarRun& b = runs[k];
    EXPECT_NEAR(b.o.final_length / length, 1.0, e.tolerance("final_length")) << "final length at " << kSpacings[k];
    EXPECT_NEAR(0.5 * b.o.impact_face_diameter_shifted / foot_radius, 1.0, e.tolerance("foot_radius"))
        << "foot radius at " << kSpacings[k];
    EXPECT_GE(b.peak_plastic_strain, 2.5) << "peak plastic strain at " << kSpacings[k];
    EXPECT_GE(b.rim_consistency, 0.9) << "rim consistency at " << kSpacings[k];
    EXPECT_LT(std::abs(b.energy_drift), 0.005) << "energy drift at " << kSpacings[k];
  }
  expect_shape_converging("bilinear", runs);
}

}  // namespace
}  // namespace impactsph::verification
