// impactsph verify, the plots: convergence, observables against spacing, and the speed-against-error study
// (what an answer of a given accuracy costs; app/verify_parts.hpp).
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
#include "common/case_file.hpp"
#include "common/driver.hpp"
#include "common/expected.hpp"
#include "gpu/solver.hpp"
#include "reference/solver.hpp"

namespace impactsph::verify_detail {

// ---------------------------------------------------------------------------------------------------
// Plots

const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

std::string header(const fs::path& png, const std::string& title, const std::string& xlabel, const std::string& ylabel) {
  std::ostringstream g;
  g << "# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.\n"
    << "set terminal pngcairo size 1000,750 enhanced font 'Sans,11'\n"
    << "set output " << gp_quote(png.string()) << "\n"
    << "set title " << gp_quote(title) << " noenhanced\n"
    << "set xlabel " << gp_quote(xlabel) << "\nset ylabel " << gp_quote(ylabel) << "\n"
    << "set grid\nset key below left Left reverse noenhanced\n";
  return g.str();
}

// Error against spacing in log-log, each series with its fitted power law.
std::string convergence_script(const Report& r, const fs::path& png) {
  std::ostringstream g;
  g << header(png, "Convergence against the closed forms (|relative error| against spacing)", "spacing h [mm]",
              "|relative error|")
    << "set logscale xy\nset format y '10^{%L}'\n";
  std::vector<std::string> plots;
  int k = 0;
  for (const std::string& s : series_names(r.errors, true)) {
    const std::vector<Point> pts = of_series(r.errors, s);
    std::ostringstream d;
    for (const Point& p : pts)
      if (p.value != 0) d << gp_number(p.spacing * 1e3) << " " << gp_number(std::abs(p.value)) << "\n";
    const std::string block = "$s" + std::to_string(k);
    g << block << " << EOD\n" << d.str() << "EOD\n";
    const std::string colour = kColours[k % 8];
    const Order o = fit_order(pts);
    plots.push_back(block + " u 1:2 w p pt " + std::to_string(5 + 2 * (k % 4)) + " ps 1.4 lc rgb '" + colour + "' t " +
                    gp_quote(s + (o.ok ? ": order " + fmt("%.2f", o.p) : "")));
    if (o.ok)
      plots.push_back("exp(" + gp_number(o.log_c) + ")*x**(" + gp_number(o.p) + ") w l lw 1.5 dt 2 lc rgb '" + colour +
                      "' notitle");
    ++k;
  }
  g << "plot ";
  for (std::size_t i = 0; i < plots.size(); ++i) g << (i ? ", \\\n     " : "") << plots[i];
  g << "\nunset output\n";
  return g.str();
}

// ---------------------------------------------------------------------------------------------------
// Speed against error, per case: what an answer of a given accuracy costs


const char* const kReadmeTargets = "README.md, \"How far the answers go\"";

std::vector<Study> studies() {
  const double plate = recht_ipson(g_experiments.plate_curve, kPlateSpeed);
  auto exp_label = [](const char* name, double v, const char* unit) {
    return std::string(name) + " (experiment " + fmt("%.4g", v) + " " + unit + ")";
  };
  return {
      {"Elastic wave (cases/elastic-wave-convergence)", "elastic_wave", "the closed form",
       "verification/analytic_elastic_wave.cpp; the velocity profile's error need only fall with the spacing",
       {{"elastic wave: wave speed", "wave speed (c_L)", 0.01},
        {"elastic wave: stress amplitude", "stress amplitude (rho c_L v)", 0.03},
        {"elastic wave: velocity profile L1", "velocity profile L1"}},
       {{"Elastic wave", {0, 1, 2}}}},
      {"Hugoniot, 4340 steel (cases/hugoniot-4340)", "hugoniot", "the closed form",
       "verification/analytic_hugoniot.cpp",
       {{"Hugoniot 500 m/s: shock pressure", "500 m/s: shock pressure", 0.03},
        {"Hugoniot 500 m/s: shock speed", "500 m/s: shock speed", 0.03},
        {"Hugoniot 1000 m/s: shock pressure", "1000 m/s: shock pressure", 0.03},
        {"Hugoniot 1000 m/s: shock speed", "1000 m/s: shock speed", 0.03}},
       {{"Hugoniot at 500 m/s", {0, 1}}, {"Hugoniot at 1000 m/s", {2, 3}}}},
      {"Taylor bar, OFHC copper at 190 m/s (cases/taylor-bar)", "taylor_bar", "the experiment",
       "cases/taylor-bar/expected.toml",
       {{"Taylor bar: final length", exp_label("final length", g_experiments.taylor_length * 1e3, "mm"),
         g_experiments.taylor_length_tolerance, true}},
       {{"Taylor bar", {0}}}},
      {"8 mm Weldox 460 E plate at 298 m/s (cases/plate-8mm)", "plate_8mm", "the experiments' Recht-Ipson curve",
       kReadmeTargets + std::string("; the curve from cases/plate-8mm/expected.toml"),
       {{"8 mm plate at 298 m/s: residual velocity", exp_label("residual velocity", plate, "m/s"), kPlateResidualTarget,
         true}},
       {{"8 mm plate at 298 m/s", {0}}}},
      {"Ceramic tile, tungsten rod at 903.9 m/s (cases/ceramic-tile)", "ceramic_tile", "the experiment",
       "cases/ceramic-tile/expected.toml",
       {{"ceramic tile: residual velocity", exp_label("residual velocity", g_experiments.tile_velocity, "m/s"),
         g_experiments.tile_velocity_tolerance, true},
        {"ceramic tile: residual mass", exp_label("residual mass", g_experiments.tile_mass * 1e3, "g"),
         g_experiments.tile_mass_tolerance, true}},
       {{"Ceramic tile", {0, 1}}}},
  };
}

// The points of a measure, as relative errors against the closed form or the experiment.
std::vector<Point> measure_points(const Report& r, const Measure& m) {
  std::vector<Point> out;
  for (const Point& p : m.observable ? r.observables : r.errors)
    if (p.series == m.series) {
      Point q = p;
      if (m.observable) q.value = p.value / validation_observable(m.series).experiment - 1;
      out.push_back(q);
    }
  return out;
}

bool study_has_points(const Report& r, const Study& st) {
  for (const Measure& m : st.measures)
    if (!measure_points(r, m).empty()) return true;
  return false;
}

// The solvers of a study's points in order of appearance (reference first where it ran).
std::vector<std::string> study_solvers(const Report& r, const Study& st) {
  std::vector<std::string> out;
  for (const Measure& m : st.measures)
    for (const Point& p : measure_points(r, m))
      if (std::find(out.begin(), out.end(), solver_label(p)) == out.end()) out.push_back(solver_label(p));
  return out;
}

std::string spacing_mm(double m) { return fmt("%.5g", m * 1e3); }


std::vector<StudyRun> question_runs(const Report& r, const Study& st, const Question& q) {
  std::vector<StudyRun> runs;
  for (std::size_t k = 0; k < q.measures.size(); ++k)
    for (const Point& p : measure_points(r, st.measures[q.measures[k]])) {
      auto it = std::find_if(runs.begin(), runs.end(), [&](const StudyRun& s) {
        return s.solver == solver_label(p) && std::abs(s.spacing / p.spacing - 1) < 1e-9;
      });
      if (it == runs.end()) {
        runs.push_back({p.spacing, solver_label(p), p.cost, std::vector<double>(q.measures.size(), std::nan(""))});
        it = runs.end() - 1;
      }
      it->errors[k] = p.value;
    }
  return runs;
}

std::string percent(double target) { return fmt("%.3g", 100 * target) + " %"; }

// "the reference (double)" or "the gpu port host build (float)": a solver label in words.
std::string solver_words(const std::string& label) {
  const std::size_t comma = label.rfind(", ");
  return "the " + label.substr(0, comma) + " (" + label.substr(comma + 2) + ")";
}

// The answer to "what is the cheapest run within X %?" for one question, as a Markdown list item (and,
// when the question has several targets, one sub-item per target).
std::string answer(const Report& r, const Study& st, const Question& q, int threads) {
  std::vector<StudyRun> runs = question_runs(r, st, q);
  runs.erase(std::remove_if(runs.begin(), runs.end(), [](const StudyRun& s) { return !s.complete(); }), runs.end());
  std::vector<int> targeted;
  for (std::size_t k = 0; k < q.measures.size(); ++k)
    if (st.measures[q.measures[k]].target > 0) targeted.push_back(static_cast<int>(k));
  auto within = [&](const std::vector<int>& ks) {
    std::string w;
    for (std::size_t i = 0; i < ks.size(); ++i) {
      const Measure& m = st.measures[q.measures[ks[i]]];
      w += (i ? (i + 1 == ks.size() ? " and " : ", ") : "") + percent(m.target) +
           (ks.size() > 1 || targeted.size() > 1 ? " (" + m.series.substr(m.series.find(": ") + 2) + ")" : "");
    }
    return w;
  };
  auto describe = [&](const StudyRun& s, const std::vector<int>& ks) {
    std::string errors;
    for (std::size_t i = 0; i < ks.size(); ++i) {
      const Measure& m = st.measures[q.measures[ks[i]]];
      errors +=
          (i ? ", " : "") + m.series.substr(m.series.find(": ") + 2) + " " + fmt("%+.2f %%", 100 * s.errors[ks[i]]);
    }
    return "spacing " + spacing_mm(s.spacing) + " mm on " + solver_words(s.solver) + ", " + fmt("%.3g", s.cost.wall_s) +
           " s on this machine (" + std::to_string(threads) + " thread" + (threads > 1 ? "s" : "") + "; " + errors +
           "; " + fmt("%.3g", s.cost.particle_steps()) + " particle-steps)";
  };
  auto line = [&](const std::vector<int>& ks) {
    const StudyRun* cheapest = nullptr;
    const StudyRun* closest = nullptr;
    auto worst = [&](const StudyRun& s) {
      double w = 0;
      for (int k : ks) w = std::max(w, std::abs(s.errors[k]) / st.measures[q.measures[k]].target);
      return w;
    };
    // Errors within 0.1 % of each other (the double port's and the reference's) count as equally close,
    // and the cheaper of them is the closest.
    for (const StudyRun& s : runs) {
      if (worst(s) <= 1 && (!cheapest || s.cost.wall_s < cheapest->cost.wall_s)) cheapest = &s;
      const bool tie = closest && std::abs(worst(s) - worst(*closest)) <= 1e-3 * worst(*closest);
      if (!closest || (tie ? s.cost.wall_s < closest->cost.wall_s : worst(s) < worst(*closest))) closest = &s;
    }
    if (cheapest)
      return "the cheapest run within " + within(ks) + " of " + st.against + " is " + describe(*cheapest, ks) + ".";
    return "no run is within " + within(ks) + " of " + st.against + ": the closest is " + describe(*closest, ks) + ".";
  };
  std::string md = "- **" + q.what + "**: ";
  if (runs.empty()) return md + "no run completed (see Skipped).\n";
  if (targeted.empty()) return md + "no target.\n";
  md += line(targeted) + "\n";
  if (targeted.size() > 1)
    for (int k : targeted) md += "  - " + st.measures[q.measures[k]].label + " alone: " + line({k}) + "\n";
  return md;
}

// Filled circles for the first solver, open shapes over them for the others, so that coinciding points
// (the double port's on the reference's) stay visible.
const char* kSolverColours[] = {"#1f1f1f", "#d62728", "#1f77b4", "#2ca02c", "#ff7f0e"};
const int kSolverPoints[] = {7, 4, 8, 10, 12};
const double kSolverSizes[] = {1.6, 2.2, 2.2, 2.2, 2.2};

// Tics at 1, 2 and 5 times the powers of ten within [lo, hi] (a log axis narrower than a decade has
// hardly any tics of its own), as a gnuplot tic list.
std::string log_tics(double lo, double hi) {
  std::string tics;
  for (int e = static_cast<int>(std::floor(std::log10(lo))); e <= static_cast<int>(std::ceil(std::log10(hi))); ++e)
    for (const double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, e);
      if (v >= lo && v <= hi) tics += (tics.empty() ? "" : ", ") + gp_quote(fmt("%g", v)) + " " + gp_number(v);
    }
  return "(" + tics + ")";
}

