// impactsph ballistic-limit: brackets the ballistic limit of a perforation case by running it at
// several impact speeds in parallel, fits the Recht-Ipson curve to the perforating runs and plots it
// (docs/ballistic-limit.md). Host only.
#pragma once
#include <string>
#include <vector>

#include "app/recht_ipson.hpp"

namespace impactsph {

struct BallisticOptions {
  std::string case_file;
  std::string spacing;             // --spacing, empty: the case's
  std::vector<std::string> sets;   // --set overrides, applied to every run
  std::string from, to;            // impact speeds bracketing the limit ("150 m/s"; a bare number is m/s)
  std::string tolerance = "5 m/s"; // stop when the bracket is this narrow
  std::string out;                 // empty: runs/<case name>-ballistic
  int jobs = 0;                    // concurrent runs; 0: one per core
  std::string backend = "reference";  // --backend: reference or gpu (the port; its host build without a GPU)
  std::string precision = "double";   // --precision: double, or float (gpu only)
  bool quiet = false;              // no banner and no line per run
  std::string coarse_spacing;      // --coarse: first the same search at this spacing; empty: none
  double coarse_margin = 0.05;     // --coarse-margin: the share of the coarse limit added on each side of its bracket
  std::string split = "thirds";    // --split: thirds (even) or recht-ipson (at the limit the perforating runs point to)
  std::vector<std::string> command_line;  // recorded in ballistic.json
};

// Runs the search and writes DIR/ballistic.csv, ballistic.json, ballistic_curve.png. Returns the exit
// status: 0 done, 1 the plot could not be drawn, 3 a run diverged or failed, 4 a bad bracket
// (--from perforates or --to does not), 130 stopped by Ctrl-C. Throws CaseError or std::runtime_error
// for bad inputs, before any run starts.
int ballistic_limit_command(const BallisticOptions& options);

}  // namespace impactsph
