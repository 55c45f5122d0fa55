// What identifies one `impactsph run`: the case file, --spacing and the --set overrides. Shared by the
// run command (checkpoints and summary.json carry the fingerprint) and the sweep (which skips runs whose
// summary.json holds the fingerprint it would give). Host only.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace impactsph {

std::string read_text_file(const std::string& path);  // "" when it cannot be read

// The JSON in `file`, or null when it is missing or not JSON (a run folder written by another version).
nlohmann::json read_json_or_null(const std::filesystem::path& file);

// FNV-1a 64 of what the case file says, of what the material files it reads say (toml_file_content:
// values, not comments or layout), the spacing and every override, as 16 hex digits: a restart must see
// the same inputs, and a finished run with the same fingerprint need not run again.
std::string run_fingerprint(const std::string& case_file, const std::string& spacing,
                            const std::vector<std::string>& sets);

// A path as a report shows it, naming no folder of the machine it ran on: a relative path as given; an
// absolute one relative to the source tree's root when inside it, else relative to the current folder
// when inside that, else ".../" and its file name.
std::string report_path(const std::filesystem::path& path);

// The words of a command line as a report shows them: the program as `impactsph` when it was called by an
// absolute path, each absolute path among the arguments (also the value of KEY=/path) as report_path
// shows it.
std::vector<std::string> report_arguments(const std::vector<std::string>& argv);

// report_arguments joined by spaces, those with spaces or shell characters in single quotes.
std::string report_command(const std::vector<std::string>& argv);

}  // namespace impactsph