// Wall time against |error| of a case, log-log, one panel per measure with its target as a dashed
// vertical line, one series per solver (backend and precision) through its spacings, each point
// labelled with its spacing.
std::string study_script(const Report& r, const Study& st, const fs::path& png, int threads) {
  const std::vector<std::string> solvers = study_solvers(r, st);
  const std::size_t n = st.measures.size(), cols = std::min<std::size_t>(n, 2), rows = (n + 1) / 2;
  std::ostringstream g, plots;
  g << "# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.\n"
    << "set terminal pngcairo size " << (cols == 1 ? 1000 : 1500) << "," << (rows == 1 ? 700 : 1200)
    << " enhanced font 'Sans,11'\n"
    << "set output " << gp_quote(png.string()) << "\n";
  for (std::size_t k = 0; k < n; ++k) {
    const Measure& m = st.measures[k];
    const std::vector<Point> pts = measure_points(r, m);
    double lo = m.target > 0 ? 100 * m.target : 1e300, hi = m.target > 0 ? 100 * m.target : 0;
    double wall_lo = 1e300, wall_hi = 0;
    std::vector<std::pair<std::string, std::pair<double, double>>> labels;  // text, (log x, log y)
    std::ostringstream labelled;
    plots << "set title " << gp_quote(m.label + (m.target > 0 ? ", target " + percent(m.target) : ", no target"))
          << " noenhanced\nunset arrow\nunset label\n";
    std::vector<std::string> series;
    for (std::size_t v = 0; v < solvers.size(); ++v) {
      std::vector<Point> of;
      for (const Point& p : pts)
        if (solver_label(p) == solvers[v] && p.value != 0 && std::isfinite(p.value) && p.cost.wall_s > 0)
          of.push_back(p);
      if (of.empty()) continue;
      std::sort(of.begin(), of.end(), [](const Point& a, const Point& b) { return a.spacing > b.spacing; });
      const std::string block = "$m" + std::to_string(k) + "s" + std::to_string(v);
      g << block << " << EOD\n";
      for (const Point& p : of) {
        const double x = 100 * std::abs(p.value), y = p.cost.wall_s;
        g << gp_number(x) << " " << gp_number(y) << "\n";
        lo = std::min(lo, x);
        hi = std::max(hi, x);
        wall_lo = std::min(wall_lo, y);
        wall_hi = std::max(wall_hi, y);
        // A spacing's label once where its points lie together (the double port on the reference's).
        const std::string text = spacing_mm(p.spacing) + " mm";
        const bool near = std::any_of(labels.begin(), labels.end(), [&](const auto& l) {
          return l.first == text && std::abs(l.second.first - std::log10(x)) < 0.15 &&
                 std::abs(l.second.second - std::log10(y)) < 0.15;
        });
        if (!near) {
          labels.push_back({text, {std::log10(x), std::log10(y)}});
          labelled << gp_number(x) << " " << gp_number(y) << " \"" << text << "\"\n";
        }
      }
      g << "EOD\n";
      series.push_back(block + " u 1:2 w lp pt " + std::to_string(kSolverPoints[v % 5]) + " ps " +
                       fmt("%.1f", kSolverSizes[v % 5]) + " lw 1.5 lc rgb '" + kSolverColours[v % 5] + "' t " +
                       gp_quote(solvers[v]));
    }
    const std::string labels_block = "$m" + std::to_string(k) + "labels";
    g << labels_block << " << EOD\n" << labelled.str() << "EOD\n";
    if (series.empty()) {
      plots << "set xrange [1:10]\nset yrange [1:10]\nset xtics autofreq\nset ytics autofreq\n"
            << "set label 1 'no run' at graph 0.5, graph 0.5 center\n"
            << "plot 2 lc rgb '#ffffff' notitle\n";
      continue;
    }
    plots << "set xrange [" << gp_number(lo / 3) << ":" << gp_number(hi * 3) << "]\nset xtics "
          << log_tics(lo / 3, hi * 3) << "\nset yrange [" << gp_number(wall_lo / 2) << ":" << gp_number(wall_hi * 2)
          << "]\nset ytics " << log_tics(wall_lo / 2, wall_hi * 2) << "\n";
    if (m.target > 0)
      plots << "set arrow 1 from " << gp_number(100 * m.target) << ", graph 0 to " << gp_number(100 * m.target)
            << ", graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'\n"
            << "set label 1 " << gp_quote("target " + percent(m.target)) << " at " << gp_number(100 * m.target)
            << ", graph 0.04 offset 0.5,0 left tc rgb '#555555'\n";
    plots << "plot ";
    for (const std::string& s : series) plots << s << ", \\\n     ";
    plots << labels_block << " u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle\n";
  }
  g << "set multiplot layout " << rows << "," << cols << " title "
    << gp_quote(st.title + ": wall time against |error| (" + std::to_string(threads) + " thread" +
                (threads > 1 ? "s" : "") + ")")
    << " noenhanced\n"
    << "set logscale xy\nset grid\nset key top right opaque box noenhanced\n"
    << "set xlabel '|error| against " << (st.against == "the closed form" ? "the closed form" : "the experiment")
    << " [%]'\nset ylabel 'wall time [s]'\n"
    << plots.str() << "unset multiplot\nunset output\n";
  return g.str();
}

