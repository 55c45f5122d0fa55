// impactsph sweep (docs/sweeps-and-verification.md): runs one case over a set of parameters (spacing,
// impact velocity, any case key, backend, precision), several runs at a time as child processes of
// `impactsph run`, each in its own folder; resumes a stopped sweep; writes a table of every run's
// observables and costs; or writes a Slurm job array that does the same on a cluster. Host only.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace impactsph {

// One run of a sweep: its parameters (axis name -> value as written) and what `impactsph run` is given.
struct SweepRun {
  std::string name;                                       // folder name, readable from the parameters
  std::vector<std::pair<std::string, std::string>> parameters;  // in the order of the sweep file's axes
  std::string spacing;                                    // --spacing, "" for the case's
  std::vector<std::string> sets;                          // --set KEY=VALUE (the sweep's, then the run's)
  std::string backend, precision;                         // --backend, --precision; "" when not given
  std::string fingerprint;                                // run_fingerprint(case, spacing, sets)
};

struct SweepSpec {
  std::string file;                  // the sweep file
  std::string name;                  // [sweep] name, default the file's stem
  std::string case_file;             // absolute
  std::vector<std::string> axis_names;  // columns of the table, in file order
  std::vector<SweepRun> runs;
  // [slurm]: #SBATCH values (time, partition, account) and extra lines.
  std::map<std::string, std::string> slurm;
  std::vector<std::string> slurm_extra;
};

// Reads and validates the sweep file: every run's overrides are checked against the case as
// `impactsph run` would check them. Throws CaseError(file, line, key, what is valid).
SweepSpec load_sweep_file(const std::string& path);

struct SweepOptions {
  std::string sweep_file;
  std::string out;            // default runs/<sweep name>
  int jobs = 0;               // runs at a time; 0: cores / threads_per_run
  int threads_per_run = 1;
  std::string emit;           // "slurm": write the job-array script instead of running
  bool collect = false;       // only build the table from the run folders
  bool retry_failed = false;  // run again the runs that failed (diverged) before
  std::string executable;     // the impactsph binary the runs call; default this process's
};

// Returns the exit status: 0 every run complete, 3 a run failed, 130 stopped by a signal (the runs in
// flight were stopped and wrote their checkpoints; the same command continues the sweep).
int sweep_command(const SweepOptions& options);

}  // namespace impactsph
