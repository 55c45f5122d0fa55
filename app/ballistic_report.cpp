// ballistic-limit's outputs: ballistic.csv and ballistic.json after every round, the plot of the
// Recht-Ipson curves with gnuplot (pngcairo) and report.md (app/ballistic_search.hpp).
#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/ballistic_search.hpp"
#include "app/gnuplot.hpp"
#include "app/picture.hpp"
#include "app/run_args.hpp"
#include "common/output.hpp"
#include "common/units.hpp"

namespace impactsph::ballistic {

namespace {

nlohmann::json fit_json(const RechtIpsonFit& f, bool v_bl_fixed) {
  if (!f.ok) return f.message.empty() ? nlohmann::json(nullptr) : nlohmann::json{{"error", f.message}};
  return {{"a", f.curve.a},           {"p", f.curve.p},       {"v_bl_m_s", f.curve.v_bl},
          {"v_bl_fixed", v_bl_fixed}, {"rms_m_s", f.rms},     {"points", f.points}};
}

std::string plot_script(const Search& s, const Outcome& o, const fs::path& png) {
  const std::vector<const Run*> runs = sorted_done(s);
  std::vector<double> xs;
  double y_max = 10;
  for (const Run* r : runs) {
    xs.push_back(r->v);
    if (r->obs.perforated) y_max = std::max(y_max, r->obs.residual_velocity);
  }
  if (o.reference)
    for (const ReferencePoint& p : o.reference->points) {
      xs.push_back(p.v_impact);
      y_max = std::max(y_max, p.v_residual);
    }
  const double x_lo = *std::min_element(xs.begin(), xs.end()), x_hi = *std::max_element(xs.begin(), xs.end());
  const double pad = 0.06 * std::max(x_hi - x_lo, 0.2 * x_hi);
  const double x0 = std::max(0.0, x_lo - pad), x1 = x_hi + pad;
  if (o.fit.ok) y_max = std::max(y_max, recht_ipson(o.fit.curve, x1));
  if (o.fit_free.ok) y_max = std::max(y_max, recht_ipson(o.fit_free.curve, x1));
  if (o.reference_curve) y_max = std::max(y_max, recht_ipson({o.plug.a(), 2, o.reference_v_bl}, x1));
  y_max *= 1.1;

  std::ostringstream g;
  g << "# Drawn by impactsph ballistic-limit; run `gnuplot ballistic_curve.gp` in this folder to redraw.\n";
  g << "set terminal pngcairo size 900,600 enhanced font 'Sans,11'\n";
  g << "set output " << gp_quote(png.string()) << "\n";
  char title[256];
  std::snprintf(title, sizeof title, "%s: ballistic limit %.1f m/s (spacing %s, %zu runs)", s.spec.name.c_str(),
                o.limit(), format_quantity(s.spec.numerics.spacing, Dimension::Length).c_str(), runs.size());
  g << "set title " << gp_quote(title) << " noenhanced\n";
  g << "set xlabel 'impact velocity v_i [m/s]'\nset ylabel 'residual velocity v_r [m/s]'\n";
  g << "set grid\nset key top left Left reverse box opaque\nset xzeroaxis lt -1\nset samples 1000\n";
  g << "set xrange [" << gp_number(x0) << ":" << gp_number(x1) << "]\n";
  g << "set yrange [" << gp_number(-0.04 * y_max) << ":" << gp_number(y_max) << "]\n";
  // The final bracket, shaded, and the estimate as a dashed line labelled on its left, where v_r = 0 and
  // no curve runs.
  g << "set object 1 rect from " << gp_number(o.lo) << ", graph 0 to " << gp_number(o.hi)
    << ", graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind\n";
  g << "set arrow 1 from " << gp_number(o.limit()) << ", graph 0 to " << gp_number(o.limit())
    << ", graph 1 nohead dt 2 lc rgb '#555555'\n";
  g << "set label 1 " << gp_quote("v_{bl} = " + fixed(o.limit(), 1) + " m/s") << " at " << gp_number(o.limit())
    << ", graph 0.12 offset -0.8,0 right textcolor rgb '#555555'\n";
  g << "ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0\n";

  std::ostringstream perf, stopped;
  for (const Run* r : runs) {
    if (r->obs.perforated) perf << gp_number(r->v) << " " << gp_number(r->obs.residual_velocity) << "\n";
    else stopped << gp_number(r->v) << "\n";
  }
  std::vector<std::string> plots;
  if (o.fit.ok) {
    const RechtIpson& c = o.fit.curve;
    g << "a1 = " << gp_number(c.a) << "; p1 = " << gp_number(c.p) << "; v1 = " << gp_number(c.v_bl) << "\n";
    plots.push_back("ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t " +
                    gp_quote("Recht-Ipson fit: a = " + fixed(c.a, 3) + ", p = " + fixed(c.p, 2) + ", v_{bl} = " +
                             fixed(c.v_bl, 1) + " m/s (fixed)"));
  }
  if (o.fit_free.ok) {
    const RechtIpson& c = o.fit_free.curve;
    g << "a2 = " << gp_number(c.a) << "; p2 = " << gp_number(c.p) << "; v2 = " << gp_number(c.v_bl) << "\n";
    plots.push_back("ri(x, a2, p2, v2) w l lw 1.5 dt 2 lc rgb '#ff7f0e' t " +
                    gp_quote("Recht-Ipson fit, all free: a = " + fixed(c.a, 3) + ", p = " + fixed(c.p, 2) +
                             ", v_{bl} = " + fixed(c.v_bl, 1) + " m/s"));
  }
  if (o.reference_curve) {
    g << "a3 = " << gp_number(o.plug.a()) << "; v3 = " << gp_number(o.reference_v_bl) << "\n";
    plots.push_back("ri(x, a3, 2, v3) w l lw 1.5 dt 3 lc rgb '#2ca02c' t " +
                    gp_quote("reference: p = 2, a = m_p/(m_p+m_{plug}) = " + fixed(o.plug.a(), 3) + ", v_{bl} = " +
                             fixed(o.reference_v_bl, 1) + " m/s"));
  }
  if (!perf.str().empty()) {
    g << "$perforated << EOD\n" << perf.str() << "EOD\n";
    plots.push_back("$perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated'");
  }
  if (!stopped.str().empty()) {
    g << "$stopped << EOD\n" << stopped.str() << "EOD\n";
    plots.push_back("$stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated'");
  }
  if (o.reference) {
    // One marker per source: experiments as black triangles, other simulations as open shapes.
    const char* styles[] = {"pt 4 ps 1.6 lw 2 lc rgb '#9467bd'", "pt 12 ps 1.8 lw 2 lc rgb '#8c564b'",
                            "pt 8 ps 1.6 lw 2 lc rgb '#e377c2'"};
    int other = 0;
    for (std::size_t k = 0; k < o.reference->sources.size(); ++k) {
      const std::string& src = o.reference->sources[k];
      std::ostringstream d;
      for (const ReferencePoint& p : o.reference->points)
        if (p.source == src) d << gp_number(p.v_impact) << " " << gp_number(p.v_residual) << "\n";
      const std::string block = "$reference" + std::to_string(k);
      g << block << " << EOD\n" << d.str() << "EOD\n";
      const std::string style = src == "experiment" ? "pt 9 ps 2 lc rgb 'black'" : styles[other++ % 3];
      plots.push_back(block + " u 1:2 w p " + style + " t " + gp_quote(src + " (reference.csv)") + " noenhanced");
    }
  }
  g << "plot ";
  for (std::size_t k = 0; k < plots.size(); ++k) g << (k ? ", \\\n     " : "") << plots[k];
  g << "\nunset output\n";
  return g.str();
}

}  // namespace

std::vector<const Run*> sorted_done(const Search& s) {
  std::vector<const Run*> runs;
  for (const Run& r : s.runs)
    if (r.done) runs.push_back(&r);
  std::sort(runs.begin(), runs.end(), [](const Run* a, const Run* b) { return a->v < b->v; });
  return runs;
}

void write_results(const Search& s, const Outcome& o) {
  std::string csv = "v_impact_m_s,perforated,residual_velocity_m_s,plug_velocity_m_s,plug_mass_kg,settled_time_s,wall_s\n";
  for (const Run* r : sorted_done(s)) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s,%d,%.6g,%.6g,%.6g,", speed_text(r->v).c_str(), r->obs.perforated ? 1 : 0,
                  r->obs.residual_velocity, r->obs.plug_velocity, r->obs.plug_mass);
    csv += buf;
    if (r->obs.settled_time >= 0) {
      std::snprintf(buf, sizeof buf, "%.6g", r->obs.settled_time);
      csv += buf;
    }
    std::snprintf(buf, sizeof buf, ",%.3f\n", r->wall);
    csv += buf;
  }
  write_text_atomic(s.out / "ballistic.csv", csv);

  nlohmann::json j;
  j["case"] = s.spec.name;
  j["case_file"] = report_path(s.opt.case_file);
  j["spacing_m"] = s.spec.numerics.spacing;
  j["set"] = s.opt.sets;
  j["command_line"] = report_arguments(s.opt.command_line);
  j["from_m_s"] = s.v_from;
  j["to_m_s"] = s.v_to;
  j["tolerance_m_s"] = s.tolerance;
  j["jobs"] = s.jobs;
  j["backend"] = s.opt.backend;
  j["precision"] = s.opt.precision;
  j["status"] = o.status;
  j["limit_m_s"] = o.bracketed ? nlohmann::json(o.limit()) : nlohmann::json(nullptr);
  j["bracket_m_s"] = o.bracketed ? nlohmann::json::array({o.lo, o.hi}) : nlohmann::json(nullptr);
  j["a"] = o.fit.ok ? nlohmann::json(o.fit.curve.a) : nlohmann::json(nullptr);
  j["p"] = o.fit.ok ? nlohmann::json(o.fit.curve.p) : nlohmann::json(nullptr);
  j["recht_ipson"] = fit_json(o.fit, true);
  j["recht_ipson_free"] = fit_json(o.fit_free, false);
  if (o.reference_curve) {
    j["reference"] = {{"file", o.reference->file.string()},
                      {"v_bl_m_s", o.reference_v_bl},
                      {"v_bl_from", o.reference_v_bl_from},
                      {"p", 2.0},
                      {"a", o.plug.a()},
                      {"projectile_mass_kg", o.plug.m_p},
                      {"plug_mass_kg", o.plug.m_plug},
                      {"rms_of_runs_m_s", o.reference_rms >= 0 ? nlohmann::json(o.reference_rms) : nlohmann::json(nullptr)}};
  }
  nlohmann::json runs = nlohmann::json::array();
  for (const Run& r : s.runs) {
    const char* origin = r.origin == Origin::Reused ? "reused" : r.origin == Origin::Continued ? "continued" : "ran";
    nlohmann::json x{{"v_impact_m_s", round_speed(r.v)}, {"dir", r.dir.string()}, {"wall_s", r.wall}, {"origin", origin}};
    if (r.failed) {
      x["error"] = r.error;
    } else if (!r.done) {
      x["error"] = "stopped before its end";
    } else {
      x["perforated"] = r.obs.perforated;
      x["residual_velocity_m_s"] = r.obs.residual_velocity;
      x["residual_mass_kg"] = r.obs.residual_mass;
      x["plug_velocity_m_s"] = r.obs.plug_velocity;
      x["plug_mass_kg"] = r.obs.plug_mass;
      x["settled_time_s"] = r.obs.settled_time >= 0 ? nlohmann::json(r.obs.settled_time) : nlohmann::json(nullptr);
    }
    runs.push_back(x);
  }
  j["runs"] = runs;
  write_text_atomic(s.out / "ballistic.json", j.dump(2) + "\n");
}

