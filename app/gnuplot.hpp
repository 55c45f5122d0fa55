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

// Runs gnuplot in the folder of `png` on `script(target)`, `target` a temporary file name in that
// folder, and renames the result to `png`, so a failed plot never leaves half a PNG. Returns an error
// message (what went wrong and how to fix it), or "" when the PNG is there.
std::string run_gnuplot(const std::filesystem::path& png,
                        const std::function<std::string(const std::filesystem::path&)>& script);

// Writes `script(png's file name)` to `gp_file` in the folder of `png` (so a person can redraw the plot
// with `gnuplot FILE` in that folder; the script names no other path), then draws it with run_gnuplot.
// `script(target)` must return a gnuplot script that writes its plot to `target`, relative to the folder.
// Returns an error message, or "" when the PNG is there.
std::string draw_gnuplot(const std::filesystem::path& png, const std::filesystem::path& gp_file,
                         const std::function<std::string(const std::filesystem::path&)>& script);

}  // namespace impactsph
