// The Recht-Ipson residual-velocity curve of a perforation (Recht and Ipson 1963) and its least-squares
// fit with GSL, used by ballistic-limit and verify (docs/ballistic-limit.md). Host only.
#pragma once
#include <string>
#include <vector>

namespace impactsph {

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
