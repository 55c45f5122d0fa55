// Atomic writes, VTU frames + PVD series, CSV histories.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "common/case_observables.hpp"
#include "common/output.hpp"
#include "tests/temp_dir_test.hpp"

namespace impactsph {
namespace {

namespace fs = std::filesystem;

class OutputTest : public TempDirTest {
 protected:
  OutputTest() : TempDirTest("impactsph_output") {}
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

};

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "<no exception>";
}

ParticleSet sample_particles() {
  ParticleSet p;
  const std::size_t n = 5;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double k = static_cast<double>(i);
    p.pos[i] = {0.001 * k, -0.002 * k, 0.1 + k};
    p.vel[i] = {3.0 * k, 4.0 * k, -1.5};
    p.mass[i] = 1e-6 * (1 + k);
    p.rho[i] = 7850.0 + 0.1 * k + 1.0 / 3.0;
    p.energy[i] = 1000.0 * k;
    p.pressure[i] = -1e8 + 1e7 * k;
    p.h[i] = 2e-4;
    p.dev_stress[i] = {1e8 * k, -0.5e8 * k, -0.5e8 * k, 0, 0, 0};
    p.plastic_strain[i] = 0.01 * k;
    p.damage[i] = 0.25 * k;
    p.temperature[i] = 293.0 + 10.0 * k;
    p.body[i] = static_cast<std::int32_t>(i % 2);
    p.material[i] = static_cast<std::int32_t>(i % 2);
    p.fixed[i] = static_cast<std::uint8_t>(i == 4);
  }
  return p;
}

std::vector<MaterialParams<double>> sample_materials() {
  std::vector<MaterialParams<double>> m(2);
  m[0].specific_heat = 477;  // steel, J/(kg K)
  m[1].specific_heat = 0;    // temperature not tracked
  return m;
}

// Minimal XML check for the text part: every opening tag is closed in order.
bool tags_balanced(const std::string& xml) {
  std::vector<std::string> stack;
  std::size_t pos = 0;
  while ((pos = xml.find('<', pos)) != std::string::npos) {
    const std::size_t end = xml.find('>', pos);
    if (end == std::string::npos) return false;
    const std::string tag = xml.substr(pos + 1, end - pos - 1);
    pos = end + 1;
    if (tag.empty() || tag[0] == '?') continue;
    const std::string name = tag.substr(tag[0] == '/' ? 1 : 0, tag.find_first_of(" />", 1) - (tag[0] == '/' ? 1 : 0));
    if (tag[0] == '/') {
      if (stack.empty() || stack.back() != name) return false;
      stack.pop_back();
    } else if (tag.back() != '/') {
      stack.push_back(name);
    }
  }
  return stack.empty();
}

// Raw appended array `name` of a VTU file, without its UInt64 byte count.
std::string appended_array(const std::string& file, const std::string& name) {
  const std::size_t tag = file.find("Name=\"" + name + "\"");
  const std::size_t key = file.find("offset=\"", tag);
  const std::size_t offset = std::stoull(file.substr(key + 8));
  const std::size_t start = file.find("<AppendedData encoding=\"raw\">");
  const std::size_t data = file.find('_', start) + 1 + offset;
  std::uint64_t nbytes = 0;
  std::memcpy(&nbytes, file.data() + data, sizeof nbytes);
  return file.substr(data + sizeof nbytes, nbytes);
}

