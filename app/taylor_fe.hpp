// `impactsph taylor-fe CASE`: the Taylor bar of a case file by the axisymmetric finite-element solver of
// verification/fe2d (its README gives the equations), with the outputs a person and the scripts read:
// summary.json (the observables of `impactsph run` for a Taylor bar, the energy balance), profile.csv (the
// outer surface), history.csv, and picture.png of the deformed mesh. Host only.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "verification/fe2d/fe2d.hpp"

namespace impactsph {

struct TaylorFeOptions {
  std::string case_file;
  std::vector<std::string> sets;  // --set KEY=VALUE overrides of the case file
  fe2d::Options numerics;
  std::string end;                // --end with its unit; empty: the case's time.end
  std::string out;                // empty: runs/<case name>-fe
  bool quiet = false;
  bool picture = true;
  std::vector<std::string> command_line;
};

// What a finished run measured, as summary.json holds it.
struct TaylorFeResult {
  std::filesystem::path out;
  fe2d::Observables observables;
  int elements_across = 0, elements = 0;
  long steps = 0;
  double wall_seconds = 0;
  double energy_drift = 0;  // (E_end - E_0) / E_0, E = kinetic + internal + hourglass + wall
  std::string picture_warning;  // why picture.png was not drawn ("" when it was)
};

// Runs the case and writes its outputs. Throws CaseError for a case that is not a Taylor bar (the file, line
// and key named), std::runtime_error for bad options.
TaylorFeResult run_taylor_fe(const TaylorFeOptions& opt);

// The command: prints what run_taylor_fe measured. Returns the exit status.
int taylor_fe_command(const TaylorFeOptions& opt);

}  // namespace impactsph
