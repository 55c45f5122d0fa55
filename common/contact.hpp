// Penalty contact between particles of different bodies (F section 4.1, eqs 4.1-4.6), rebuilt as one pair
// force applied equal and opposite (physics-notes). F's criteria 4.4-4.6 are accelerations of particle i;
// F 4.4 as printed, (m_k/m_i) p/dt^2, gives the pair forces m_k p/dt^2 on i and m_i p/dt^2 on k, which
// differ when the masses differ, so the contact would create momentum. Here each criterion is a force
// built from symmetric pair quantities (reduced masses, series moduli), so that swapping i and k flips its
// sign exactly. Units: lengths m, velocities m/s, masses kg, moduli Pa, densities kg/m^3, dt s, forces N.
#pragma once
#include "common/tensor.hpp"

namespace impactsph {

template <class Real>
struct PenaltyContactParams {
  Real scale = Real(0.3);  // K_p of F eq 4.3, dimensionless (F Table 3)
};

// a b / (a + b), the series (reduced) combination of two non-negative pair quantities; 0 when both are 0.
// Exactly symmetric in a and b (IEEE + and x commute). When one of them is 0 the result is 0.
template <class Real> IMPACTSPH_HD Real series_combination(Real a, Real b) {
  const Real s = a + b;
  return s > Real(0) ? a * b / s : Real(0);
}

// Penalty force on particle i from particle k (N); the caller applies minus it on k.
//   x_ik = x_i - x_k (m), v_ik = v_i - v_k (m/s),
//   penetration p = contact_distance - |x_ik| (F eq 4.1; F writes h_i + h_k for the distance at which
//     two particles touch, here the caller passes it),
//   normal n = x_ik / |x_ik| (F eq 4.2), penetration rate p_dot = -(v_ik . n) (> 0 while approaching),
//   force = K_p max(F1, F2, F3) n (F eq 4.3) with
//     F1 = m* p / dt^2, m* = m_i m_k / (m_i + m_k)                       (F eq 4.4 times a mass),
//     F2 = sqrt(h_i h_k / (h_i + h_k)) G* p^(3/2), G* = G_i G_k/(G_i + G_k) (F eq 4.5 times m_i; Hertz-like),
//     F3 = M_h p_dot / dt if p_dot > 0, else 0, M_h = a_i a_k / (a_i + a_k), a = rho h^3
//                                                                        (F eq 4.6 times m_i).
// G* is the series shear modulus: 0 when either body has no shear modulus (a fluid), and F1 or F3 then
// carry the contact. Zero force when the particles do not overlap (p <= 0), when they coincide
// (|x_ik| == 0: no direction to push along), and F1 = F3 = 0 when dt <= 0. Swapping every pair argument
// (i <-> k, so x_ik -> -x_ik and v_ik -> -v_ik) returns exactly minus the force, to the last bit.
template <class Real>
IMPACTSPH_HD Vec3<Real> penalty_contact_force(const PenaltyContactParams<Real>& params, Vec3<Real> x_ik, Vec3<Real> v_ik,
                                              Real contact_distance, Real m_i, Real m_k, Real h_i, Real h_k, Real G_i,
                                              Real G_k, Real rho_i, Real rho_k, Real dt) {
  const Vec3<Real> none{Real(0), Real(0), Real(0)};
  const Real r2 = norm2(x_ik);
  if (!(r2 > Real(0))) return none;
  const Real r = std::sqrt(r2);
  const Real p = contact_distance - r;
  if (!(p > Real(0))) return none;
  const Vec3<Real> n = (Real(1) / r) * x_ik;
  const Real p_dot = -dot(v_ik, n);

  Real f1 = Real(0), f3 = Real(0);
  if (dt > Real(0)) {
    f1 = series_combination(m_i, m_k) * p / (dt * dt);
    if (p_dot > Real(0)) f3 = series_combination(rho_i * h_i * h_i * h_i, rho_k * h_k * h_k * h_k) * p_dot / dt;
  }
  const Real f2 = std::sqrt(series_combination(h_i, h_k)) * series_combination(G_i, G_k) * p * std::sqrt(p);
  const Real magnitude = params.scale * max_of(max_of(f1, f2), f3);
  return magnitude * n;
}

// Distance at which two particles touch (m): SRAD (h_i + h_j)/2 when srad > 0 (X eqs 18, 20), else the
// fixed contact distance (m; a case file gives it in spacings).
template <class Real> IMPACTSPH_HD Real contact_touch_distance(Real srad, Real fixed_distance, Real h_i, Real h_j) {
  return srad > Real(0) ? srad * Real(0.5) * (h_i + h_j) : fixed_distance;
}

// Power the contact pair takes out of the kinetic energy (W): with the force F on i and -F on k,
// dKE/dt = F . v_i - F . v_k = F . v_ik, so the rate is -F . v_ik. Positive while the particles approach
// (energy stored in, or dissipated by, the penalty), negative while the penalty pushes them apart.
template <class Real> IMPACTSPH_HD Real penalty_contact_energy_rate(Vec3<Real> force_on_i, Vec3<Real> v_ik) {
  return -dot(force_on_i, v_ik);
}

}  // namespace impactsph