template <class T>
std::string bytes_of(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

struct PvdEntry {
  double time;
  std::string file;
};

std::vector<PvdEntry> read_pvd(const std::string& text) {
  std::vector<PvdEntry> out;
  std::size_t pos = 0;
  while ((pos = text.find("<DataSet", pos)) != std::string::npos) {
    const std::size_t t = text.find("timestep=\"", pos) + 10;
    const std::size_t f = text.find("file=\"", pos) + 6;
    out.push_back({std::stod(text.substr(t, text.find('"', t) - t)), text.substr(f, text.find('"', f) - f)});
    pos = f;
  }
  return out;
}

TEST_F(OutputTest, AtomicWriteReplacesContentAndLeavesNoTempFile) {
  const fs::path target = dir_ / "a.txt";
  write_text_atomic(target, "first version, longer\n");
  write_text_atomic(target, "second\n");
  EXPECT_EQ(slurp(target), "second\n");
  const std::vector<char> bytes = {'x', '\0', 'y', '\n'};
  write_binary_atomic(dir_ / "b.bin", bytes);
  EXPECT_EQ(slurp(dir_ / "b.bin"), std::string(bytes.data(), bytes.size()));
  EXPECT_EQ(listing(), (std::vector<std::string>{"a.txt", "b.bin"}));
}

TEST_F(OutputTest, AtomicWriteFailureNamesPathAndReason) {
  const fs::path target = dir_ / "missing_dir" / "a.txt";
  const std::string message = error_of([&] { write_text_atomic(target, "x"); });
  EXPECT_NE(message.find(target.string()), std::string::npos) << message;
  EXPECT_NE(message.find(std::strerror(ENOENT)), std::string::npos) << message;
  EXPECT_EQ(listing(), std::vector<std::string>{});
}

TEST_F(OutputTest, VtuIsWellFormedAndCarriesEveryField) {
  const ParticleSet p = sample_particles();
  const auto materials = sample_materials();
  FrameSeriesWriter writer(dir_, "frame");
  writer.write_frame(1.25e-5, 3, p, materials);
  const std::string file = slurp(dir_ / "frame_000003.vtu");

  const std::string open_data = "<AppendedData encoding=\"raw\">";
  const std::size_t data_start = file.find(open_data);
  ASSERT_NE(data_start, std::string::npos);
  const std::string closing = "\n  </AppendedData>\n</VTKFile>\n";
  ASSERT_GE(file.size(), closing.size());
  EXPECT_EQ(file.substr(file.size() - closing.size()), closing);
  EXPECT_TRUE(tags_balanced(file.substr(0, data_start + open_data.size()) + "</AppendedData></VTKFile>"));
  EXPECT_EQ(file.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"", 0), 0u);
  EXPECT_NE(file.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(file.find("NumberOfPoints=\"5\" NumberOfCells=\"5\""), std::string::npos);
  EXPECT_NE(file.find("Name=\"TIME\" NumberOfTuples=\"1\" format=\"ascii\">1.25e-05<"), std::string::npos);

  for (const char* field : {"velocity", "speed", "density", "pressure", "von_mises", "plastic_strain", "plastic_work", "damage",
                            "temperature", "bulking_pressure", "internal_energy", "smoothing_length", "mass",
                            "body_id", "fixed", "Points", "connectivity", "offsets", "types"})
    EXPECT_NE(file.find("Name=\"" + std::string(field) + "\""), std::string::npos) << field;

  EXPECT_EQ(appended_array(file, "density"), bytes_of(p.rho));
  EXPECT_EQ(appended_array(file, "velocity"), bytes_of(p.vel));
  EXPECT_EQ(appended_array(file, "Points"), bytes_of(p.pos));
  EXPECT_EQ(appended_array(file, "body_id"), bytes_of(p.body));
  EXPECT_EQ(appended_array(file, "fixed"), bytes_of(p.fixed));
  EXPECT_EQ(appended_array(file, "types"), std::string(5, '\1'));
  const std::vector<std::int64_t> offsets = {1, 2, 3, 4, 5};
  EXPECT_EQ(appended_array(file, "offsets"), bytes_of(offsets));

  std::vector<double> von_mises_expected(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) von_mises_expected[i] = von_mises(p.dev_stress[i]);
  EXPECT_EQ(appended_array(file, "temperature"), bytes_of(p.temperature));
  EXPECT_EQ(appended_array(file, "von_mises"), bytes_of(von_mises_expected));
  EXPECT_DOUBLE_EQ(von_mises_expected[2], 3e8);                // uniaxial deviator of 2e8 Pa axial stress
}

TEST_F(OutputTest, VtuRejectsUnknownMaterial) {
  ParticleSet p = sample_particles();
  p.material[1] = 7;
  FrameSeriesWriter writer(dir_, "frame");
  const std::string message = error_of([&] { writer.write_frame(0, 0, p, sample_materials()); });
  EXPECT_NE(message.find("particle 1 has material 7"), std::string::npos) << message;
}

TEST_F(OutputTest, PvdListsFramesInOrderAndTruncatesOnRestart) {
  const ParticleSet p = sample_particles();
  const auto materials = sample_materials();
  {
    FrameSeriesWriter writer(dir_, "run");
    for (int k = 0; k < 3; ++k) writer.write_frame(1e-6 * k, k, p, materials);
  }
  auto entries = read_pvd(slurp(dir_ / "run.pvd"));
  ASSERT_EQ(entries.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(entries[k].file, "run_00000" + std::to_string(k) + ".vtu");
    EXPECT_EQ(entries[k].time, 1e-6 * k);
  }

  // A restart from a checkpoint taken at frame 1 re-opens the series and continues at index 1.
  FrameSeriesWriter restarted(dir_, "run");
  ASSERT_EQ(restarted.frames().size(), 3u);
  EXPECT_EQ(restarted.frames()[2].time, 2e-6);
  restarted.truncate_after(1);
  entries = read_pvd(slurp(dir_ / "run.pvd"));
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].file, "run_000000.vtu");
  restarted.write_frame(1.5e-6, 1, p, materials);
  entries = read_pvd(slurp(dir_ / "run.pvd"));
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[1].file, "run_000001.vtu");
  EXPECT_EQ(entries[1].time, 1.5e-6);

  for (const std::string& name : listing()) EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name;
}

