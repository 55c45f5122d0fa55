// impactsph: the command line of ImpactSPH.
//   impactsph run CASE.toml [--out DIR] [--threads N] [--spacing X] [--set key=value ...] [--quiet]
//                 [--backend reference|gpu] [--precision double|float]
//   impactsph run --restart DIR
//   impactsph check CASE.toml [--spacing X] [--set key=value ...]
//   impactsph ballistic-limit CASE.toml --from V1 --to V2 [--tolerance DV] [--jobs N] [--out DIR] ...
//   impactsph sweep SWEEP.toml [--jobs N] [--threads-per-run T] [--out DIR] [--emit slurm] [--collect]
//   impactsph verify [--suite fast|full] [--out DIR] [--threads N]
//   impactsph taylor-fe CASE.toml [--elements-across N] [--out DIR] [--end T] [--set key=value ...]
#include <omp.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/ballistic_limit.hpp"
#include "app/picture.hpp"
#include "app/solver_choice.hpp"
#include "app/run_args.hpp"
#include "app/sweep.hpp"
#include "app/taylor_fe.hpp"
#include "app/verify.hpp"
#include "common/case_file.hpp"
#include "common/checkpoint.hpp"
#include "common/driver.hpp"
#include "common/errors.hpp"
#include "common/output.hpp"
#include "common/scene.hpp"
#include "common/units.hpp"
#include "gpu/solver.hpp"
#include "reference/solver.hpp"

namespace fs = std::filesystem;
using namespace impactsph;

