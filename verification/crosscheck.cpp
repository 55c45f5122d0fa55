// Cross-check of the gpu port (host build) against the reference solver on the same case (issue 5).
// Both solvers start from the same scene and take the same time steps (the reference's CFL step), so the
// fields are compared at matched times. Prints a table and exits 1 when a tolerance fails.
//
//   crosscheck CASE [--spacing X] [--set key=value ...] [--precision double|float] [--steps N | --to-end]
//              [--every K] [--field-tol R] [--wave-tol R] [--length-tol R] [--residual-tol R] [--build host|cuda]
// --build cuda checks the CUDA build instead of the host build; with no CUDA device it exits with 77
// (CTest: skipped).
//
// Field differences, at every K-th step and at the last: for displacement u = x - x_0 (m), velocity
// (m/s), density (kg/m^3) and stress sigma = S - P I (Pa, six components), the relative L2 difference
// |a - b|_2 / |b|_2 over particles and the relative max difference max |a_i - b_i| / max |b_i|, with b the
// reference; --field-tol bounds both. Observables at the end: per-body momentum, kinetic and internal
// energy, contact work, and the case observables; with --field-tol the body sums are bounded too, relative
// to the larger of the reference's value at the end and at the start (rel_body).
// Observable tolerances (float runs): --wave-tol on the elastic-wave front speed and stress amplitude,
// --length-tol on the Taylor bar final length, --residual-tol on the plate residual velocity.
#include <omp.h>
#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "common/case_file.hpp"
#include "common/case_observables.hpp"
#include "common/observables.hpp"
#include "gpu/solver.hpp"
#include "reference/solver.hpp"
#include "verification/field_diff.hpp"
#include "verification/harness.hpp"

using namespace impactsph;

namespace {

struct Args {
  std::string case_file, spacing;
  std::vector<std::string> sets;
  gpu::Precision precision = gpu::Precision::Double;
  bool cuda = false;
  long steps = 100;
  bool to_end = false;
  long every = 0;
  double field_tol = -1, wave_tol = -1, length_tol = -1, residual_tol = -1;
};

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr,
               "crosscheck: %s\nusage: crosscheck CASE [--spacing X] [--set key=value ...] [--precision double|float]\n"
               "       [--steps N | --to-end] [--every K] [--field-tol R] [--wave-tol R] [--length-tol R] "
               "[--residual-tol R]\n",
               why);
  std::exit(2);
}

Args parse(int argc, char** argv) {
  Args a;
  for (int k = 1; k < argc; ++k) {
    const std::string s = argv[k];
    auto value = [&]() -> std::string {
      if (k + 1 >= argc) usage(("missing value after " + s).c_str());
      return argv[++k];
    };
    if (s == "--spacing") a.spacing = value();
    else if (s == "--set") a.sets.push_back(value());
    else if (s == "--precision") {
      const std::string p = value();
      if (p == "double") a.precision = gpu::Precision::Double;
      else if (p == "float") a.precision = gpu::Precision::Float;
      else usage("--precision takes double or float");
    } else if (s == "--steps") a.steps = std::stol(value());
    else if (s == "--to-end") a.to_end = true;
    else if (s == "--build") {
      const std::string b = value();
      if (b == "host") a.cuda = false;
      else if (b == "cuda") a.cuda = true;
      else usage("--build takes host or cuda");
    }
    else if (s == "--every") a.every = std::stol(value());
    else if (s == "--field-tol") a.field_tol = std::stod(value());
    else if (s == "--wave-tol") a.wave_tol = std::stod(value());
    else if (s == "--length-tol") a.length_tol = std::stod(value());
    else if (s == "--residual-tol") a.residual_tol = std::stod(value());
    else if (!s.empty() && s[0] != '-' && a.case_file.empty()) a.case_file = s;
    else usage(("unknown argument " + s).c_str());
  }
  if (a.case_file.empty()) usage("no case file");
  return a;
}

struct Check {
  int failures = 0;
  void row(const char* what, double value, double tol) {
    const bool bad = tol >= 0 && !(value <= tol);
    if (bad) ++failures;
    if (tol >= 0) std::printf("  %-44s %12.3e   tol %9.2e  %s\n", what, value, tol, bad ? "FAIL" : "ok");
    else std::printf("  %-44s %12.3e\n", what, value);
  }
};

