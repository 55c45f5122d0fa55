// Monaghan artificial viscosity (F eqs 2.16-2.17, X eqs 11-12). Naming: `linear` is F's kappa1 and X's
// Q2; `quadratic` is F's kappa2 and X's Q1 (the papers swap the names, see physics-notes).
// Pi_ij has the units of P/rho^2 (m^5 kg^-1 s^-2), like the stress terms of the momentum equation.
#pragma once
#include <cmath>

#include "common/hd.hpp"
#include "common/tensor.hpp"

namespace impactsph {

template <class Real>
struct ViscosityParams {
  Real linear = Real(1);
  Real quadratic = Real(1);
  // Limited midpoint reconstruction of the pair's velocity jump (limited_midpoint_jump); off: the raw v_ij.
  bool limited = false;
  // Close-approach radius and fold of the limiter, as fractions of the pair smoothing length h_ij: the
  // reconstruction fades out when two particles come closer than about one spacing (close_eta = 1 / h_factor).
  Real close_eta = Real(1) / Real(1.2);
  Real close_fold = Real(0.2) / Real(1.2);
};

// Spacings at which the limiter lets the full jump back, and over how many it folds in (the defaults of the
// limited Monaghan-Gingold viscosity of LLNL's Spheral, etaCritFrac = 1 and etaFoldFrac = 0.2).
constexpr double kViscosityCloseApproachSpacings = 1.0;
constexpr double kViscosityCloseFoldSpacings = 0.2;
// close_spacings: the close-approach radius in spacings (0: the reconstruction never fades).
template <class Real>
ViscosityParams<Real> limited_viscosity_params(Real linear, Real quadratic, bool limited, Real h_factor,
                                               Real close_spacings = Real(kViscosityCloseApproachSpacings)) {
  ViscosityParams<Real> p;
  p.linear = linear;
  p.quadratic = quadratic;
  p.limited = limited;
  p.close_eta = close_spacings / h_factor;
  p.close_fold = Real(kViscosityCloseFoldSpacings) / h_factor;
  return p;
}

// Van Leer's limiter of the ratio r of two slopes, symmetric in r and 1/r: 4 r / (1 + r)^2, 1 where the
// slopes agree, 0 where they have opposite signs (r <= 0).
template <class Real>
IMPACTSPH_HD Real van_leer_limiter(Real r) {
  return choose(r > Real(0), Real(4) * r / ((Real(1) + r) * (Real(1) + r)), Real(0));
}

// The pair's velocity jump reconstructed to its midpoint (m/s), as finite-volume schemes take the jump their
// dissipation acts on (Frontiere, Raskin and Owen 2017, J. Comput. Phys. 332, 160, CRKSPH's limited
// viscosity; Rosswog 2020, MAGMA2): each side's velocity is carried half-way to the other by its own gradient,
//   v_ij* = v_ij - phi/2 (grad v_i + grad v_j) x_ij,
// phi the van Leer limiter of the two slopes x_ij . grad v . x_ij. A linear velocity field (uniform strain,
// shear and rotation, isochoric plastic flow) has no jump left, so a Monaghan term on it leaves smooth flow
// alone; a shock or a particle sliding past its neighbours (the non-affine share the gradient does not
// register) keeps its jump. When the two come closer than close_eta h the reconstruction fades out with
// exp(-((r/h - close_eta)/close_fold)^2), so that a pair being crushed meets the full viscosity.
// grad_v is dv_a/dx_b (1/s); x_ij = x_i - x_j (m); h the pair smoothing length (m).
template <class Real>
IMPACTSPH_HD Vec3<Real> limited_midpoint_jump(const ViscosityParams<ScalarOf<Real>>& p, Vec3<Real> xij, Vec3<Real> vij,
                                              const Mat3<Real>& grad_v_i, const Mat3<Real>& grad_v_j, Real h) {
  using std::exp;
  const Vec3<Real> di = grad_v_i * xij, dj = grad_v_j * xij;
  const Real si = dot(di, xij), sj = dot(dj, xij);
  const Real phi = choose(si * sj > Real(0), van_leer_limiter(si / sj), Real(0));
  const Real eta = norm(xij) / h;
  const FlagOf<Real> close = eta < Real(p.close_eta);
  if (!any_true(close)) return vij - (Real(0.5) * phi) * (di + dj);
  const Real f = (eta - p.close_eta) / p.close_fold;
  return vij - (Real(0.5) * choose(close, phi * exp(-f * f), phi)) * (di + dj);
}

// The jump the Monaghan term acts on (m/s). Off: the raw v_ij. Limited: the limited midpoint jump of a
// closing pair where it closes less than the raw jump, else the raw jump; an opening pair gets no viscosity.
// So the limited term never exceeds the Monaghan term of the raw jump (the viscous heating stays
// non-negative), and it is continuous in the pair's state: gated on the raw jump alone, a finite Pi_ij
// switched on and off at v_ij . x_ij = 0, where pairs in shear sit, and round-off decided which (the port
// and the reference parted by 1e-6 of the velocity in one step on the copper bar at 0.8 mm).
// grad_v is dv_a/dx_b (1/s); x_ij = x_i - x_j (m); h the pair smoothing length (m).
template <class Real>
IMPACTSPH_HD Vec3<Real> viscous_jump(const ViscosityParams<ScalarOf<Real>>& p, Vec3<Real> xij, Vec3<Real> vij,
                                     const Mat3<Real>& grad_v_i, const Mat3<Real>& grad_v_j, Real h) {
  if (!p.limited) return vij;
  const Real closing = dot(vij, xij);
  const Vec3<Real> none{Real(0), Real(0), Real(0)};
  if (!any_true(closing < Real(0))) return none;
  const Vec3<Real> jump = limited_midpoint_jump(p, xij, vij, grad_v_i, grad_v_j, h);
  return choose(closing < Real(0), choose(dot(jump, xij) > closing, jump, vij), none);
}

// xij = x_i - x_j, vij = v_i - v_j, h the pair smoothing length, c and rho the pair means.
template <class Real>
IMPACTSPH_HD Real monaghan_viscosity(const ViscosityParams<ScalarOf<Real>>& p, Vec3<Real> xij, Vec3<Real> vij, Real h,
                                     Real c_mean, Real rho_mean) {
  const Real vx = dot(vij, xij);
  if (!any_true(vx < Real(0))) return Real(0);
  const Real phi = h * vx / (norm2(xij) + Real(0.01) * h * h);
  return choose(vx < Real(0), (-p.linear * c_mean * phi + p.quadratic * phi * phi) / rho_mean, Real(0));
}

// Bulk (volumetric) viscosity, the von Neumann-Richtmyer form of finite-element solid elements (LS-DYNA's
// *CONTROL_BULK_VISCOSITY, Q1 quadratic and Q2 linear; Hallquist, LS-DYNA Theory Manual, "Artificial Bulk
// Viscosity"), taken from the particle's own corrected velocity divergence and the particle length l = h:
//   q = rho l (quadratic l (div v)^2 - linear c div v)   where div v < 0, else 0   (Pa),
// added to the pressure. It acts on the volumetric rate alone, so isochoric (plastic) flow feels none of it,
// unlike the pairwise Monaghan term, which also resists shear. Both coefficients 0: off.
template <class Real>
struct BulkViscosityParams {
  Real linear = Real(0);
  Real quadratic = Real(0);
};

template <class Real>
IMPACTSPH_HD Real bulk_viscosity(const BulkViscosityParams<Real>& p, Real div_v, Real rho, Real sound_speed, Real h) {
  if (!(div_v < Real(0))) return Real(0);
  return rho * h * (p.quadratic * h * div_v * div_v - p.linear * sound_speed * div_v);
}

// The bulk viscosity's share of (S - P I) / rho^2: q / rho^2, taken off the diagonal (m^5 kg^-1 s^-2).
template <class Real>
IMPACTSPH_HD Real bulk_viscosity_over_rho2(const BulkViscosityParams<Real>& p, Real div_v, Real rho, Real sound_speed,
                                           Real h) {
  return bulk_viscosity(p, div_v, rho, sound_speed, h) / (rho * rho);
}

// Adds the bulk viscosity to a particle's A = (S - P I) / rho^2 as to its pressure: A - (q / rho^2) I.
template <class Real>
IMPACTSPH_HD void add_bulk_viscosity(const BulkViscosityParams<Real>& p, Real div_v, Real rho, Real sound_speed, Real h,
                                     Sym3<Real>& a) {
  const Real q = bulk_viscosity_over_rho2(p, div_v, rho, sound_speed, h);
  a.xx -= q;
  a.yy -= q;
  a.zz -= q;
}

// Balsara (1995) shear limiter of particle i, in [0, 1]: |div v| / (|div v| + |curl v| + 0.0001 c/h).
// Near 1 in compression (shocks), near 0 in shear and isochoric plastic flow, where the Monaghan term
// otherwise acts as a physical viscosity. The pair uses the mean of the two factors.
template <class Real>
IMPACTSPH_HD Real balsara_factor(const Mat3<Real>& grad_v, Real sound_speed, Real h) {
  const Real div = grad_v.trace();
  const Real cx = grad_v.m[2][1] - grad_v.m[1][2], cy = grad_v.m[0][2] - grad_v.m[2][0], cz = grad_v.m[1][0] - grad_v.m[0][1];
  const Real curl = std::sqrt(cx * cx + cy * cy + cz * cz);
  const Real a = div < Real(0) ? -div : div;
  return a / (a + curl + Real(1e-4) * sound_speed / h);
}

}  // namespace impactsph
