#include "app/run_args.hpp"

#include "common/case_file.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace impactsph {

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

nlohmann::json read_json_or_null(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return nullptr;
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception&) {
    return nullptr;
  }
}

std::string run_fingerprint(const std::string& case_file, const std::string& spacing,
                            const std::vector<std::string>& sets) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const std::string& s) {
    for (unsigned char c : s) {
      h ^= c;
      h *= 1099511628211ull;
    }
    h ^= 0xff;
    h *= 1099511628211ull;
  };
  mix(toml_file_content(case_file));  // comments and layout do not count, values do
  for (const std::string& f : case_material_files(case_file)) mix(toml_file_content(f));
  mix(spacing);
  for (const std::string& s : sets) mix(s);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

namespace {

// `path` relative to `root` when it lies inside it.
bool relative_inside(const std::filesystem::path& path, const std::filesystem::path& root, std::string& out) {
  const std::filesystem::path rel = path.lexically_normal().lexically_relative(root.lexically_normal());
  if (rel.empty() || *rel.begin() == "..") return false;
  out = rel.string();
  return true;
}

std::string shell_word(const std::string& s) {
  const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string("-_./=:,+@%").find(c) != std::string::npos;
  });
  if (plain) return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string report_path(const std::filesystem::path& path) {
  if (!path.is_absolute()) return path.string();
  std::string rel;
  if (relative_inside(path, IMPACTSPH_SOURCE_DIR, rel)) return rel;
  std::error_code ec;
  const std::filesystem::path cwd = std::filesystem::current_path(ec);
  if (!ec && relative_inside(path, cwd, rel)) return rel;
  std::filesystem::path p = path.lexically_normal();
  if (!p.has_filename()) p = p.parent_path();  // a trailing '/'
  return ".../" + p.filename().string();
}

std::vector<std::string> report_arguments(const std::vector<std::string>& argv) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < argv.size(); ++k) {
    const std::string& a = argv[k];
    const std::size_t eq = a.find("=/");
    if (k == 0 && !a.empty() && a[0] == '/') out.push_back("impactsph");
    else if (!a.empty() && a[0] == '/') out.push_back(report_path(a));
    else if (eq != std::string::npos) out.push_back(a.substr(0, eq + 1) + report_path(a.substr(eq + 1)));
    else out.push_back(a);
  }
  return out;
}

std::string report_command(const std::vector<std::string>& argv) {
  std::string out;
  for (const std::string& a : report_arguments(argv)) out += (out.empty() ? "" : " ") + shell_word(a);
  return out;
}

}  // namespace impactsph
