// impactsph verify (docs/sweeps-and-verification.md): convergence of the analytic cases against their
// closed forms over four or more spacings, with the observed order from a least-squares fit in log-log
// (GSL), the cost of every run, per case the wall time against the error of each run (spacing, backend,
// precision) with the cheapest run within the case's target, and (full suite) the validation observables
// against spacing and the time-step sensitivity. Writes DIR/report.md, DIR/results.csv and PNG plots
// (gnuplot). Host only.
#pragma once
#include <string>
#include <vector>

namespace impactsph {

struct VerifyOptions {
  std::string suite = "fast";  // fast: elastic wave and Hugoniot; full: + Taylor bar, plate, tile, CFL sensitivity
  std::string out;             // default runs/verify-<suite>
  int threads = 0;             // OpenMP threads of each run; 0: all cores
  std::string cases;           // folder of the case folders; default the source tree's cases/
  std::vector<std::string> command_line;
};

// Returns 0 when the report is written (whatever the figures say: the report states them), 1 when a
// plot could not be drawn, 3 when a run failed (the report lists it).
int verify_command(const VerifyOptions& options);

}  // namespace impactsph
