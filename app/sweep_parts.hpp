// The parts of `impactsph sweep` (app/sweep.cpp) shared by its files (internal; app/sweep.hpp is the
// interface): a run folder's state, read by the runs and by the table. sweep_file.cpp reads the sweep file,
// sweep_table.cpp writes sweep.csv and sweep.md, sweep.cpp runs the pool, resumes and writes the Slurm script.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/sweep.hpp"

namespace impactsph::sweep_detail {

// "0.5 mm" -> "0.5mm", "250 m/s" -> "250m_per_s", "[0, 0, -1]" -> "0,0,-1": a folder name a shell and
// Slurm take without quotes.
std::string name_part(const std::string& text);

enum class RunState { NotRun, Complete, Stopped, Failed, Stale };

struct FolderState {
  RunState state = RunState::NotRun;
  nlohmann::json summary;  // summary.json when it belongs to this run
  std::string error;       // why it failed (sweep_run.json)
};

// Complete: summary.json says completed with this run's fingerprint and solver flags. Stopped: a
// checkpoint of this run is there. Failed: the sweep recorded a failure of this very run. Stale: the
// folder holds another run (the case or an override changed). The solver flags are compared through the
// command line summary.json records, since the fingerprint covers the case and overrides only.
FolderState folder_state(const SweepRun& r, const std::filesystem::path& dir);

struct TableRow {
  const SweepRun* run;
  std::string status;
  nlohmann::json summary;  // null when the run has none of its own
};

// The state of each run's folder, as rows of the table.
std::vector<TableRow> collect_rows(const SweepSpec& spec, const std::filesystem::path& out);
std::string status_text(RunState s);
// Writes OUT/sweep.csv and OUT/sweep.md; returns the Markdown table.
std::string write_table(const SweepSpec& spec, const std::filesystem::path& out, const std::vector<TableRow>& rows);

}  // namespace impactsph::sweep_detail
