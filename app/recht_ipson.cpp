#include "app/recht_ipson.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <algorithm>
#include <cmath>

namespace impactsph {

namespace {

// Recht-Ipson fit with GSL. Parameters are fitted as logarithms (a, p and v_bl stay positive) and
// speeds are scaled by the largest impact speed (a and p do not change, the problem is well scaled).

struct FitData {
  const std::vector<double>* x;  // v_impact / scale
  const std::vector<double>* y;  // v_residual / scale
  RechtIpson fixed;              // scaled v_bl; the values of the parameters not fitted
  bool free[3];                  // a, p, v_bl
};

RechtIpson unpack(const gsl_vector* q, const FitData& d) {
  RechtIpson c = d.fixed;
  std::size_t k = 0;
  if (d.free[0]) c.a = std::exp(gsl_vector_get(q, k++));
  if (d.free[1]) c.p = std::exp(gsl_vector_get(q, k++));
  if (d.free[2]) c.v_bl = std::exp(gsl_vector_get(q, k++));
  return c;
}

// The model and its derivatives along a, p and v_bl at one point.
void model(const RechtIpson& c, double x, double& g, double deriv[3]) {
  const double xp = std::pow(x, c.p), bp = std::pow(c.v_bl, c.p), u = xp - bp;
  if (!(u > 1e-12 * xp)) {  // at or below the limit the curve is 0 and flat
    g = deriv[0] = deriv[1] = deriv[2] = 0;
    return;
  }
  const double r = std::pow(u, 1.0 / c.p);
  g = c.a * r;
  deriv[0] = r;
  deriv[1] = c.a * r * (-std::log(u) / (c.p * c.p) + (xp * std::log(x) - bp * std::log(c.v_bl)) / (c.p * u));
  deriv[2] = -c.a * r / u * std::pow(c.v_bl, c.p - 1);
}

int fit_f(const gsl_vector* q, void* data, gsl_vector* f) {
  const FitData& d = *static_cast<const FitData*>(data);
  const RechtIpson c = unpack(q, d);
  for (std::size_t i = 0; i < d.x->size(); ++i) {
    double g, deriv[3];
    model(c, (*d.x)[i], g, deriv);
    gsl_vector_set(f, i, g - (*d.y)[i]);
  }
  return GSL_SUCCESS;
}

int fit_df(const gsl_vector* q, void* data, gsl_matrix* J) {
  const FitData& d = *static_cast<const FitData*>(data);
  const RechtIpson c = unpack(q, d);
  const double value[3] = {c.a, c.p, c.v_bl};
  for (std::size_t i = 0; i < d.x->size(); ++i) {
    double g, deriv[3];
    model(c, (*d.x)[i], g, deriv);
    std::size_t k = 0;
    for (int j = 0; j < 3; ++j)
      if (d.free[j]) gsl_matrix_set(J, i, k++, deriv[j] * value[j]);  // d/d(log q) = q d/dq
  }
  return GSL_SUCCESS;
}


}  // namespace

double recht_ipson(const RechtIpson& c, double v) {
  if (!(v > c.v_bl)) return 0;
  return c.a * std::pow(std::pow(v, c.p) - std::pow(c.v_bl, c.p), 1.0 / c.p);
}

RechtIpsonFit fit_recht_ipson(const std::vector<double>& v_impact, const std::vector<double>& v_residual,
                              const RechtIpson& start, bool fit_a, bool fit_p, bool fit_v_bl) {
  RechtIpsonFit out;
  out.curve = start;
  out.points = static_cast<int>(v_impact.size());
  const std::size_t n = v_impact.size(), k = static_cast<std::size_t>(fit_a) + fit_p + fit_v_bl;
  if (n < k || k == 0) {
    out.message = "needs at least " + std::to_string(k) + " perforating runs, has " + std::to_string(n);
    return out;
  }
  if (!(start.a > 0 && start.p > 0 && start.v_bl > 0)) {
    out.message = "the start values must be positive";
    return out;
  }
  const double scale = *std::max_element(v_impact.begin(), v_impact.end());
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = v_impact[i] / scale;
    y[i] = v_residual[i] / scale;
  }
  FitData data{&x, &y, {start.a, start.p, start.v_bl / scale}, {fit_a, fit_p, fit_v_bl}};

  gsl_error_handler_t* old_handler = gsl_set_error_handler_off();  // report failures, do not abort
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  gsl_multifit_nlinear_workspace* w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, k);
  gsl_vector* q0 = gsl_vector_alloc(k);
  {
    std::size_t j = 0;
    if (fit_a) gsl_vector_set(q0, j++, std::log(data.fixed.a));
    if (fit_p) gsl_vector_set(q0, j++, std::log(data.fixed.p));
    if (fit_v_bl) gsl_vector_set(q0, j++, std::log(data.fixed.v_bl));
  }
  gsl_multifit_nlinear_fdf fdf;
  fdf.f = fit_f;
  fdf.df = fit_df;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = k;
  fdf.params = &data;
  int info = 0;
  int status = gsl_multifit_nlinear_init(q0, &fdf, w);
  if (status == GSL_SUCCESS) status = gsl_multifit_nlinear_driver(500, 1e-10, 1e-10, 0.0, nullptr, nullptr, &info, w);
  // "No progress" at an exact or flat minimum still leaves the best point found.
  if (status == GSL_SUCCESS || status == GSL_ENOPROG) {
    RechtIpson c = unpack(gsl_multifit_nlinear_position(w), data);
    c.v_bl *= scale;
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += std::pow(recht_ipson(c, v_impact[i]) - v_residual[i], 2);
    out.curve = c;
    out.rms = std::sqrt(sum / static_cast<double>(n));
    out.ok = std::isfinite(c.a) && std::isfinite(c.p) && std::isfinite(c.v_bl) && std::isfinite(out.rms);
    if (!out.ok) out.message = "the fit ran off to infinite parameters";
    else if (n == k) out.message = "exact: as many runs as parameters";
  } else {
    out.message = std::string("the fit did not converge (") + gsl_strerror(status) + ")";
  }
  gsl_vector_free(q0);
  gsl_multifit_nlinear_free(w);
  gsl_set_error_handler(old_handler);
  return out;
}

}  // namespace impactsph
