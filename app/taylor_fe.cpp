#include "app/taylor_fe.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "app/gnuplot.hpp"
#include "common/case_file.hpp"
#include "common/case_observables.hpp"
#include "common/driver.hpp"
#include "common/output.hpp"
#include "common/units.hpp"

namespace fs = std::filesystem;

namespace impactsph {
namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// A time given with its unit (--end 40us); a bare number is refused, as `run --end` refuses it.
double parse_end(const std::string& end) {
  if (end.find_first_not_of("0123456789.eE+- \t") == std::string::npos)
    throw std::runtime_error("--end " + end + ": give the time with its unit, e.g. --end 40us (a bare number would be "
                             "seconds)");
  double t = 0;
  try {
    t = parse_quantity(end, Dimension::Time);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string("--end: ") + e.what());
  }
  if (!(t > 0)) throw std::runtime_error("--end " + end + ": must be later than 0");
  return t;
}

// The rows of summary.json's observables, as `impactsph run` writes a Taylor bar's (common/case_observables).
std::vector<ObservableRow> observable_rows(const fe2d::Observables& o) {
  using K = ObservableRow::Kind;
  return {{"final_length", o.final_length, "mm", 1e3, 4, K::Number, "m"},
          {"impact_face_diameter", o.impact_face_diameter, "mm", 1e3, 4, K::Number, "m"}};
}

std::string csv_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string profile_csv(const fe2d::Simulation& s) {
  std::string t = "height_m,radius_m\n";
  for (const auto& [z, r] : fe2d::outer_profile(s)) t += csv_number(z) + "," + csv_number(r) + "\n";
  return t;
}

std::string history_csv(const fe2d::Simulation& s) {
  std::string t = "time_s,length_m,face_radius_m,axial_velocity_m_s,kinetic_J,internal_J,hourglass_J,wall_J,total_J,"
                  "plastic_work_J\n";
  for (const fe2d::HistoryRow& h : s.history()) {
    const double row[] = {h.time,           h.length,          h.face_radius,        h.axial_velocity,
                          h.energy.kinetic, h.energy.internal, h.energy.hourglass,   h.energy.wall,
                          h.energy.total(), h.energy.plastic_work};
    for (std::size_t k = 0; k < std::size(row); ++k) t += (k ? "," : "") + csv_number(row[k]);
    t += "\n";
  }
  return t;
}

// The largest hourglass energy against the internal energy over the history, where the internal energy is at
// least 1 % of the initial kinetic energy (before, both are round-off).
double peak_hourglass_share(const fe2d::Simulation& s) {
  double peak = 0;
  for (const fe2d::HistoryRow& h : s.history())
    if (h.energy.internal > 0.01 * s.initial_energy()) peak = std::max(peak, h.energy.hourglass / h.energy.internal);
  return peak;
}

// picture.dat: each element as a closed polygon (r [mm], z [mm], plastic strain) in its own block, the section
// drawn whole (the half-plane and its mirror r -> -r).
std::string picture_data(const fe2d::Simulation& s) {
  std::ostringstream d;
  d << "# The deformed mesh drawn by picture.gp: each element a closed polygon, r [mm], z [mm] (height above the "
       "wall), plastic strain\n";
  char line[96];
  for (double side : {1.0, -1.0})
    for (int j = 0; j < s.nz(); ++j)
      for (int i = 0; i < s.nr(); ++i) {
        const std::size_t c[5] = {s.node_index(i, j), s.node_index(i + 1, j), s.node_index(i + 1, j + 1),
                                  s.node_index(i, j + 1), s.node_index(i, j)};
        const double eps = s.elements()[s.element_index(i, j)].plastic_strain;
        for (std::size_t k : c) {
          std::snprintf(line, sizeof line, "%.6g %.6g %.6g\n", side * s.nodes()[k].r * 1e3, s.nodes()[k].z * 1e3, eps);
          d << line;
        }
        d << "\n";
      }
  return d.str();
}

// The mesh's lines are drawn up to this many elements across the radius; finer, they would hide the colours.
constexpr int kMeshLinesUpTo = 32;

