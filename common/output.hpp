// Run outputs (host only): atomic file writes, VTU frames with a PVD series for ParaView, and CSV time
// histories per body. Every file is written to a temporary name and renamed, so a reader (or a crash)
// never sees half a file.
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/material.hpp"
#include "common/observables.hpp"
#include "common/particle_set.hpp"

namespace impactsph {

struct ObservableRow;  // common/case_observables.hpp

// Write `content` to `path` via `path.tmp-<pid>` in the same directory: write, fsync, rename. Throws
// std::runtime_error naming the path and the system's reason on failure; the target is then untouched.
void write_text_atomic(const std::filesystem::path& path, const std::string& content);
void write_binary_atomic(const std::filesystem::path& path, const std::vector<char>& bytes);

// One entry of a PVD series.
struct FrameEntry {
  std::int64_t index = 0;
  double time = 0;   // s
  std::string file;  // relative to the series directory
};

// VTU frames `dir/<basename>_<index, 6 digits>.vtu` (one VTK_VERTEX cell per particle, raw appended
// binary, UInt64 headers) and the series `dir/<basename>.pvd`, rewritten after every frame.
// An existing PVD in `dir` is loaded on construction so a restarted run extends it; a restart from a
// checkpoint taken at frame k calls truncate_after(k), a fresh run truncate_after(0).
class FrameSeriesWriter {
 public:
  FrameSeriesWriter(std::filesystem::path dir, std::string basename);

  // Point fields: velocity, speed, density, pressure, von_mises, plastic_strain, damage, temperature,
  // internal_energy (specific, J/kg), smoothing_length, mass, body_id, material_id, fixed; FieldData TIME.
  // Writing an index already in the series replaces that entry.
  void write_frame(double time, std::int64_t index, const ParticleSet& p,
                   const std::vector<MaterialParams<double>>& materials);

  // Drop series entries with index >= next_index and rewrite the PVD if any were dropped. Frame files
  // on disk are left alone; the continuing run overwrites them.
  void truncate_after(std::int64_t next_index);

  const std::vector<FrameEntry>& frames() const { return frames_; }  // ordered by index
  std::filesystem::path pvd_path() const;
  std::filesystem::path frame_path(std::int64_t index) const;

 private:
  void load_pvd();
  void write_pvd() const;

  std::filesystem::path dir_;
  std::string basename_;
  std::vector<FrameEntry> frames_;
};

// CSV time histories: `dir/history_<name>.csv` per body and `dir/totals.csv`. Rows are kept in memory
// and flush() rewrites every file whole (histories are small), so each file is always complete.
class HistoryWriter {
 public:
  static constexpr const char* kBodyHeader =
      "time_s,mass_kg,vx_m_s,vy_m_s,vz_m_s,speed_m_s,kinetic_J,internal_J,damaged_mass_fraction";
  static constexpr const char* kTotalsHeader = "time_s,px_kg_m_s,py_kg_m_s,pz_kg_m_s,kinetic_J,internal_J,total_J";

  // Body names become file names: characters other than [A-Za-z0-9._-] are replaced by '_'. Throws
  // std::invalid_argument when two bodies would share a file.
  HistoryWriter(std::filesystem::path dir, std::vector<std::string> body_names);

  // Restart: replace the rows in memory by those in the existing files with time <= up_to_time (a
  // relative tolerance of 1e-12 absorbs printing). Missing files give no rows; a malformed file throws
  // std::runtime_error naming the file and line.
  void load_existing(double up_to_time);

  // `bodies` has one entry per body name, in the same order.
  void append(double time, const std::vector<BodySummary>& bodies, const Totals& totals);

  void flush() const;

  std::size_t rows() const { return totals_rows_.size(); }  // rows of totals.csv
  double last_time() const { return totals_rows_.empty() ? -1.0 : totals_rows_.back()[0]; }  // s; -1: no row
  std::filesystem::path body_path(std::size_t body) const;
  std::filesystem::path totals_path() const;

 private:
  static constexpr std::size_t kBodyColumns = 9;
  static constexpr std::size_t kTotalsColumns = 7;

  std::filesystem::path dir_;
  std::vector<std::string> file_stems_;
  std::vector<std::vector<std::vector<double>>> body_rows_;  // [body][row][column]
  std::vector<std::vector<double>> totals_rows_;
};

// `dir/observables.csv`: the case's observables (observable_rows, common/case_observables.hpp) at every
// history row, in the units they are printed in (columns `plug_mass_g`, `residual_velocity_m_s`, ...; a
// time not reached yet, as settled_time_us, is -1): when the plug came off, how the residual velocity
// settled. Kept and rewritten whole as HistoryWriter does.
class ObservableHistory {
 public:
  // `shape`: the rows the case's observables produce (their names and units make the header).
  ObservableHistory(std::filesystem::path dir, const std::vector<ObservableRow>& shape);

  // Restart: the rows of the existing file with time <= up_to_time; a missing file gives none, a file with
  // another header or a malformed row throws std::runtime_error naming the file and line.
  void load_existing(double up_to_time);
  // Throws std::invalid_argument when `rows` has another length than the shape.
  void append(double time, const std::vector<ObservableRow>& rows);
  void flush() const;

  const std::string& header() const { return header_; }
  std::size_t rows() const { return rows_.size(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::string header_;
  std::size_t columns_ = 1;
  std::vector<std::vector<double>> rows_;
};

}  // namespace impactsph