TEST_F(OutputTest, FrameSeriesRejectsUnsafeBasename) {
  EXPECT_THROW(FrameSeriesWriter(dir_, "a/b"), std::invalid_argument);
  EXPECT_THROW(FrameSeriesWriter(dir_, ""), std::invalid_argument);
}

std::vector<BodySummary> summaries(double t) {
  std::vector<BodySummary> b(2);
  b[0].mass = 0.004;
  b[0].velocity = {0, 0, -800 + 1e4 * t};
  b[0].kinetic_energy = 0.5 * b[0].mass * b[0].velocity.z * b[0].velocity.z;
  b[0].internal_energy = 1.0 / 3.0 + t;
  b[1].mass = 0.1;
  b[1].velocity = {3, 4, 0};
  b[1].kinetic_energy = 2.5;
  b[1].damaged_fraction = 0.125;
  return b;
}

Totals totals(double t) {
  Totals s;
  s.momentum = {0.1, -0.2, -3.2 + t};
  s.kinetic_energy = 1280;
  s.internal_energy = 0.1 + t;
  return s;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST_F(OutputTest, HistoryWritesCsvAndReloadsUpToRestartTime) {
  const std::vector<std::string> names = {"projectile", "plate 1"};
  HistoryWriter history(dir_, names);
  for (int k = 0; k < 4; ++k) history.append(1e-6 * k, summaries(1e-6 * k), totals(1e-6 * k));
  history.flush();

  const auto body = lines_of(slurp(dir_ / "history_projectile.csv"));
  ASSERT_EQ(body.size(), 5u);
  EXPECT_EQ(body[0], HistoryWriter::kBodyHeader);
  EXPECT_EQ(body[1], "0,0.004,0,0,-800,800,1280,0.3333333333333333,0");
  const auto plate = lines_of(slurp(dir_ / "history_plate_1.csv"));
  ASSERT_EQ(plate.size(), 5u);
  const std::string plate_tail = ",0.1,3,4,0,5,2.5,0,0.125";
  EXPECT_EQ(plate[4].substr(plate[4].size() - plate_tail.size()), plate_tail);
  const auto total_lines = lines_of(slurp(dir_ / "totals.csv"));
  ASSERT_EQ(total_lines.size(), 5u);
  EXPECT_EQ(total_lines[0], HistoryWriter::kTotalsHeader);

  // Reloading everything and flushing reproduces the files byte for byte (numbers round-trip).
  const std::string before = slurp(dir_ / "history_projectile.csv") + slurp(dir_ / "totals.csv");
  HistoryWriter reloaded(dir_, names);
  reloaded.load_existing(1.0);
  EXPECT_EQ(reloaded.rows(), 4u);
  reloaded.flush();
  EXPECT_EQ(slurp(dir_ / "history_projectile.csv") + slurp(dir_ / "totals.csv"), before);

  // A restart at t = 2 us keeps rows 0..2 and continues from there.
  HistoryWriter restarted(dir_, names);
  restarted.load_existing(2e-6);
  EXPECT_EQ(restarted.rows(), 3u);
  restarted.append(2.5e-6, summaries(2.5e-6), totals(2.5e-6));
  restarted.flush();
  const auto after = lines_of(slurp(dir_ / "totals.csv"));
  ASSERT_EQ(after.size(), 5u);
  EXPECT_EQ(after[3].substr(0, 6), "2e-06,");
  EXPECT_EQ(after[4].substr(0, 8), "2.5e-06,");
  EXPECT_EQ(lines_of(slurp(dir_ / "history_plate_1.csv")).size(), 5u);
  for (const std::string& name : listing()) EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name;
}

// observables.csv: the header from the rows' names and printed units, values in those units, and a restart
// keeps the rows up to its time.
TEST_F(OutputTest, ObservableHistoryWritesRowsInPrintedUnitsAndRestarts) {
  CaseObservables o;
  o.projectile = o.target = true;
  ObservableHistory observed(dir_, observable_rows(o));
  EXPECT_EQ(observed.header(),
            "time_s,residual_velocity_m_s,residual_mass_g,eroded_mass_g,settled_time_us,plug_velocity_m_s,plug_mass_g,"
            "perforated,damage_fraction");
  for (int k = 0; k < 3; ++k) {
    o.residual_velocity = 100.0 - k;
    o.plug_mass = 0.001 * k;
    o.perforated = k == 2;
    o.settled_time = k == 2 ? 2e-6 : -1;
    observed.append(1e-6 * k, observable_rows(o));
  }
  observed.flush();
  const auto lines = lines_of(slurp(dir_ / "observables.csv"));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], observed.header());
  EXPECT_EQ(lines[1], "0,100,0,0,-1,0,0,0,0");
  EXPECT_EQ(lines[3], "2e-06,98,0,0,2,0,2,1,0");

  ObservableHistory restarted(dir_, observable_rows(o));
  restarted.load_existing(1e-6);
  EXPECT_EQ(restarted.rows(), 2u);
  EXPECT_THROW(restarted.append(3e-6, {}), std::invalid_argument);

  CaseObservables bar;
  bar.taylor_bar = true;
  ObservableHistory other(dir_, observable_rows(bar));
  const std::string message = error_of([&] { other.load_existing(1.0); });
  EXPECT_NE(message.find("observables.csv:1: unexpected header"), std::string::npos) << message;
}