namespace {

struct CaseArgs {
  std::string case_file;
  std::string spacing;
  std::vector<std::string> sets;
};

const char* shape_name(const BodySpec& b) {
  switch (b.shape) {
    case Shape::Box: return "box";
    case Shape::Sphere: return "sphere";
    case Shape::Mesh: return "mesh";
    case Shape::Cylinder: break;
  }
  switch (b.nose) {
    case Nose::Hemispherical: return "hemi-nosed";
    case Nose::Conical: return "cone-nosed";
    case Nose::Ogival: return "ogive-nosed";
    case Nose::Flat: break;
  }
  return "cylinder";
}

// A relative difference in per cent, rounding noise shown as zero.
double percent_difference(double generated, double specified) {
  const double d = generated / specified - 1;
  return std::abs(d) < 5e-10 ? 0.0 : 100 * d;
}

// The warnings of the scene builder about bodies whose generated geometry departs from the case's.
void print_geometry_warnings(const Scene& scene, std::FILE* to) {
  for (std::size_t k = 0; k < scene.bodies.size(); ++k)
    for (const std::string& w : scene.bodies[k].warnings)
      std::fprintf(to, "warning: %s: bodies[%zu] (\"%s\"): %s\n", scene.spec.source_file.c_str(), k,
                   scene.bodies[k].name.c_str(), w.c_str());
}

void print_scene(const Scene& scene, double dt) {
  const CaseSpec& s = scene.spec;
  std::printf("case      %s (%s)\n", s.name.c_str(), s.source_file.c_str());
  if (!s.description.empty()) std::printf("          %s\n", s.description.c_str());
  std::printf("spacing   %.6g mm, h = %.6g mm (h/dx = %.3g), kernel %s\n", s.numerics.spacing * 1e3,
              s.numerics.spacing * s.numerics.h_factor * 1e3, s.numerics.h_factor,
              s.numerics.kernel == KernelKind::WendlandC2 ? "Wendland C2" : "cubic spline");
  std::printf("\n%-16s %-16s %-11s %10s %12s %10s\n", "body", "material", "shape", "particles", "mass [g]", "fixed");
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    std::size_t fixed = 0;
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
      if (scene.particles.body[i] == static_cast<int>(k) && scene.particles.fixed[i]) ++fixed;
    const BodyInfo& b = scene.bodies[k];
    std::printf("%-16s %-16s %-11s %10zu %12.6g %10zu\n", b.name.c_str(), s.materials[b.material].name.c_str(),
                shape_name(s.bodies[k]), b.particle_count, b.initial_mass * 1e3, fixed);
  }
  std::printf("%-16s %-16s %-11s %10zu\n", "total", "", "", scene.particles.size());
  std::printf("\nbodies as specified and as generated (whole bodies; each lattice is fitted to its shape)\n");
  std::printf("%-16s %-10s %14s %14s %11s\n", "body", "", "specified", "generated", "difference");
  for (const BodyInfo& b : scene.bodies) {
    std::printf("%-16s %-10s %12.6g g %12.6g g %+10.3f %%\n", b.name.c_str(), "mass", b.specified_mass * 1e3,
                b.generated_mass * 1e3, percent_difference(b.generated_mass, b.specified_mass));
    for (const BodySize& size : b.sizes)
      std::printf("%-16s %-10s %11.6g mm %11.6g mm %+10.3f %%\n", "", size.name.c_str(), size.specified * 1e3,
                  size.generated * 1e3, percent_difference(size.generated, size.specified));
    std::printf("%-16s %-10s %.6g x %.6g x %.6g mm cells (x, y, z), stretched by at most %.2f %%", "", "lattice",
                b.lattice_spacing.x * 1e3, b.lattice_spacing.y * 1e3, b.lattice_spacing.z * 1e3, 100 * b.max_stretch);
    if (std::abs(b.mass_scale - 1) > 1e-9) std::printf(", masses scaled by %.6g", b.mass_scale);
    std::printf("\n");
    if (b.coarse_particle_count > 0)
      std::printf("%-16s %-10s %.6g x %.6g x %.6g mm cells in the coarse region: %zu of its %zu particles\n", "", "coarse",
                  b.coarse_lattice_spacing.x * 1e3, b.coarse_lattice_spacing.y * 1e3, b.coarse_lattice_spacing.z * 1e3,
                  b.coarse_particle_count, b.particle_count);
  }
  for (const BodySpec& b : s.bodies)
    if (b.coarse_off_above > 0)
      std::printf("%-16s %-10s none: the case builds its coarse region at spacings up to %.6g mm only "
                  "([bodies.coarse] max_spacing)\n",
                  b.name.c_str(), "coarse", b.coarse_off_above * 1e3);
  print_geometry_warnings(scene, stdout);
  for (const SymmetryPlaneSpec& p : s.symmetry)
    std::printf("%s plane %c = %.6g mm\n", p.wall ? "wall     " : "symmetry ", "xyz"[p.axis], p.position * 1e3);
  const double steps = dt > 0 ? s.time.end / dt : 0;
  std::printf("\ntime      end %.6g us, output every %.6g us\n", s.time.end * 1e6, s.time.output_interval * 1e6);
  const bool leapfrog = s.numerics.integrator == Integrator::Leapfrog;
  std::printf("step      estimated dt %.4g ns (CFL %.3g, %s), about %.0f steps, %.3g particle-steps, %.3g force "
              "evaluations\n",
              dt * 1e9, s.numerics.cfl, leapfrog ? "leapfrog" : "midpoint rule", steps,
              steps * static_cast<double>(scene.particles.size()), leapfrog ? steps + 1 : 2 * steps);
}

Scene load_scene(const CaseArgs& a) {
  CaseSpec spec = load_case_file(a.case_file, a.sets, a.spacing);
  return build_scene(spec);
}

// The solver of --backend and --precision: the reference (double only) or the gpu port, which runs its
// host build on a machine without a CUDA device and says so in one line.
std::unique_ptr<Stepper> make_run_stepper(const Scene& scene, const std::string& backend, const std::string& precision) {
  std::string note;
  std::unique_ptr<Stepper> s = make_stepper(scene, backend, precision, &note);
  if (!note.empty()) std::fprintf(stderr, "note: %s\n", note.c_str());
  return s;
}