// The runs of a question beside its chart: each measure's error, the cost, whether within the targets.
std::string study_table(const Report& r, const Study& st, const Question& q) {
  const std::vector<StudyRun> runs = question_runs(r, st, q);
  std::ostringstream md;
  md << "| spacing [mm] | solver |";
  for (int k : q.measures) md << " " << st.measures[k].label << " |";
  md << " particles | steps | particle-steps | wall [s] | particle-steps/s | within the targets |\n|---|---|";
  for (std::size_t k = 0; k < q.measures.size(); ++k) md << "---|";
  md << "---|---|---|---|---|---|\n";
  for (const StudyRun& s : runs) {
    md << "| " << spacing_mm(s.spacing) << " | " << s.solver << " |";
    for (std::size_t k = 0; k < q.measures.size(); ++k) {
      const Measure& m = st.measures[q.measures[k]];
      const double e = s.errors[k];
      if (!std::isfinite(e)) {
        md << " - |";
        continue;
      }
      if (m.observable) {
        const Observable o = validation_observable(m.series);
        md << " " << fmt(o.format, o.experiment * (1 + e) * o.scale) << " " << o.unit << " ("
           << fmt("%+.2f %%", 100 * e) << ") |";
      } else {
        md << " " << fmt("%+.3f %%", 100 * e) << " |";
      }
    }
    md << " " << cost_cells(s.cost) << " | " << (s.complete() ? (s.worst(st, q) <= 1 ? "yes" : "no") : "-") << " |\n";
  }
  return md.str();
}

