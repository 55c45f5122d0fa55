#include "common/output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <type_traits>

#include "common/case_observables.hpp"

namespace impactsph {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void write_failed(const fs::path& path, const std::string& stage, int err) {
  throw std::runtime_error("cannot write " + path.string() + ": " + stage + ": " + std::strerror(err));
}

// fsync of the directory makes the rename itself durable; a file system that refuses it still has the
// complete file, so failure here is not an error.
void sync_directory(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

void write_atomic(const fs::path& path, const char* data, std::size_t size) {
  fs::path tmp = path;
  tmp += ".tmp-" + std::to_string(static_cast<long long>(::getpid()));
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) write_failed(path, "open " + tmp.string(), errno);
  auto abandon = [&](const std::string& stage, int err) {
    ::close(fd);
    ::unlink(tmp.c_str());
    write_failed(path, stage, err);
  };
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      abandon("write " + tmp.string(), errno);
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) abandon("fsync " + tmp.string(), errno);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    write_failed(path, "close " + tmp.string(), err);
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    ::unlink(tmp.c_str());
    write_failed(path, "rename from " + tmp.string(), ec.value());
  }
  sync_directory(path.parent_path());
}

// Shortest text that reads back to the same double; locale-independent, unlike printf.
std::string format_double(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

bool parse_double(const std::string& s, double& out) {
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (first != last && *first == '+') ++first;
  const auto r = std::from_chars(first, last, out);
  return r.ec == std::errc() && r.ptr == last;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string() + ": " + std::strerror(errno));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool little_endian() {
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Raw appended data of a VTU file: each array is a UInt64 byte count followed by the bytes; offsets are
// counted from the first byte after the '_' marker.
class AppendedData {
 public:
  template <class T>
  std::uint64_t add(const T* values, std::size_t count) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::uint64_t offset = bytes_.size();
    const std::uint64_t nbytes = count * sizeof(T);
    append(&nbytes, sizeof nbytes);
    append(values, nbytes);
    return offset;
  }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  void append(const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    bytes_.insert(bytes_.end(), c, c + n);
  }
  std::vector<char> bytes_;
};

bool safe_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
         c == '-';
}

std::string frame_file_name(const std::string& basename, std::int64_t index) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%06lld", static_cast<long long>(index));
  return basename + "_" + digits + ".vtu";
}

// Value of attribute `name` inside one XML tag, or false when absent.
bool xml_attribute(const std::string& tag, const std::string& name, std::string& value) {
  const std::string key = " " + name + "=\"";
  const std::size_t start = tag.find(key);
  if (start == std::string::npos) return false;
  const std::size_t begin = start + key.size();
  const std::size_t end = tag.find('"', begin);
  if (end == std::string::npos) return false;
  value = tag.substr(begin, end - begin);
  return true;
}

}  // namespace

void write_text_atomic(const fs::path& path, const std::string& content) {
  write_atomic(path, content.data(), content.size());
}

void write_binary_atomic(const fs::path& path, const std::vector<char>& bytes) {
  write_atomic(path, bytes.data(), bytes.size());
}

// ---------------------------------------------------------------------------------------------------
// FrameSeriesWriter

FrameSeriesWriter::FrameSeriesWriter(fs::path dir, std::string basename)
    : dir_(std::move(dir)), basename_(std::move(basename)) {
  // The basename goes unescaped into XML attributes and file names, so keep it to safe characters.
  if (basename_.empty() || !std::all_of(basename_.begin(), basename_.end(), safe_name_char))
    throw std::invalid_argument("frame series basename '" + basename_ +
                                "' must be non-empty and use only letters, digits, '.', '_' and '-'");
  fs::create_directories(dir_);
  if (fs::exists(pvd_path())) load_pvd();
}

fs::path FrameSeriesWriter::pvd_path() const { return dir_ / (basename_ + ".pvd"); }

fs::path FrameSeriesWriter::frame_path(std::int64_t index) const { return dir_ / frame_file_name(basename_, index); }