int run_command(CaseArgs args, std::string out, int threads, bool quiet, const std::string& restart_dir,
                const std::vector<std::string>& argv_all, std::string backend, std::string precision,
                std::string end) {
  if (!end.empty() && restart_dir.empty())
    throw std::runtime_error("--end " + end + " continues a run to a later end time and goes with --restart DIR; "
                             "a new run takes its end from the case file, e.g. --set time.end=\"600 us\"");
  nlohmann::json run_record;
  bool end_from_record = false;
  if (!restart_dir.empty()) {
    const fs::path run_json = fs::path(restart_dir) / "run.json";
    std::ifstream in(run_json);
    if (!in) throw std::runtime_error("cannot restart: " + run_json.string() + " is missing (is " + restart_dir +
                                      " the --out folder of an earlier run?)");
    const nlohmann::json j = nlohmann::json::parse(in);
    run_record = j;
    if (end.empty()) {
      end = j.value("end", "");  // a run extended once keeps its later end
      end_from_record = true;
    }
    if (args.case_file.empty()) {
      args.case_file = j.at("case_file").get<std::string>();
      args.spacing = j.at("spacing").get<std::string>();
      args.sets = j.at("set").get<std::vector<std::string>>();
    }
    out = restart_dir;
    if (threads <= 0) threads = j.value("threads", 0);
    if (backend.empty()) backend = j.value("backend", "reference");
    if (precision.empty()) precision = j.value("precision", "double");
  }
  if (backend.empty()) backend = "reference";
  if (precision.empty()) precision = "double";
  if (args.case_file.empty()) throw std::runtime_error("run needs a case file (impactsph run CASE.toml) or --restart DIR");
  if (threads > 0) omp_set_num_threads(threads);
  threads = omp_get_max_threads();

  Scene scene = load_scene(args);
  print_geometry_warnings(scene, stderr);
  if (out.empty()) out = (fs::path("runs") / scene.spec.name).string();
  if (!end.empty()) {
    // --end: the same run (same fingerprint, same physics) continued past the case's time.end.
    double t_end = 0;
    if (end.find_first_not_of("0123456789.eE+- \t") == std::string::npos)
      throw std::runtime_error("--end " + end + ": give the time with its unit, e.g. --end 600us (a bare number "
                               "would be seconds)");
    try {
      t_end = parse_quantity(end, Dimension::Time);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(std::string("--end: ") + e.what());
    }
    const double t_now = end_from_record ? 0.0 : read_checkpoint(checkpoint_path(out)).clock.time;
    if (!(t_end > t_now))
      throw std::runtime_error("--end " + end + ": the run in " + out + " is already at " +
                               format_quantity(t_now, Dimension::Time) + "; give a later end time");
    scene.spec.time.end = t_end;
    run_record["end"] = end;
    write_text_atomic(fs::path(out) / "run.json", run_record.dump(2) + "\n");
  }
  RunOptions opt;
  opt.out_dir = out;
  opt.quiet = quiet;
  opt.threads = threads;
  opt.fingerprint = run_fingerprint(args.case_file, args.spacing, args.sets);
  opt.restart = !restart_dir.empty();
  opt.command_line = argv_all;
  fs::create_directories(opt.out_dir);
  if (!opt.restart) {
    nlohmann::json j{{"case_file", fs::absolute(args.case_file).string()}, {"spacing", args.spacing}, {"set", args.sets},
                     {"threads", threads}, {"backend", backend}, {"precision", precision}};
    write_text_atomic(opt.out_dir / "run.json", j.dump(2) + "\n");
  }

  const std::unique_ptr<Stepper> solver = make_run_stepper(scene, backend, precision);
  if (!quiet) {
    std::printf("ImpactSPH: %s, %zu particles, %d threads, %s, output in %s%s\n", scene.spec.name.c_str(),
                scene.particles.size(), threads, solver->name().c_str(), opt.out_dir.string().c_str(),
                opt.restart ? " (restart)" : "");
    std::fflush(stdout);
  }
  const RunResult r = run_simulation(scene, *solver, opt);
  if (r.interrupted) {
    std::printf("stopped at t = %.6g us (step %lld); checkpoint written. Continue with:\n  impactsph run --restart %s\n",
                r.clock.time * 1e6, static_cast<long long>(r.clock.step), opt.out_dir.string().c_str());
    return 130;
  }
  std::printf("done: t = %.6g us in %lld steps, %.1f s wall, %.3g particle-steps/s, %.1f neighbours per particle\n",
              r.clock.time * 1e6, static_cast<long long>(r.clock.step), r.wall_seconds, r.particle_steps_per_second,
              r.mean_neighbours);
  for (std::size_t k = 0; k < r.bodies.size(); ++k) {
    const BodySummary& b = r.bodies[k];
    std::printf("  %-14s mass %.6g g  velocity (%.4g, %.4g, %.4g) m/s  kinetic %.6g J  internal %.6g J\n",
                scene.bodies[k].name.c_str(), b.mass * 1e3, b.velocity.x, b.velocity.y, b.velocity.z, b.kinetic_energy,
                b.internal_energy);
  }
  const double e0 = r.initial_totals.total_energy();
  const double e1 = r.final_totals.total_energy() + r.clock.contact_work;
  if (e0 != 0) std::printf("  energy drift %.3g%% (contact took %.6g J)\n", 100 * (e1 - e0) / std::abs(e0), r.clock.contact_work);
  const double k0 = r.initial_totals.kinetic_energy;
  if (k0 > 0) {
    const double plastic = r.final_totals.plastic_work - r.initial_totals.plastic_work;
    const double other = r.final_totals.internal_energy - r.initial_totals.internal_energy - plastic;
    std::printf("  of the initial kinetic energy, %.1f %% is plastic work and %.1f %% other internal energy "
                "(viscous heat, stored elastic)\n", 100 * plastic / k0, 100 * other / k0);
  }
  const CaseObservables& o = r.observables;
  if (r.settled)
    std::printf(r.held ? "  stopped early: the target held the projectile (stopped or moving back, no target particle "
                         "failing, for a settle window)\n"
                       : "  stopped early: the residual velocity was steady\n");
  for (const ObservableRow& row : observable_rows(o)) std::printf("%s\n", format_observable(row).c_str());
  bool picture = false;
  if (scene.spec.output.picture) {
    const std::string warning = write_and_draw_picture(opt.out_dir, "picture", scene, scene.particles, r.clock.time,
                                                       scene.spec.output.picture_field);
    if (!warning.empty()) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    picture = warning.empty();
  }
  std::printf("results: %s (summary.json, history_*.csv, particles.pvd%s)\n", opt.out_dir.string().c_str(),
              picture ? ", picture.png" : "");
  return 0;
}

