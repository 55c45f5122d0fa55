// Plots drawn with gnuplot (pngcairo), shared by the commands that write PNGs (ballistic-limit, verify).
// Host only.
#pragma once
#include <filesystem>
#include <functional>
#include <string>

namespace impactsph {

// A gnuplot single-quoted string: no escapes inside, a quote is doubled.
std::string gp_quote(const std::string& text);
// A number with 10 significant digits, as gnuplot reads it.
std::string gp_number(double v);
// True when `program` is an executable file in one of the folders of $PATH.
bool on_path(const std::string& program);

// Writes `script(png)` to `gp_file` (so a person can redraw the plot with `gnuplot FILE`), then runs
// gnuplot on the script drawn into a temporary name and renames it to `png`, so a failed plot never
// leaves half a PNG. `script(target)` must return a gnuplot script that writes its plot to `target`.
// Returns an error message (what went wrong and how to fix it), or "" when the PNG is there.
std::string draw_gnuplot(const std::filesystem::path& png, const std::filesystem::path& gp_file,
                         const std::function<std::string(const std::filesystem::path&)>& script);

}  // namespace impactsph