// CPU seconds of all threads of this process: on a shared machine the wall time of a step also counts
// the time other programs held the cores (run with OMP_WAIT_POLICY=passive so that waiting threads sleep).
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double rel(double a, double b) { return b != 0 ? std::abs(a - b) / std::abs(b) : std::abs(a - b); }
// A body sum's difference relative to the larger of the reference's value at the end (b) and at the start
// (b0): a body that passed nearly all it carried to another (a flyer stopped by its target) keeps the
// round-off of what passed through it, which is measured against what it carried, not against the little
// left at the end.
double rel_body(double a, double b, double b0) {
  const double scale = std::max(std::abs(b), std::abs(b0));
  return scale != 0 ? std::abs(a - b) / scale : std::abs(a - b);
}

// Elastic-wave measurements (as verification/analytic_elastic_wave.cpp): the front of half the particle
// velocity behind it (10 m/s for the 20 m/s flyer), sampled every 0.5 us from 4 us, fitted by a line; and
// the mean stress -sigma_xx 10-30 mm behind the front at the end.
struct Wave {
  std::vector<double> t, front;
  double speed = 0, stress = 0;
};
constexpr double kWaveV = 10.0, kFlyer = 20e-3, kBar = 100e-3;
void wave_sample(Wave& w, const ParticleSet& p, double dx, double t) {
  const int slabs = static_cast<int>(std::lround(kBar / dx));
  const verification::Profile prof =
      verification::slab_profile(p, 0, 0.0, dx, slabs, [&](std::size_t i) { return p.vel[i].x; });
  w.t.push_back(t);
  w.front.push_back(verification::leading_crossing(prof, 0.5 * kWaveV));
}
void wave_finish(Wave& w, const ParticleSet& p, double dx) {
  w.speed = verification::fit_line(w.t, w.front).slope;
  const double front = w.front.empty() ? 0 : w.front.back();
  const int slabs = static_cast<int>(std::lround(kBar / dx));
  const verification::Profile prof = verification::slab_profile(
      p, 0, 0.0, dx, slabs, [&](std::size_t i) { return p.pressure[i] - p.dev_stress[i].xx; });
  double sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < prof.x.size(); ++k)
    if (prof.x[k] > front - 30e-3 && prof.x[k] < front - 10e-3) {
      sum += prof.value[k];
      ++count;
    }
  w.stress = count ? sum / count : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  if (args.cuda && gpu::cuda::device_count() == 0) {
    std::printf("skipped: no CUDA device%s\n", gpu::cuda_built() ? "" : " (built without CUDA)");
    return 77;
  }
  try {
    Scene ref_scene = build_scene(load_case_file(args.case_file, args.sets, args.spacing));
    Scene gpu_scene = ref_scene;
    const std::vector<Vec3d> x0 = ref_scene.particles.pos;
    reference::ReferenceSolver ref(ref_scene);
    std::unique_ptr<gpu::GpuStepper> port = args.cuda ? gpu::cuda::make_solver(gpu_scene, args.precision)
                                                      : gpu::host::make_solver(gpu_scene, args.precision);
    ParticleSet& a = gpu_scene.particles;
    ParticleSet& b = ref_scene.particles;
    const std::size_t n = b.size();
    const double end = ref_scene.spec.time.end;
    const double dx = ref_scene.spec.numerics.spacing;
    const bool wave = args.wave_tol >= 0;
    const std::vector<BodySummary> b0 = summarise_bodies(b, ref_scene.bodies.size());

    std::printf("cross-check: %s at %.3g mm, %zu particles, %s against %s, %d threads\n", ref_scene.spec.name.c_str(),
                dx * 1e3, n, port->name().c_str(), ref.name().c_str(), omp_get_max_threads());
    std::printf("\n%8s %11s | %-21s | %-21s | %-21s | %-21s\n", "step", "t [us]", "displacement L2 / max",
                "velocity L2 / max", "density L2 / max", "stress L2 / max");
    Check check;
    verification::FieldDiff worst[4];
    auto compare = [&](long step, double t) {
      const verification::FieldDiffs diffs = verification::compare_fields(a, b, x0);
      const verification::FieldDiff* d = diffs.field.data();
      std::printf("%8ld %11.5f |", step, t * 1e6);
      for (int k = 0; k < 4; ++k) {
        std::printf(" %9.2e %9.2e  |", d[k].l2, d[k].max);
        worst[k].l2 = std::max(worst[k].l2, d[k].l2);
        worst[k].max = std::max(worst[k].max, d[k].max);
      }
      std::printf("\n");
    };

    Wave wave_a, wave_b;
    double next_wave = 4e-6;
    double t = 0, contact_a = 0, contact_b = 0, wall_ref = 0, wall_port = 0, cpu_ref = 0, cpu_port = 0;
    long step = 0;
    const long every = args.every > 0 ? args.every : (args.to_end ? 50 : 10);
    while (args.to_end ? t < end * (1 - 1e-12) : step < args.steps) {
      double dt = ref.stable_time_step(b);
      if (args.to_end) dt = std::min(dt, end - t);
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = process_cpu_seconds();
      ref.step(b, dt);
      const auto t1 = std::chrono::steady_clock::now();
      const double c1 = process_cpu_seconds();
      port->step(a, dt);
      const auto t2 = std::chrono::steady_clock::now();
      const double c2 = process_cpu_seconds();
      wall_ref += std::chrono::duration<double>(t1 - t0).count();
      wall_port += std::chrono::duration<double>(t2 - t1).count();
      cpu_ref += c1 - c0;
      cpu_port += c2 - c1;
      t += dt;
      ++step;
      contact_b += ref.last_stats().contact_work;
      contact_a += port->last_stats().contact_work;
      if (wave && t >= next_wave) {
        next_wave += 0.5e-6;
        wave_sample(wave_a, a, dx, t);
        wave_sample(wave_b, b, dx, t);
      }
      if (step % every == 0) compare(step, t);
    }
    if (step % every != 0) compare(step, t);

    std::printf("\nfields, largest difference over the run (relative to the reference):\n");
    const char* names[4] = {"displacement", "velocity", "density", "stress"};
    for (int k = 0; k < 4; ++k) {
      check.row((std::string(names[k]) + " L2").c_str(), worst[k].l2, args.field_tol);
      check.row((std::string(names[k]) + " max").c_str(), worst[k].max, args.field_tol);
    }

    std::printf("\nobservables at t = %.6g us (step %ld), relative difference (body sums: rel_body):\n", t * 1e6, step);
    const std::vector<BodySummary> ba = summarise_bodies(a, ref_scene.bodies.size());
    const std::vector<BodySummary> bb = summarise_bodies(b, ref_scene.bodies.size());
    for (std::size_t k = 0; k < bb.size(); ++k) {
      const std::string body = ref_scene.bodies[k].name;
      const double pa = ba[k].mass * norm(ba[k].velocity), pb = bb[k].mass * norm(bb[k].velocity);
      const double pb0 = b0[k].mass * norm(b0[k].velocity);
      check.row((body + " momentum").c_str(), rel_body(pa, pb, pb0), args.field_tol);
      check.row((body + " kinetic energy").c_str(),
                rel_body(ba[k].kinetic_energy, bb[k].kinetic_energy, b0[k].kinetic_energy), args.field_tol);
      check.row((body + " internal energy").c_str(),
                rel_body(ba[k].internal_energy, bb[k].internal_energy, b0[k].internal_energy), args.field_tol);
    }
    if (contact_b != 0) check.row("contact work", rel(contact_a, contact_b), -1);
    const CaseObservables oa = measure_observables(gpu_scene, a), ob = measure_observables(ref_scene, b);
    if (ob.taylor_bar) {
      std::printf("  final length: gpu %.5f mm, reference %.5f mm\n", oa.final_length * 1e3, ob.final_length * 1e3);
      check.row("Taylor bar final length", rel(oa.final_length, ob.final_length), args.length_tol);
    }
    if (ob.projectile) {
      std::printf("  residual velocity: gpu %.3f m/s, reference %.3f m/s\n", oa.residual_velocity, ob.residual_velocity);
      check.row("residual velocity", rel(oa.residual_velocity, ob.residual_velocity), args.residual_tol);
    }
    if (wave) {
      wave_finish(wave_a, a, dx);
      wave_finish(wave_b, b, dx);
      std::printf("  wave speed: gpu %.2f m/s, reference %.2f m/s; stress amplitude: gpu %.4g MPa, reference %.4g MPa\n",
                  wave_a.speed, wave_b.speed, wave_a.stress * 1e-6, wave_b.stress * 1e-6);
      check.row("elastic wave speed", rel(wave_a.speed, wave_b.speed), args.wave_tol);
      check.row("elastic wave stress amplitude", rel(wave_a.stress, wave_b.stress), args.wave_tol);
    }
    std::printf("\nwall time of the steps: reference %.3f s (%.3g particle-steps/s), gpu port %.3f s (%.3g "
                "particle-steps/s, %ld sorts); ratio %.2f\n",
                wall_ref, double(n) * double(step) / wall_ref, wall_port, double(n) * double(step) / wall_port,
                port->sorts(), wall_ref / wall_port);
    std::printf("cpu time of the steps (all threads): reference %.3f s, gpu port %.3f s; ratio %.2f\n", cpu_ref,
                cpu_port, cpu_ref / cpu_port);
    std::printf("\n%s: %d tolerance%s failed\n", check.failures ? "FAIL" : "PASS", check.failures,
                check.failures == 1 ? "" : "s");
    return check.failures ? 1 : 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crosscheck: %s\n", e.what());
    return 2;
  }
}