int check_command(const CaseArgs& args) {
  Scene scene = load_scene(args);
  reference::ReferenceSolver solver(scene);
  const double dt = solver.stable_time_step(scene.particles);
  print_scene(scene, dt);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> argv_all(argv, argv + argc);
  CLI::App app{
      "ImpactSPH: high-velocity impact of solids with 3D SPH.\n\n"
      "  impactsph check cases/elastic-wave/case.toml      validate a case and print its scene\n"
      "  impactsph run cases/elastic-wave/case.toml        run it (results in runs/<case name>/)\n"
      "  impactsph run --restart runs/elastic-wave         continue a stopped run from its checkpoint\n"
      "  impactsph ballistic-limit cases/plate-8mm/case.toml --from 100 --to 300   find the ballistic limit\n"
      "  impactsph sweep cases/sweeps/hugoniot-spacing.toml   run a case over a set of parameters\n"
      "  impactsph verify --suite fast                         convergence report against closed forms\n"
      "  impactsph taylor-fe cases/taylor-bar/case.toml        the Taylor bar by axisymmetric finite elements\n\n"
      "Values take units: --spacing 0.5mm, --set projectile.velocity=\"298 m/s\". Case files: docs/case-files.md"};
  app.require_subcommand(1);

  CaseArgs run_args, check_args;
  std::string out, restart_dir, backend, precision, run_end;
  int threads = 0;
  bool quiet = false;
  auto add_case_options = [](CLI::App* sub, CaseArgs& a) {
    sub->add_option("--spacing", a.spacing, "particle spacing, overrides numerics.spacing (e.g. 0.5mm)");
    sub->add_option("--set", a.sets, "override a case value: KEY=VALUE, e.g. projectile.velocity=\"298 m/s\", "
                                     "numerics.cfl=0.1 (repeatable)")
        ->take_all();
  };
  CLI::App* run = app.add_subcommand("run", "run a case (or continue one with --restart DIR)");
  run->add_option("case", run_args.case_file, "case file (TOML)")->check(CLI::ExistingFile);
  run->add_option("--out", out, "output folder (default runs/<case name>)");
  run->add_option("--threads", threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  run->add_flag("--quiet,-q", quiet, "no banner and no progress line");
  run->add_option("--restart", restart_dir, "continue the run whose output folder is DIR from its last checkpoint");
  run->add_option("--end", run_end, "with --restart: continue the run to this later end time (e.g. 600us); "
                                    "later restarts keep it");
  run->add_option("--backend", backend, "solver: reference (default) or gpu (the CUDA port; its host build without a GPU)")
      ->check(CLI::IsMember({"reference", "gpu"}));
  run->add_option("--precision", precision, "double (default) or float (gpu backend only)")
      ->check(CLI::IsMember({"double", "float"}));
  add_case_options(run, run_args);
  CLI::App* check = app.add_subcommand("check", "validate a case file and print the scene it builds");
  check->add_option("case", check_args.case_file, "case file (TOML)")->required()->check(CLI::ExistingFile);
  add_case_options(check, check_args);
  BallisticOptions ballistic_opt;
  CaseArgs ballistic_args;
  CLI::App* ballistic = app.add_subcommand(
      "ballistic-limit", "bracket the ballistic limit of a perforation case with parallel runs and fit the "
                         "Recht-Ipson curve (docs/ballistic-limit.md)");
  ballistic->add_option("case", ballistic_args.case_file, "case file (TOML) with [observables] projectile and target")
      ->required()
      ->check(CLI::ExistingFile);
  ballistic->add_option("--from", ballistic_opt.from, "impact speed that does not perforate (\"150 m/s\"; bare: m/s)")
      ->required();
  ballistic->add_option("--to", ballistic_opt.to, "impact speed that perforates")->required();
  ballistic->add_option("--tolerance", ballistic_opt.tolerance, "stop when the bracket is this narrow")
      ->capture_default_str();
  ballistic->add_option("--jobs", ballistic_opt.jobs, "runs at a time (default: one per core)")
      ->check(CLI::PositiveNumber);
  ballistic->add_option("--out", ballistic_opt.out, "output folder (default runs/<case name>-ballistic)");
  ballistic->add_flag("--quiet,-q", ballistic_opt.quiet, "print only the results, no line per run");
  ballistic->add_option("--backend", ballistic_opt.backend, "solver of every run: reference (default) or gpu (the port)")
      ->check(CLI::IsMember({"reference", "gpu"}));
  ballistic->add_option("--precision", ballistic_opt.precision, "double (default) or float (gpu backend only)")
      ->check(CLI::IsMember({"double", "float"}));
  ballistic->add_option("--coarse", ballistic_opt.coarse_spacing,
                        "first the same search at this coarser spacing (\"2 mm\"), then this one from its bracket");
  ballistic->add_option("--coarse-margin", ballistic_opt.coarse_margin,
                        "share of the coarse limit added on each side of the coarse bracket")
      ->capture_default_str();
  ballistic->add_option("--split", ballistic_opt.split,
                        "thirds (even splits) or recht-ipson (splits at the limit the perforating runs point to)")
      ->capture_default_str();
  add_case_options(ballistic, ballistic_args);

  SweepOptions sweep_opt;
  CLI::App* sweep = app.add_subcommand(
      "sweep", "run a case over a set of parameters, several runs at a time, resumable; or write a Slurm job array "
               "(docs/sweeps-and-verification.md)");
  sweep->add_option("sweep_file", sweep_opt.sweep_file, "sweep file (TOML)")->required()->check(CLI::ExistingFile);
  sweep->add_option("--out", sweep_opt.out, "folder of the run folders and the table (default runs/<sweep name>)");
  sweep->add_option("--jobs", sweep_opt.jobs, "runs at a time (default: cores / threads per run)")
      ->check(CLI::PositiveNumber);
  sweep->add_option("--threads-per-run", sweep_opt.threads_per_run, "OpenMP threads of each run")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sweep->add_option("--emit", sweep_opt.emit, "write a job script instead of running: slurm")
      ->check(CLI::IsMember({"slurm"}));
  sweep->add_flag("--collect", sweep_opt.collect, "only build the table (sweep.csv, sweep.md) from the run folders");
  sweep->add_flag("--retry-failed", sweep_opt.retry_failed, "run again the runs that failed in an earlier sweep");

  VerifyOptions verify_opt;
  CLI::App* verify = app.add_subcommand(
      "verify", "run the analytic cases over spacings, fit the observed order, write report.md with plots "
                "(docs/sweeps-and-verification.md)");
  verify->add_option("--suite", verify_opt.suite, "fast: elastic wave and Hugoniot; full: + Taylor bar, 8 mm plate, "
                                                  "ceramic tile, CFL sensitivity; smoke: 3 coarse elastic-wave "
                                                  "runs (CI)")
      ->capture_default_str()
      ->check(CLI::IsMember({"fast", "full", "smoke"}));
  verify->add_option("--out", verify_opt.out, "report folder (default runs/verify-<suite>)");
  verify->add_option("--threads", verify_opt.threads, "OpenMP threads of each run (default: all cores)")
      ->check(CLI::PositiveNumber);
  verify->add_option("--cases", verify_opt.cases, "folder of the case folders (default: the source tree's cases/)");

  TaylorFeOptions fe_opt;
  CLI::App* taylor_fe = app.add_subcommand(
      "taylor-fe", "a Taylor bar (one cylinder on a wall) by axisymmetric finite elements with the case's material "
                   "models: summary.json, profile.csv, history.csv, picture.png (verification/fe2d/README.md)");
  taylor_fe->add_option("case", fe_opt.case_file, "case file (TOML) of one cylinder and a wall or symmetry plane at its end")
      ->required()
      ->check(CLI::ExistingFile);
  taylor_fe->add_option("--elements-across", fe_opt.numerics.elements_across, "elements across the radius")
      ->capture_default_str()
      ->check(CLI::Range(1, 1024));
  taylor_fe->add_option("--out", fe_opt.out, "output folder (default runs/<case name>-fe)");
  taylor_fe->add_option("--end", fe_opt.end, "end time with its unit (default the case's time.end), e.g. 40us");
  taylor_fe->add_option("--cfl", fe_opt.numerics.cfl, "the step as a fraction of the least element's stable step")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 1.0));
  taylor_fe->add_option("--hourglass", fe_opt.numerics.hourglass_stiffness,
                        "stiffness coefficient kappa of the Flanagan-Belytschko hourglass control")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  taylor_fe->add_option("--set", fe_opt.sets, "override a case value: KEY=VALUE, e.g. bar.velocity=\"200 m/s\" "
                                              "(repeatable)")
      ->take_all();
  taylor_fe->add_flag("--quiet,-q", fe_opt.quiet, "no banner");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (*run) return run_command(run_args, out, threads, quiet, restart_dir, argv_all, backend, precision, run_end);
    if (*sweep) return sweep_command(sweep_opt);
    if (*verify) {
      verify_opt.command_line = argv_all;
      return verify_command(verify_opt);
    }
    if (*taylor_fe) {
      fe_opt.command_line = argv_all;
      return taylor_fe_command(fe_opt);
    }
    if (*ballistic) {
      ballistic_opt.case_file = ballistic_args.case_file;
      ballistic_opt.spacing = ballistic_args.spacing;
      ballistic_opt.sets = ballistic_args.sets;
      ballistic_opt.command_line = argv_all;
      return ballistic_limit_command(ballistic_opt);
    }
    return check_command(check_args);
  } catch (const CaseError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const DivergenceError& e) {
    std::fprintf(stderr, "\nerror: %s\nThe last good state was written (last frame and checkpoint.bin).\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