std::string draw_plot(const Search& s, const Outcome& o) {
  return draw_gnuplot(s.out / "ballistic_curve.png", s.out / "ballistic_curve.gp",
                      [&](const fs::path& png) { return plot_script(s, o, png); });
}

void write_report(const Search& s, const Outcome& o, const std::string& plot_error) {
  auto num = [](const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return std::string(buf);
  };
  const std::vector<const Run*> runs = sorted_done(s);
  std::ostringstream md;
  md << "# Ballistic limit: " << s.spec.name << "\n\n"
     << "Written by `" << report_command(s.opt.command_line) << "`; the figures are also in ballistic.json and "
     << "ballistic.csv, each run in its folder v_SPEED/.\n\n"
     << "| | |\n|---|---|\n"
     << "| case | `" << report_path(s.opt.case_file) << "` at spacing "
     << format_quantity(s.spec.numerics.spacing, Dimension::Length) << " |\n"
     << "| status | " << o.status << " |\n";
  if (o.bracketed)
    md << "| bracket | not perforated at " << speed_text(o.lo) << " m/s, perforated at " << speed_text(o.hi)
       << " m/s (" << runs.size() << " runs) |\n"
       << "| ballistic limit | " << num("%.1f", o.limit()) << " m/s |\n";
  if (o.fit.ok)
    md << "| Recht-Ipson, v_bl fixed | a = " << num("%.4f", o.fit.curve.a) << ", p = " << num("%.3f", o.fit.curve.p)
       << ", rms residual " << num("%.2f", o.fit.rms) << " m/s over " << o.fit.points << " perforating runs |\n";
  if (o.fit_free.ok)
    md << "| Recht-Ipson, all free | a = " << num("%.4f", o.fit_free.curve.a) << ", p = "
       << num("%.3f", o.fit_free.curve.p) << ", v_bl = " << num("%.1f", o.fit_free.curve.v_bl) << " m/s"
       << (o.fit_free.message.empty() ? "" : " (" + o.fit_free.message + ")") << " |\n";
  if (o.reference_curve)
    md << "| reference | v_bl = " << num("%.1f", o.reference_v_bl) << " m/s (" << o.reference_v_bl_from
       << "), simulated limit " << num("%+.1f", 100 * (o.limit() - o.reference_v_bl) / o.reference_v_bl) << " % |\n";
  md << "\n"
     << (plot_error.empty() ? "![residual velocity against impact velocity](ballistic_curve.png)\n"
                            : "The plot was not drawn: " + plot_error + "\n")
     << "\n| impact velocity [m/s] | perforated | residual velocity [m/s] | plug mass [g] | plug velocity [m/s] | "
        "settled at [us] | wall [s] |\n|---|---|---|---|---|---|---|\n";
  for (const Run* r : runs)
    md << "| " << speed_text(r->v) << " | " << (r->obs.perforated ? "yes" : "no") << " | "
       << num("%.1f", r->obs.residual_velocity) << " | " << num("%.2f", r->obs.plug_mass * 1e3) << " | "
       << num("%.1f", r->obs.plug_velocity) << " | "
       << (r->obs.settled_time >= 0 ? num("%.1f", r->obs.settled_time * 1e6) : std::string("not settled")) << " | "
       << num("%.1f", r->wall) << " |\n";

  std::vector<std::pair<const Run*, std::string>> key;
  auto add_key = [&](const Run* r, const std::string& why) {
    if (!r) return;
    for (auto& k : key)
      if (k.first == r) {
        k.second += "; " + why;
        return;
      }
    key.emplace_back(r, why);
  };
  auto at = [&](double v) -> const Run* {
    for (const Run* r : runs)
      if (r->v == v) return r;
    return nullptr;
  };
  if (o.bracketed) {
    add_key(at(o.lo), "the fastest that did not perforate");
    add_key(at(o.hi), "the slowest that perforated");
  }
  if (!runs.empty()) add_key(runs.back(), "the fastest run");
  if (!key.empty() && s.spec.output.picture) {
    md << "\n## The key runs at their end\n\nA cut through the model coloured by "
       << picture_field_label(s.spec.output.picture_field)
       << " (docs/case-files.md, `[output]`); each run folder holds picture.gp and picture.dat to redraw it.\n";
    for (const auto& [r, why] : key) {
      const std::string name = r->dir.filename().string();
      const std::string error = r->picture_error.empty() ? draw_picture(r->dir, "picture") : r->picture_error;
      md << "\n### " << speed_text(r->v) << " m/s: " << why << "\n\n";
      if (error.empty())
        md << "![" << speed_text(r->v) << " m/s at its end](" << name << "/picture.png)\n";
      else
        md << "Not drawn: " << error << "\n";
    }
  }
  write_text_atomic(s.out / "report.md", md.str());
}

}  // namespace impactsph::ballistic