void FrameSeriesWriter::load_pvd() {
  const fs::path path = pvd_path();
  const std::string text = read_file(path);
  const std::string prefix = basename_ + "_";
  const std::string suffix = ".vtu";
  std::size_t pos = 0;
  while ((pos = text.find("<DataSet", pos)) != std::string::npos) {
    const std::size_t end = text.find('>', pos);
    if (end == std::string::npos) throw std::runtime_error(path.string() + ": unterminated <DataSet> tag");
    const std::string tag = text.substr(pos, end - pos);
    pos = end;
    FrameEntry e;
    std::string time_text;
    if (!xml_attribute(tag, "timestep", time_text) || !parse_double(time_text, e.time) ||
        !xml_attribute(tag, "file", e.file))
      throw std::runtime_error(path.string() + ": <DataSet> without a valid timestep and file: " + tag);
    // The index is in the file name; a name this writer would not produce means the PVD is not ours.
    const bool shaped = e.file.size() > prefix.size() + suffix.size() && e.file.compare(0, prefix.size(), prefix) == 0 &&
                        e.file.compare(e.file.size() - suffix.size(), suffix.size(), suffix) == 0;
    const std::string digits =
        shaped ? e.file.substr(prefix.size(), e.file.size() - prefix.size() - suffix.size()) : std::string();
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), e.index);
    if (!shaped || r.ec != std::errc() || r.ptr != digits.data() + digits.size() || e.index < 0)
      throw std::runtime_error(path.string() + ": frame file '" + e.file + "' is not named " + prefix +
                               "<index>" + suffix);
    frames_.push_back(std::move(e));
  }
  std::stable_sort(frames_.begin(), frames_.end(),
                   [](const FrameEntry& a, const FrameEntry& b) { return a.index < b.index; });
  frames_.erase(std::unique(frames_.begin(), frames_.end(),
                            [](const FrameEntry& a, const FrameEntry& b) { return a.index == b.index; }),
                frames_.end());
}

void FrameSeriesWriter::write_pvd() const {
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"";
  s += little_endian() ? "LittleEndian" : "BigEndian";
  s += "\">\n  <Collection>\n";
  for (const FrameEntry& e : frames_)
    s += "    <DataSet timestep=\"" + format_double(e.time) + "\" group=\"\" part=\"0\" file=\"" + e.file + "\"/>\n";
  s += "  </Collection>\n</VTKFile>\n";
  write_text_atomic(pvd_path(), s);
}

