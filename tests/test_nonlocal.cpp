// The integral non-local plastic work (common/nonlocal.hpp) and the non-local fracture-energy damage
// (common/models/damage_fracture_energy.hpp): the weight's band width, the average on a lattice (uniform
// fields, free surfaces, bodies kept apart, thin bands of any width), the failure rule, and both solvers
// failing exactly the particles the common function says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/case_file.hpp"
#include "common/damage.hpp"
#include "common/nonlocal.hpp"
#include "common/scene.hpp"
#include "gpu/solver.hpp"
#include "reference/solver.hpp"

namespace impactsph {
namespace {

constexpr double kRho0 = 7850;  // kg/m^3

MaterialParams<double> nonlocal_steel(double R, double gamma) {
  MaterialParams<double> m;
  m.eos.rho0 = kRho0;
  m.damage.kind = DamageKind::FractureEnergy;
  m.damage.fracture_energy.gamma = gamma;
  m.damage.fracture_energy.nonlocal_radius = R;
  set_damage_smoothing_length(m.damage, 1e-3);
  return m;
}

// A block of nx x ny x nz particles at spacing dx (m) from the origin, of body `body`, material 0.
void add_block(ParticleSet& p, int nx, int ny, int nz, double dx, Vec3d origin, std::int32_t body) {
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::size_t s = p.size();
        p.resize(s + 1);
        p.pos[s] = origin + Vec3d{(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx};
        p.mass[s] = kRho0 * dx * dx * dx;
        p.body[s] = body;
        p.material[s] = 0;
      }
}

std::vector<double> averages(const ParticleSet& p, const std::vector<MaterialParams<double>>& mats,
                             const std::vector<double>& work) {
  const NonlocalGridData g = build_nonlocal_grid(p, mats);
  std::vector<double> out(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    out[i] = nonlocal_work_density(g.view(), static_cast<std::int32_t>(i), damage_nonlocal_radius(mats[0]), work.data());
  return out;
}

// L = int alpha dV / int_plane alpha dA = 32 R / 35, by quadrature of the weight on a fine grid.
TEST(Nonlocal, BandWidthOfTheWeightIs32RBy35) {
  const double R = 6e-3, d = R / 200;
  double volume = 0, plane = 0;
  for (int i = -200; i <= 200; ++i)
    for (int j = -200; j <= 200; ++j) {
      const double r2 = (i * d) * (i * d) + (j * d) * (j * d);
      plane += nonlocal_weight(r2, R) * d * d;
      for (int k = -200; k <= 200; ++k) volume += nonlocal_weight(r2 + (k * d) * (k * d), R) * d * d * d;
    }
  EXPECT_NEAR(volume / plane, nonlocal_band_width(R), 1e-4 * R);
  EXPECT_NEAR(nonlocal_band_width(R), 32.0 / 35.0 * R, 1e-15);
  EXPECT_EQ(nonlocal_weight(R * R, R), 0.0);
  EXPECT_EQ(nonlocal_weight(0.0, R), 1.0);
}

// A uniform work density averages to itself everywhere, the corners of the block included (the average is
// normalised by the weights it found).
TEST(Nonlocal, UniformWorkAveragesToItselfAtFreeSurfacesToo) {
  const std::vector<MaterialParams<double>> mats{nonlocal_steel(3e-3, 1e6)};
  ParticleSet p;
  add_block(p, 12, 10, 8, 1e-3, Vec3d{0, 0, 0}, 0);
  const std::vector<double> work(p.size(), 2.5e8);
  const std::vector<double> avg = averages(p, mats, work);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(avg[i], 2.5e8, 1e-6) << "particle " << i;
}

// Another body's work does not enter a particle's average, however close it lies.
TEST(Nonlocal, OtherBodiesDoNotEnter) {
  const std::vector<MaterialParams<double>> mats{nonlocal_steel(3e-3, 1e6)};
  ParticleSet p;
  add_block(p, 6, 6, 6, 1e-3, Vec3d{0, 0, 0}, 0);
  const std::size_t first = p.size();
  add_block(p, 6, 6, 6, 1e-3, Vec3d{6e-3, 0, 0}, 1);
  std::vector<double> work(p.size(), 0.0);
  for (std::size_t i = first; i < p.size(); ++i) work[i] = 1e9;
  const std::vector<double> avg = averages(p, mats, work);
  for (std::size_t i = 0; i < first; ++i) EXPECT_EQ(avg[i], 0.0) << "particle " << i;
  for (std::size_t i = first; i < p.size(); ++i) EXPECT_NEAR(avg[i], 1e9, 1e-3) << "particle " << i;
  // A particle that does not average (its material is local) gets 0.
  MaterialParams<double> local = mats[0];
  local.damage.fracture_energy.nonlocal_radius = 0;
  const NonlocalGridData none = build_nonlocal_grid(p, {local});
  EXPECT_TRUE(none.empty());
}

// The property the model is for: a band narrower than the averaging width fails once its work per unit
// area reaches Gamma, whatever its width and whatever the spacing. On a lattice of spacing dx with R = 6 mm
// (the Weldox file's) and a band of n layers of uniform work W, the centre's average reaches W_c = Gamma / L
// when n dx W = Gamma x ratio. A one-layer band is a thin band: ratio 1 (1.002 at R / dx = 3, 2 mm). A wider
// band of width b = n dx costs more, as the continuum says: ratio = 1 / mean over |t| < s of (1 - t^2)^3,
// s = b / 2R (the planar weight, common/nonlocal_weight.hpp): 1.064 for 3 mm. Both held within 1 % at
// R / dx = 3 to 8.6 (the 2, 1.333, 1 and 0.7 mm spacings of the plate cases).
TEST(Nonlocal, BandFailsAtGammaPerUnitAreaWhateverItsWidth) {
  const double R = 6e-3;
  for (double dx : {2e-3, 1.333e-3, 1e-3, 0.7e-3}) {
    const std::vector<MaterialParams<double>> mats{nonlocal_steel(R, 1e6)};
    const int n = 2 * static_cast<int>(std::ceil(R / dx)) + 7;
    ParticleSet p;
    add_block(p, n, n, n, dx, Vec3d{0, 0, 0}, 0);
    const int mid = n / 2;
    for (int layers : {1, 3, 5}) {
      if (layers * dx > 0.6 * R) continue;
      std::vector<double> work(p.size(), 0.0);
      for (std::size_t s = 0; s < p.size(); ++s) {
        const int i = static_cast<int>(std::lround(p.pos[s].x / dx - 0.5));
        if (std::abs(i - mid) <= layers / 2) work[s] = 1.0;
      }
      const NonlocalGridData g = build_nonlocal_grid(p, mats);
      const std::int32_t centre = static_cast<std::int32_t>((mid * n + mid) * n + mid);
      const double avg = nonlocal_work_density(g.view(), centre, R, work.data());
      const double ratio = layers * dx / nonlocal_band_width(R) / avg;  // (work per area at failure) / Gamma
      const double s = layers * dx / (2 * R);
      const double continuum = 1.0 / (1 - s * s + 0.6 * std::pow(s, 4) - std::pow(s, 6) / 7);
      EXPECT_NEAR(ratio, layers == 1 ? 1.0 : continuum, 0.01) << "dx " << dx << ", " << layers << " layers";
    }
  }
}

// The non-local fracture energy fails a particle on a plastic step once its own work density and its
// average both reach W_c = Gamma / (32 R / 35), whatever the spacing (W_c does not depend on h0).
TEST(FractureEnergy, NonlocalFailsWhenItsOwnWorkAndTheAverageReachTheCriticalWork) {
  const double R = 6e-3, gamma = 1.3e6;
  MaterialParams<double> m = nonlocal_steel(R, gamma);
  const double w_c = gamma / (32.0 / 35.0 * R);
  EXPECT_NEAR(m.damage.fracture_energy.critical_work, w_c, 1e-6);
  set_damage_smoothing_length(m.damage, 0.3e-3);
  EXPECT_NEAR(m.damage.fracture_energy.critical_work, w_c, 1e-6);
  const double w = w_c / kRho0;  // J/kg
  EXPECT_EQ(damage_increment(m, 0.01, 0.5, w, 0.0, 5e8, 1e3, 293.0, w_c), 1.0);
  EXPECT_EQ(damage_increment(m, 0.01, 0.5, w, 0.0, 5e8, 1e3, 293.0, 0.999 * w_c), 0.0);   // average short
  EXPECT_EQ(damage_increment(m, 0.01, 0.5, 0.999 * w, 0.0, 5e8, 1e3, 293.0, 2 * w_c), 0.0);  // own work short
  EXPECT_EQ(damage_increment(m, 0.0, 0.5, w, 0.0, 5e8, 1e3, 293.0, w_c), 0.0);             // elastic step
  // The solvers form the average only where it can decide: intact, plastic step, own work at W_c.
  EXPECT_TRUE(damage_uses_nonlocal_work(m, 0.0, 0.01, w));
  EXPECT_FALSE(damage_uses_nonlocal_work(m, 0.0, 0.01, 0.999 * w));
  EXPECT_FALSE(damage_uses_nonlocal_work(m, 0.0, 0.0, w));
  EXPECT_FALSE(damage_uses_nonlocal_work(m, 1.0, 0.01, w));
  MaterialParams<double> local = m;
  local.damage.fracture_energy.nonlocal_radius = 0;
  local.damage.fracture_energy.band_width_factor = 2.6;
  EXPECT_FALSE(damage_uses_nonlocal_work(local, 0.0, 0.01, 1e9));
}

// Both solvers fail exactly the particles that the common function says, in the 8 mm plate at 2.5 mm with
// the non-local damage: every plate particle is set beyond yield in shear (1.3 A, above the Johnson-Cook rate term of the step) (so each flows plastically
// on the first step) over a field of plastic work with two one-layer bands, A whose average passes W_c and
// B whose average does not though its own work does, on a background below W_c. The gpu port sorts its
// particles, so this also checks that it averages over the right neighbours.
TEST(FractureEnergy, NonlocalSolversFailWhatTheCommonAverageSays) {
  const std::vector<std::string> sets{
      "projectile.velocity=0 m/s",
      "weldox-460e.damage={kind=\"fracture-energy\", fracture_energy=\"1300 kJ/m^2\", nonlocal_radius=\"6 mm\", "
      "crack_faces=\"compression\"}"};
  const Scene built = build_scene(load_case_file(std::string(IMPACTSPH_CASES) + "/plate-8mm/case.toml", sets, "2.5 mm"));
  const std::int32_t plate = 0;
  ASSERT_EQ(built.bodies[plate].name, "plate");
  const MaterialParams<double>& steel = built.materials[static_cast<std::size_t>(built.particles.material[0])];
  const double w_c = steel.damage.fracture_energy.critical_work;
  ASSERT_GT(w_c, 0.0);
  const double dx = 2.5e-3;
  Scene scene = built;
  ParticleSet& p = scene.particles;
  const double tau = 1.3 * steel.strength.johnson_cook.a / std::sqrt(3.0);  // von Mises 1.3 A
  std::vector<double> density(p.size(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.body[i] != plate) continue;
    const double x = p.pos[i].x;
    const double W = std::abs(x - 10e-3) < 0.5 * dx ? 4.0 * w_c : std::abs(x - 35e-3) < 0.5 * dx ? 1.5 * w_c : 0.3 * w_c;
    density[i] = W;
    p.plastic_work[i] = W / kRho0;
    p.dev_stress[i] = Sym3d{0, 0, 0, tau, 0, 0};
  }
  const NonlocalGridData g = build_nonlocal_grid(p, scene.materials);
  std::vector<std::uint8_t> expected(p.size(), 0);
  int fails = 0, held_by_average = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.body[i] != plate) continue;
    const double avg = nonlocal_work_density(g.view(), static_cast<std::int32_t>(i), 6e-3, density.data());
    // Far enough from the threshold that the step's own small plastic work cannot decide.
    ASSERT_GT(std::abs(avg / w_c - 1), 0.05) << "particle " << i;
    expected[i] = density[i] >= w_c && avg >= w_c;
    fails += expected[i];
    held_by_average += density[i] >= w_c && avg < w_c;
  }
  ASSERT_GT(fails, 0);
  ASSERT_GT(held_by_average, 0);

  auto check = [&](Stepper& solver, const char* what) {
    ParticleSet q = p;
    solver.step(q, 0.2 * solver.stable_time_step(q));
    solver.copy_to_host(q);
    int wrong = 0;
    int flowed = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      if (q.body[i] != plate) continue;
      flowed += q.plastic_strain[i] > 0;
      wrong += (q.damage[i] >= 1.0) != (expected[i] != 0);
    }
    EXPECT_EQ(flowed, static_cast<int>(std::count(p.body.begin(), p.body.end(), plate))) << what;
    EXPECT_EQ(wrong, 0) << what << ": " << fails << " particles should fail";
  };
  reference::ReferenceSolver ref(scene);
  check(ref, "reference");
  for (gpu::Precision pr : {gpu::Precision::Double, gpu::Precision::Float}) {
    const std::unique_ptr<gpu::GpuStepper> port = gpu::host::make_solver(scene, pr);
    check(*port, gpu::precision_name(pr));
  }
}

}  // namespace
}  // namespace impactsph
