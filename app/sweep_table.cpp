// impactsph sweep, the table: sweep.csv and sweep.md from the run folders' summary.json files.
#include <cstdio>
#include <fstream>
#include <sstream>

#include "app/run_args.hpp"
#include "app/sweep_parts.hpp"
#include "common/output.hpp"

namespace fs = std::filesystem;

namespace impactsph::sweep_detail {
namespace {

std::string number(double v, int digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string json_cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_number()) return number(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

}  // namespace

std::string write_table(const SweepSpec& spec, const fs::path& out, const std::vector<TableRow>& rows) {
  std::vector<std::string> observables;
  for (const TableRow& r : rows)
    if (r.summary.is_object() && r.summary.contains("observables"))
      for (auto& [k, v] : r.summary["observables"].items())
        if (std::find(observables.begin(), observables.end(), k) == observables.end()) observables.push_back(k);

  std::vector<std::string> head{"run"};
  for (const std::string& a : spec.axis_names) head.push_back(a);
  head.insert(head.end(), {"status", "particles", "steps", "wall_time_s", "particle_steps_per_s", "mean_neighbours",
                           "energy_drift", "correction_fallbacks"});
  // Each observable's SI unit as the runs' summary.json give it ("observable_units"; none from a run
  // written before it had them).
  for (const std::string& o : observables) {
    std::string unit;
    for (const TableRow& r : rows)
      if (r.summary.is_object() && r.summary.contains("observable_units") && r.summary["observable_units"].contains(o))
        unit = r.summary["observable_units"][o].get<std::string>();
    head.push_back(unit.empty() ? o : o + "_" + name_part(unit));
  }
  std::vector<std::vector<std::string>> cells;
  for (const TableRow& r : rows) {
    std::vector<std::string> c{r.run->name};
    for (const std::string& a : spec.axis_names) {
      std::string v;
      for (const auto& [k, x] : r.run->parameters)
        if (k == a) v = x;
      c.push_back(v);
    }
    c.push_back(r.status);
    const nlohmann::json& s = r.summary;
    if (s.is_object()) {
      const double particles = s.value("particles", 0.0), steps = s.value("steps", 0.0), wall = s.value("wall_time_s", 0.0);
      c.push_back(json_cell(s.value("particles", nlohmann::json())));
      c.push_back(json_cell(s.value("steps", nlohmann::json())));
      c.push_back(number(wall, 4));
      // Over the whole run, restarts included: particles x steps / the wall time of all its segments.
      c.push_back(wall > 0 ? number(particles * steps / wall, 4) : "");
      c.push_back(number(s.value("mean_neighbours", 0.0), 4));
      c.push_back(s.contains("totals") ? number(s["totals"].value("energy_drift_relative", 0.0), 3) : "");
      c.push_back(s.contains("correction_fallbacks") ? json_cell(s["correction_fallbacks"].value("particle_steps", nlohmann::json()))
                                                     : "");
      for (const std::string& o : observables)
        c.push_back(s.contains("observables") ? json_cell(s["observables"].value(o, nlohmann::json())) : "");
    } else {
      c.resize(head.size());
    }
    cells.push_back(c);
  }
  std::string csv;
  for (std::size_t k = 0; k < head.size(); ++k) csv += (k ? "," : "") + csv_field(head[k]);
  csv += "\n";
  for (const auto& c : cells) {
    for (std::size_t k = 0; k < c.size(); ++k) csv += (k ? "," : "") + csv_field(c[k]);
    csv += "\n";
  }
  write_text_atomic(out / "sweep.csv", csv);

  std::string md = "|";
  for (const std::string& h : head) md += " " + h + " |";
  md += "\n|";
  for (std::size_t k = 0; k < head.size(); ++k) md += "---|";
  md += "\n";
  for (const auto& c : cells) {
    md += "|";
    for (const std::string& x : c) md += " " + x + " |";
    md += "\n";
  }
  std::string doc = "# Sweep " + spec.name + "\n\nSweep file `" + report_path(spec.file) + "`, case `" + report_path(spec.case_file) +
                    "`, " + std::to_string(rows.size()) + " runs. Written by `impactsph sweep`; the same table is in "
                    "sweep.csv. Observables in SI units; particle_steps_per_s is particles x steps / wall time of "
                    "the whole run (restarts included).\n\n" + md;
  write_text_atomic(out / "sweep.md", doc);
  return md;
}

std::string status_text(RunState s) {
  switch (s) {
    case RunState::Complete: return "done";
    case RunState::Stopped: return "stopped";
    case RunState::Failed: return "failed";
    case RunState::Stale: return "stale";
    default: return "not run";
  }
}

std::vector<TableRow> collect_rows(const SweepSpec& spec, const fs::path& out) {
  std::vector<TableRow> rows;
  for (const SweepRun& r : spec.runs) {
    const FolderState f = folder_state(r, out / r.name);
    rows.push_back({&r, status_text(f.state), f.summary});
  }
  return rows;
}

}  // namespace impactsph::sweep_detail