void FrameSeriesWriter::write_frame(double time, std::int64_t index, const ParticleSet& p,
                                    const std::vector<MaterialParams<double>>& materials) {
  if (index < 0) throw std::invalid_argument("frame index must be >= 0, got " + std::to_string(index));
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t m = p.material[i];
    if (m < 0 || static_cast<std::size_t>(m) >= materials.size())
      throw std::invalid_argument("particle " + std::to_string(i) + " has material " + std::to_string(m) + " but " +
                                  std::to_string(materials.size()) + " materials are defined");
  }

  AppendedData data;
  std::string point_data;
  auto tag = [](const char* type, const std::string& name, int components, std::uint64_t offset) {
    std::string t = "        <DataArray type=\"" + std::string(type) + "\" Name=\"" + name + "\"";
    if (components > 1) t += " NumberOfComponents=\"" + std::to_string(components) + "\"";
    return t + " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
  };
  auto scalar = [&](const std::string& name, auto value_of) {
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = value_of(i);
    point_data += tag("Float64", name, 1, data.add(v.data(), n));
  };

  // Every field with a VTU name, as stored (for_each_field); then the speed and the von Mises stress.
  // Vec3d is three packed doubles, so the arrays go out as they are.
  static_assert(sizeof(Vec3d) == 3 * sizeof(double));
  for_each_field(p, [&](const FieldInfo& f, const auto& a) {
    using T = typename std::decay_t<decltype(a)>::value_type;
    if (!*f.vtu_name) return;
    if constexpr (std::is_same_v<T, Vec3d>) point_data += tag("Float64", f.vtu_name, 3, data.add(a.data(), n));
    else if constexpr (std::is_same_v<T, double>) point_data += tag("Float64", f.vtu_name, 1, data.add(a.data(), n));
    else if constexpr (std::is_same_v<T, std::int32_t>) point_data += tag("Int32", f.vtu_name, 1, data.add(a.data(), n));
    else if constexpr (std::is_same_v<T, std::uint8_t>) point_data += tag("UInt8", f.vtu_name, 1, data.add(a.data(), n));
    else throw std::logic_error(std::string(f.name) + ": a field with a VTU name needs its VTU type in write_frame");
  });
  scalar("speed", [&](std::size_t i) { return norm(p.vel[i]); });
  scalar("von_mises", [&](std::size_t i) { return von_mises(p.dev_stress[i]); });

  const std::uint64_t points_offset = data.add(p.pos.data(), n);
  std::vector<std::int64_t> ids(n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<std::int64_t>(i);
  const std::uint64_t connectivity_offset = data.add(ids.data(), n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<std::int64_t>(i + 1);
  const std::uint64_t offsets_offset = data.add(ids.data(), n);
  const std::vector<std::uint8_t> types(n, 1);  // VTK_VERTEX
  const std::uint64_t types_offset = data.add(types.data(), n);

  const std::string count = std::to_string(n);
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
  xml += little_endian() ? "LittleEndian" : "BigEndian";
  xml += "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n";
  // TIME as FieldData lets ParaView show the time of a single file opened on its own.
  xml += "    <FieldData>\n      <DataArray type=\"Float64\" Name=\"TIME\" NumberOfTuples=\"1\" format=\"ascii\">" +
         format_double(time) + "</DataArray>\n    </FieldData>\n";
  xml += "    <Piece NumberOfPoints=\"" + count + "\" NumberOfCells=\"" + count + "\">\n";
  xml += "      <PointData Scalars=\"density\" Vectors=\"velocity\">\n" + point_data + "      </PointData>\n";
  xml += "      <Points>\n" + tag("Float64", "Points", 3, points_offset) + "      </Points>\n";
  xml += "      <Cells>\n" + tag("Int64", "connectivity", 1, connectivity_offset) +
         tag("Int64", "offsets", 1, offsets_offset) + tag("UInt8", "types", 1, types_offset) + "      </Cells>\n";
  xml += "    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";

  const std::string closing = "\n  </AppendedData>\n</VTKFile>\n";
  std::vector<char> file;
  file.reserve(xml.size() + data.bytes().size() + closing.size());
  file.insert(file.end(), xml.begin(), xml.end());
  file.insert(file.end(), data.bytes().begin(), data.bytes().end());
  file.insert(file.end(), closing.begin(), closing.end());
  write_binary_atomic(frame_path(index), file);

  // The PVD is rewritten only after the frame is on disk, so it never lists a missing file.
  FrameEntry entry{index, time, frame_file_name(basename_, index)};
  auto at = std::lower_bound(frames_.begin(), frames_.end(), index,
                             [](const FrameEntry& e, std::int64_t k) { return e.index < k; });
  if (at != frames_.end() && at->index == index)
    *at = std::move(entry);
  else
    frames_.insert(at, std::move(entry));
  write_pvd();
}

void FrameSeriesWriter::truncate_after(std::int64_t next_index) {
  const auto keep_end = std::find_if(frames_.begin(), frames_.end(),
                                     [&](const FrameEntry& e) { return e.index >= next_index; });
  if (keep_end == frames_.end()) return;
  frames_.erase(keep_end, frames_.end());
  write_pvd();
}

// ---------------------------------------------------------------------------------------------------
// HistoryWriter

namespace {

std::string csv_text(const std::string& header, const std::vector<std::vector<double>>& rows) {
  std::string s = header;
  s += '\n';
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c > 0) s += ',';
      s += format_double(row[c]);
    }
    s += '\n';
  }
  return s;
}

// Rows of an existing history with time <= up_to_time (`columns` numbers each, the time first); a missing
// file has none.
std::vector<std::vector<double>> read_csv(const fs::path& path, const std::string& header, std::size_t columns,
                                          double up_to_time) {
  std::vector<std::vector<double>> rows;
  if (!fs::exists(path)) return rows;
  std::istringstream in(read_file(path));
  std::string line;
  int line_number = 0;
  const double limit = up_to_time + 1e-12 * std::abs(up_to_time);
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_number == 1) {
      if (line != header)
        throw std::runtime_error(path.string() + ":1: unexpected header '" + line + "', expected '" + header + "'");
      continue;
    }
    if (line.empty()) continue;
    std::vector<double> row(columns, 0.0);
    std::size_t column = 0;
    std::size_t start = 0;
    bool ok = true;
    while (ok) {
      const std::size_t comma = line.find(',', start);
      const std::string cell = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      ok = column < columns && parse_double(cell, row[column]);
      ++column;
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (!ok || column != columns)
      throw std::runtime_error(path.string() + ":" + std::to_string(line_number) + ": expected " +
                               std::to_string(columns) + " comma-separated numbers, got '" + line + "'");
    if (row[0] <= limit) rows.push_back(std::move(row));
  }
  if (line_number == 0) throw std::runtime_error(path.string() + ": empty file, expected the header '" + header + "'");
  return rows;
}

}  // namespace