std::string picture_script(const fe2d::Simulation& s, const fs::path& png) {
  double r_max = 0, z_max = 0, eps_max = 0;
  for (const fe2d::Node& n : s.nodes()) r_max = std::max(r_max, n.r), z_max = std::max(z_max, n.z);
  for (const fe2d::Element& e : s.elements()) eps_max = std::max(eps_max, e.plastic_strain);
  const double pad = 0.05 * std::max(2 * r_max, z_max) * 1e3;
  const double x = r_max * 1e3 + pad, y0 = -pad, y1 = z_max * 1e3 + pad;
  const int width = 900;
  const int height = std::clamp(static_cast<int>(std::lround(650.0 * (y1 - y0) / (2 * x))) + 200, 450, 1500);
  const fe2d::Bar& b = s.bar();
  std::ostringstream g;
  g << "# Drawn by impactsph taylor-fe: `gnuplot picture.gp` in this folder redraws picture.png from picture.dat.\n"
    << "set terminal pngcairo size " << width << "," << height << " noenhanced font 'Sans,12'\n"
    << "set output " << gp_quote(png.string()) << "\n"
    << "set title " << gp_quote(b.case_name + " at t = " + fmt("%.4g", s.time() * 1e6) + " µs by finite elements, " +
                                std::to_string(s.nr()) + " across the radius, coloured by plastic strain")
    << ".\"\\n\"." << gp_quote("section through the axis; the wall (" +
                               std::string(b.plane_holds ? "a plane of symmetry" : "a wall that does not pull") +
                               ") at z = 0")
    << "\n"
    << "set xlabel 'r [mm]'\nset ylabel 'z [mm], height above the wall'\n"
    << "set view map\nset size ratio -1\nunset key\nset tics out\n"
    << "set xrange [" << gp_number(-x) << ":" << gp_number(x) << "]\n"
    << "set yrange [" << gp_number(y0) << ":" << gp_number(y1) << "]\n"
    << "set cbrange [0:" << gp_number(eps_max > 0 ? eps_max : 1.0) << "]\n"
    << "set cblabel 'plastic strain [-]'\n"
    << "set palette defined (0 '#f0f0f0', 0.2 '#fde08a', 0.45 '#f99b3e', 0.7 '#d9480f', 1 '#6b0f1a')\n"
    << (s.nr() <= kMeshLinesUpTo ? "set pm3d border lc rgb '#606060' lw 0.4\n" : "")
    << "splot 'picture.dat' using 1:2:3 with polygons fillcolor palette z\n"
    << "unset output\n";
  return g.str();
}

void write_summary(const TaylorFeOptions& opt, const fe2d::Simulation& s, const fs::path& out, double wall_seconds) {
  const fe2d::HistoryRow& now = s.now();
  const double e0 = s.initial_energy(), e1 = now.energy.total();
  double peak_strain = 0, peak_temperature = 0;
  for (const fe2d::Element& e : s.elements()) {
    peak_strain = std::max(peak_strain, e.plastic_strain);
    peak_temperature = std::max(peak_temperature, e.temperature);
  }
  const fe2d::Bar& b = s.bar();
  const fe2d::Options& o = s.options();
  nlohmann::json j;
  j["case"] = b.case_name;
  j["case_file"] = b.case_file;
  j["command_line"] = opt.command_line;
  j["solver"] = "fe2d: explicit axisymmetric finite elements (4-node quadrilaterals, volume-averaged gradient, "
                "Flanagan-Belytschko hourglass stiffness, central differences; verification/fe2d/README.md)";
  j["hardware"] = {{"cpu", cpu_model()}, {"threads", 1}};
  j["elements"] = s.elements().size();
  j["nodes"] = s.nodes().size();
  j["elements_across"] = s.nr();
  j["elements_along"] = s.nz();
  j["element_size_m"] = b.radius / s.nr();
  j["wall"] = b.plane_holds ? "plane of symmetry" : "wall";
  j["numerics"] = {{"cfl", o.cfl},
                   {"hourglass_stiffness", o.hourglass_stiffness},
                   {"bulk_viscosity_linear", o.bulk_linear},
                   {"bulk_viscosity_quadratic", o.bulk_quadratic}};
  j["steps"] = s.steps();
  j["simulated_time_s"] = s.time();
  j["end_time_s"] = s.end_time();
  j["completed"] = true;
  j["wall_time_s"] = wall_seconds;
  j["element_steps_per_second"] =
      wall_seconds > 0 ? static_cast<double>(s.elements().size()) * static_cast<double>(s.steps()) / wall_seconds : 0.0;
  j["energy"] = {{"kinetic_J", now.energy.kinetic},     {"internal_J", now.energy.internal},
                 {"hourglass_J", now.energy.hourglass}, {"wall_J", now.energy.wall},
                 {"plastic_work_J", now.energy.plastic_work},
                 {"peak_hourglass_over_internal", peak_hourglass_share(s)}};
  j["totals"] = {{"initial_energy_J", e0}, {"final_energy_J", e1}, {"energy_drift_relative", (e1 - e0) / e0}};
  j["energy_partition"] = {{"initial_kinetic_energy_J", e0},
                           {"plastic_work_J", now.energy.plastic_work},
                           {"other_internal_energy_J", now.energy.internal - now.energy.plastic_work},
                           {"plastic_work_share", now.energy.plastic_work / e0},
                           {"other_internal_share", (now.energy.internal - now.energy.plastic_work) / e0}};
  j["peak_plastic_strain"] = peak_strain;
  j["peak_temperature_K"] = peak_temperature;
  j["final_axial_velocity_m_s"] = now.axial_velocity;
  nlohmann::json obs = nlohmann::json::object(), units = nlohmann::json::object();
  for (const ObservableRow& row : observable_rows(fe2d::measure(s))) {
    obs[row.name] = row.value;
    units[row.name] = row.si_unit;
  }
  j["observables"] = obs;
  j["observable_units"] = units;
  write_text_atomic(out / "summary.json", j.dump(2) + "\n");
}

}  // namespace