// Each observable row says its SI unit (summary.json's "observable_units", read by the sweep table), and the
// printed unit is that unit scaled as the row says.
TEST(ObservableRows, CarryTheirSiUnitConsistentWithThePrintedOne) {
  CaseObservables o;
  o.taylor_bar = o.projectile = o.target = true;
  const std::vector<std::tuple<std::string, std::string, double>> allowed = {
      {"mm", "m", 1e3}, {"g", "kg", 1e3}, {"us", "s", 1e6}, {"m/s", "m/s", 1.0}, {"", "", 1.0}};
  for (const ObservableRow& row : observable_rows(o)) {
    bool found = false;
    for (const auto& [printed, si, scale] : allowed)
      if (printed == row.unit && si == row.si_unit && scale == row.scale) found = true;
    EXPECT_TRUE(found) << row.name << ": printed in \"" << row.unit << "\" (x" << row.scale << "), SI unit \""
                       << row.si_unit << "\"";
  }
}

TEST_F(OutputTest, HistoryReportsMalformedFilesAndNameClashes) {
  write_text_atomic(dir_ / "totals.csv", std::string(HistoryWriter::kTotalsHeader) + "\n0,1,2,3,4,5,6\n0,1,2\n");
  HistoryWriter history(dir_, {"a"});
  const std::string message = error_of([&] { history.load_existing(1.0); });
  EXPECT_NE(message.find("totals.csv:3:"), std::string::npos) << message;
  EXPECT_THROW(HistoryWriter(dir_, std::vector<std::string>{"plate 1", "plate_1"}), std::invalid_argument);
  EXPECT_THROW(history.append(0, std::vector<BodySummary>(2), Totals{}), std::invalid_argument);
}

}  // namespace
}  // namespace impactsph