HistoryWriter::HistoryWriter(fs::path dir, std::vector<std::string> body_names)
    : dir_(std::move(dir)), body_rows_(body_names.size()) {
  for (std::string name : body_names) {
    std::replace_if(name.begin(), name.end(), [](char c) { return !safe_name_char(c); }, '_');
    std::string stem = "history_" + name;
    if (std::find(file_stems_.begin(), file_stems_.end(), stem) != file_stems_.end())
      throw std::invalid_argument("two bodies would write the same history file " + stem +
                                  ".csv; give them distinct names");
    file_stems_.push_back(std::move(stem));
  }
  fs::create_directories(dir_);
}

fs::path HistoryWriter::body_path(std::size_t body) const { return dir_ / (file_stems_.at(body) + ".csv"); }

fs::path HistoryWriter::totals_path() const { return dir_ / "totals.csv"; }

void HistoryWriter::load_existing(double up_to_time) {
  for (std::size_t b = 0; b < body_rows_.size(); ++b)
    body_rows_[b] = read_csv(body_path(b), kBodyHeader, kBodyColumns, up_to_time);
  totals_rows_ = read_csv(totals_path(), kTotalsHeader, kTotalsColumns, up_to_time);
}

void HistoryWriter::append(double time, const std::vector<BodySummary>& bodies, const Totals& totals) {
  if (bodies.size() != body_rows_.size())
    throw std::invalid_argument("history has " + std::to_string(body_rows_.size()) + " bodies, got summaries for " +
                                std::to_string(bodies.size()));
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodySummary& s = bodies[b];
    body_rows_[b].push_back({time, s.mass, s.velocity.x, s.velocity.y, s.velocity.z, norm(s.velocity),
                             s.kinetic_energy, s.internal_energy, s.damaged_fraction});
  }
  totals_rows_.push_back({time, totals.momentum.x, totals.momentum.y, totals.momentum.z, totals.kinetic_energy,
                          totals.internal_energy, totals.total_energy()});
}

void HistoryWriter::flush() const {
  for (std::size_t b = 0; b < body_rows_.size(); ++b)
    write_text_atomic(body_path(b), csv_text(kBodyHeader, body_rows_[b]));
  write_text_atomic(totals_path(), csv_text(kTotalsHeader, totals_rows_));
}

// ---------------------------------------------------------------------------------------------------
// ObservableHistory

ObservableHistory::ObservableHistory(fs::path dir, const std::vector<ObservableRow>& shape)
    : path_(std::move(dir) / "observables.csv"), header_("time_s") {
  for (const ObservableRow& row : shape) {
    std::string unit = row.unit;
    std::replace(unit.begin(), unit.end(), '/', '_');
    header_ += "," + row.name + (unit.empty() ? "" : "_" + unit);
  }
  columns_ = shape.size() + 1;
}

void ObservableHistory::load_existing(double up_to_time) { rows_ = read_csv(path_, header_, columns_, up_to_time); }

void ObservableHistory::append(double time, const std::vector<ObservableRow>& rows) {
  if (rows.size() + 1 != columns_)
    throw std::invalid_argument("observables.csv has " + std::to_string(columns_ - 1) + " observables, got " +
                                std::to_string(rows.size()));
  std::vector<double> line{time};
  for (const ObservableRow& row : rows)
    line.push_back(row.kind == ObservableRow::Kind::TimeOrNever && row.value < 0 ? -1.0 : row.value * row.scale);
  rows_.push_back(std::move(line));
}

void ObservableHistory::flush() const { write_text_atomic(path_, csv_text(header_, rows_)); }

}  // namespace impactsph