TaylorFeResult run_taylor_fe(const TaylorFeOptions& opt) {
  const CaseSpec spec = load_case_file(opt.case_file, opt.sets);
  const fe2d::Bar bar = fe2d::bar_from_case(spec);
  fe2d::Options numerics = opt.numerics;
  if (!opt.end.empty()) numerics.end_time = parse_end(opt.end);
  TaylorFeResult r;
  r.out = opt.out.empty() ? fs::path("runs") / (spec.name + "-fe") : fs::path(opt.out);
  fs::create_directories(r.out);

  fe2d::Simulation sim(bar, numerics);
  if (!opt.quiet) {
    std::printf("taylor-fe: %s, %zu elements (%d across the radius, %d along), output in %s\n", spec.name.c_str(),
                sim.elements().size(), sim.nr(), sim.nz(), r.out.string().c_str());
    std::fflush(stdout);
  }
  const auto t0 = std::chrono::steady_clock::now();
  sim.run();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  write_text_atomic(r.out / "profile.csv", profile_csv(sim));
  write_text_atomic(r.out / "history.csv", history_csv(sim));
  write_summary(opt, sim, r.out, r.wall_seconds);
  if (opt.picture) {
    write_text_atomic(r.out / "picture.dat", picture_data(sim));
    r.picture_warning = draw_gnuplot(r.out / "picture.png", r.out / "picture.gp",
                                     [&](const fs::path& png) { return picture_script(sim, png); });
  }
  r.observables = fe2d::measure(sim);
  r.elements_across = sim.nr();
  r.elements = static_cast<int>(sim.elements().size());
  r.steps = sim.steps();
  r.energy_drift = (sim.now().energy.total() - sim.initial_energy()) / sim.initial_energy();
  return r;
}

int taylor_fe_command(const TaylorFeOptions& opt) {
  const TaylorFeResult r = run_taylor_fe(opt);
  std::printf("done: %d elements, %ld steps, %.1f s wall, energy drift %.3g %%\n", r.elements, r.steps, r.wall_seconds,
              100 * r.energy_drift);
  for (const ObservableRow& row : observable_rows(r.observables)) std::printf("%s\n", format_observable(row).c_str());
  if (!r.picture_warning.empty()) std::fprintf(stderr, "warning: %s\n", r.picture_warning.c_str());
  std::printf("results: %s (summary.json, profile.csv, history.csv%s)\n", r.out.string().c_str(),
              opt.picture && r.picture_warning.empty() ? ", picture.png" : "");
  return 0;
}

}  // namespace impactsph
