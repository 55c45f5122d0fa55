// impactsph ballistic-limit: brackets the ballistic limit of a perforation case by running it at
// several impact speeds in parallel, fits the Recht-Ipson curve to the perforating runs and plots it
// (docs/ballistic-limit.md). Host only.
#pragma once
#include <string>
#include <vector>

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
  std::vector<std::string> command_line;  // recorded in ballistic.json
};

// Runs the search and writes DIR/ballistic.csv, ballistic.json, ballistic_curve.png. Returns the exit
// status: 0 done, 1 the plot could not be drawn, 3 a run diverged or failed, 4 a bad bracket
// (--from perforates or --to does not), 130 stopped by Ctrl-C. Throws CaseError or std::runtime_error
// for bad inputs, before any run starts.
int ballistic_limit_command(const BallisticOptions& options);

// The Recht-Ipson residual-velocity curve v_r = a (v_i^p - v_bl^p)^(1/p) for v_i > v_bl, else 0.
struct RechtIpson {
  double a = 1, p = 2, v_bl = 0;  // v_bl in m/s
};
double recht_ipson(const RechtIpson& c, double v_impact);

struct RechtIpsonFit {
  bool ok = false;
  RechtIpson curve;
  double rms = 0;       // m/s, root mean square of the residuals
  int points = 0;
  std::string message;  // why it failed, or a remark on the fit
};

// Least-squares fit (GSL gsl_multifit_nlinear, trust region) of the chosen parameters to the points
// (v_impact, v_residual) in m/s; the others keep their values in `start`, which also seeds the fit.
RechtIpsonFit fit_recht_ipson(const std::vector<double>& v_impact, const std::vector<double>& v_residual,
                              const RechtIpson& start, bool fit_a, bool fit_p, bool fit_v_bl);

}  // namespace impactsph