// Observables against spacing, in mm or m/s, with the experiment as a dashed horizontal line and, where a
// series has one, the finite-element answer as a solid one.
std::string observable_script(const Report& r, const fs::path& png, const std::string& title,
                              const std::vector<PlotSeries>& series, double scale, const std::string& ylabel) {
  std::ostringstream g;
  g << header(png, title, "spacing h [mm]", ylabel) << "set xrange [0:*]\n";
  std::vector<std::string> plots;
  int k = 0;
  for (const PlotSeries& ps : series) {
    const std::string& name = ps.name;
    const double experiment = ps.experiment;
    std::ostringstream d;
    for (const Point& p : of_series(r.observables, name)) d << gp_number(p.spacing * 1e3) << " " << gp_number(p.value * scale) << "\n";
    const std::string block = "$o" + std::to_string(k);
    g << block << " << EOD\n" << d.str() << "EOD\n";
    const std::string colour = kColours[k % 8];
    plots.push_back(block + " u 1:2 w lp pt 7 ps 1.4 lc rgb '" + colour + "' t " + gp_quote(name + ", simulated"));
    plots.push_back(gp_number(experiment * scale) + " w l lw 2 dt 2 lc rgb '" + colour + "' t " +
                    gp_quote(name + ", experiment " + fmt("%.4g", experiment * scale)));
    if (std::isfinite(ps.finite_element))
      plots.push_back(gp_number(ps.finite_element * scale) + " w l lw 2 dt 1 lc rgb '" + colour + "' t " +
                      gp_quote(name + ", finite elements " + fmt("%.4g", ps.finite_element * scale)));
    ++k;
  }
  g << "plot ";
  for (std::size_t i = 0; i < plots.size(); ++i) g << (i ? ", \\\n     " : "") << plots[i];
  g << "\nunset output\n";
  return g.str();
}

}  // namespace impactsph::verify_detail
