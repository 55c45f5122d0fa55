// The per-pair terms of the two SPH passes, written once for both solvers (design.md, "physics is written
// once"). Each function adds neighbour j's contribution to the sums of particle i; the loops around them
// (neighbour lists in the reference, cell gathers in the gpu port) belong to the solvers.
// Notation: x_ij = x_i - x_j (m), v_ij = v_i - v_j (m/s), V_j = m_j / rho_j (m^3), gw = grad_i W_ij (1/m^4).
#pragma once
#include "common/artificial_stress.hpp"
#include "common/correction.hpp"
#include "common/damage.hpp"
#include "common/delta_sph.hpp"
#include "common/viscosity.hpp"

namespace impactsph {

// Pass 1 sums of particle i (F 2.13, F 2.19).
template <class Real>
struct GradientSums {
  Mat3<Real> L;          // correction matrix -sum V_j gw (x) x_ij, dimensionless
  Mat3<Real> L_damaged;  // the same with each pair scaled by 1 - D_ij, dimensionless; summed once apart
  Mat3<Real> G;          // uncorrected velocity gradient sum (1 - D_ij) V_j (v_j - v_i) (x) gw, 1/s
  Vec3<Real> grad_rho;   // uncorrected density gradient sum (1 - D_ij) V_j (rho_j - rho_i) gw, kg/m^4
  // Whether L_damaged is summed apart: until a pair enters it with another weight than L's, the two hold
  // the same sum, so L_damaged is not summed and damaged_L() is L (the same bits, a third fewer products
  // in an intact neighbourhood).
  bool apart;
  IMPACTSPH_HD static GradientSums zero() {
    return {Mat3<Real>::zero(), Mat3<Real>::zero(), Mat3<Real>::zero(), Vec3<Real>{Real(0), Real(0), Real(0)}, false};
  }
  IMPACTSPH_HD const Mat3<Real>& damaged_L() const { return apart ? L_damaged : L; }
};

// The weight of a pair in the scaled sums, (1 - D_ij) V_j (m^3), and none across a crack face. Face is bool,
// or a lane mask where the pairs are SIMD lanes (common/lanes.hpp).
template <class Real, class Face>
IMPACTSPH_HD Real damaged_gradient_weight(Real vol_j, Real damage_i, Real damage_j, Face crack_face) {
  return choose(crack_face, Real(0), damaged_pair_factor(damage_i, damage_j) * vol_j);
}
// The velocity and density gradient sums' share of a pair of weight vf (damaged_gradient_weight).
template <class Real>
IMPACTSPH_HD void add_gradient_terms(Mat3<Real>& G, Vec3<Real>& grad_rho, Real vf, Vec3<Real> gw, Vec3<Real> v_ji,
                                     Real drho_ji) {
  G = G + vf * outer(v_ji, gw);
  grad_rho += (vf * drho_ji) * gw;
}

// Neighbour j's share of the pass 1 sums: v_ji = v_j - v_i, drho_ji = rho_j - rho_i, damage_i and damage_j
// what the two bring into the damaged pair factor 1 - D_ij (pair_damage, damaged_pair_factor, F eq 4.10;
// 1 for an intact pair). F 4.10 scales the kernel gradient of every interaction, so the velocity and
// density gradients take it as the momentum and energy rates do: the continuity equation of a failed particle then sees the neighbours it still
// exchanges forces with, and an intact particle beside a crack does not strain with the fragments
// flying off it. Two correction matrices are summed: L from the unscaled gradient, for the momentum and
// energy rates (F's W-hat is the corrected kernel that 4.10 then scales; a scaled L there would cancel the
// scaling in L^-1), and L_damaged from the scaled one, for the gradients, whose sums it then corrects
// consistently: a linear field is differentiated exactly over the pairs that still interact, and a rigid
// rotation beside a failed layer has no strain rate (with the unscaled L it had a deviatoric rate of about
// 0.08 omega). For an intact neighbourhood the two are the same bits. A crack-face pair (crack_face: either
// side a compressive_crack_face) is left out of the scaled sums altogether: it carries no shear
// (crack_face_stress), so the intact side must not strain with the failed particles sliding past it
// either; its gradients are then those of the intact neighbours alone, one-sided and still first-order
// exact through L_damaged.
template <class Real>
IMPACTSPH_HD void add_gradient_pair(GradientSums<Real>& s, Real vol_j, Vec3<Real> gw, Vec3<Real> xij, Vec3<Real> v_ji,
                                    Real drho_ji, Real damage_i, Real damage_j, bool crack_face) {
  const Real vf = damaged_gradient_weight(vol_j, damage_i, damage_j, crack_face);
  if (!s.apart && !(vf == vol_j)) {
    s.L_damaged = s.L;
    s.apart = true;
  }
  accumulate_correction(s.L, vol_j, gw, xij);
  if (s.apart) accumulate_correction(s.L_damaged, vf, gw, xij);
  add_gradient_terms(s.G, s.grad_rho, vf, gw, v_ji, drho_ji);
}

// Pass 1 result: L^-1 (or the identity on fallback) for pass 2, the corrected velocity gradient
// grad v = sum (1 - D_ij) V_j (v_j - v_i) (x) L_d^-1 gw (1/s) and the renormalised density gradient
// L_d^-1 sum (kg/m^4), L_d the damaged correction matrix. Where L_d is ill-conditioned (a particle among
// failed ones, whose scaled sums are mostly zero) the gradients take L^-1 instead; fell_back counts L only.
template <class Real>
struct CorrectedGradients {
  Mat3<Real> l_inverse;
  Mat3<Real> grad_v;
  Vec3<Real> grad_rho;
  bool fell_back;
};
template <class Real>
IMPACTSPH_HD CorrectedGradients<Real> corrected_gradients(const GradientSums<Real>& s, const CorrectionParams<Real>& p) {
  CorrectedGradients<Real> r;
  r.l_inverse = correction_inverse(s.L, p, r.fell_back);
  Mat3<Real> gradient_inverse = r.l_inverse;
  if (!exactly_equal(s.damaged_L(), s.L)) {
    bool damaged_fell_back = true;
    const Mat3<Real> inv = correction_inverse(s.damaged_L(), p, damaged_fell_back);
    if (!damaged_fell_back) gradient_inverse = inv;
  }
  r.grad_v = s.G * gradient_inverse.transpose();
  r.grad_rho = gradient_inverse * s.grad_rho;
  return r;
}

// What particle i carries into the pair sums of pass 2.
template <class Real>
struct PairSide {
  Mat3<Real> A;          // (S - P I) / rho^2, m^5 kg^-1 s^-2
  Mat3<Real> l_inverse;  // correction L^-1
  Real damage;           // D, dimensionless
  Real av_factor;        // viscosity factor (1, or Balsara's)
  Real sound_speed;      // m/s
  Real rho;              // kg/m^3
  FlagOf<Real> crack_face;  // failed, with pairs that carry compression only (compressive_crack_face)
  Mat3<Real> R;          // artificial stress (artificial_stress.hpp), units of A; zero when off
  Mat3<Real> grad_v;     // velocity gradient dv_a/dx_b (1/s), for the limited viscosity; zero when it is off
};

// The pair stress of a crack face (either side a crack_face): the compressive mean stresses of the two
// sides, min(tr A_i / 3, 0) + min(tr A_j / 3, 0) times I (tr A / 3 = -P / rho^2), so that across a crack
// neither tension nor shear is carried, while the faces still push apart when pressed together.
// Units of A (m^5 kg^-1 s^-2).
template <class Real> IMPACTSPH_HD Mat3<Real> crack_face_stress(const Mat3<Real>& A_i, const Mat3<Real>& A_j) {
  const Real c = min_of(A_i.trace() / Real(3), Real(0)) + min_of(A_j.trace() / Real(3), Real(0));
  Mat3<Real> T = Mat3<Real>::zero();
  T.m[0][0] = c; T.m[1][1] = c; T.m[2][2] = c;
  return T;
}

// Neighbour j's share of the momentum (F 2.11) and energy (consistent F 2.12) rates of i, with the
// symmetrised corrected gradient gt = (1 - D_ij)(L_i^-1 + L_j^-1)/2 gw (F 2.14, F 4.10) and the Monaghan
// viscosity Pi_ij (F 2.16-2.17, scaled by the pair mean of the Balsara factors, taken on viscous_jump) and
// the artificial stress (R_i + R_j) f_ij^n (Gray, Monaghan and Swift 2001; stress_factor = f_ij^n, 0 when off):
//   dv_i/dt += m_j (A_i + A_j + (R_i + R_j) f_ij^n - Pi_ij I) gt   (m/s^2),
//   de_i/dt -= m_j/2 v_ij . (A_i + A_j + (R_i + R_j) f_ij^n - Pi_ij I) gt   (J/kg/s);
// at a crack face A_i + A_j becomes crack_face_stress(A_i, A_j) and carries no artificial stress.
// h_ij is the pair smoothing length (m), m_j the mass of j (kg).
template <class Real>
IMPACTSPH_HD_INLINE void add_momentum_energy_pair(const PairSide<Real>& i, const PairSide<Real>& j,
                                                  const ViscosityParams<ScalarOf<Real>>& visc, Vec3<Real> gw,
                                                  Vec3<Real> xij, Vec3<Real> vij, Real hij, Real m_j, Real stress_factor,
                                                  Vec3<Real>& acc, Real& de) {
  const Vec3<Real> gt = (Real(0.5) * damaged_pair_factor(i.damage, j.damage)) * ((i.l_inverse + j.l_inverse) * gw);
  const Vec3<Real> v_visc = viscous_jump(visc, xij, vij, i.grad_v, j.grad_v, hij);
  const Real pi_ij = Real(0.5) * (i.av_factor + j.av_factor) *
                     monaghan_viscosity(visc, xij, v_visc, hij, Real(0.5) * (i.sound_speed + j.sound_speed),
                                        Real(0.5) * (i.rho + j.rho));
  const FlagOf<Real> face = i.crack_face | j.crack_face;
  Mat3<Real> T = i.A + j.A;
  if (any_true(face)) T = choose(face, crack_face_stress(i.A, j.A), T);
  const FlagOf<Real> stressed = (stress_factor > Real(0)) & !face;
  if (any_true(stressed)) T = choose(stressed, T + stress_factor * (i.R + j.R), T);
  T.m[0][0] -= pi_ij; T.m[1][1] -= pi_ij; T.m[2][2] -= pi_ij;
  const Vec3<Real> tg = T * gt;
  acc += m_j * tg;
  de -= Real(0.5) * m_j * dot(vij, tg);  // (v_j - v_i) . T gt
}

// Neighbour j's delta-SPH diffusion share (delta_sph_term) scaled by the damaged pair factor 1 - D_ij
// (F 4.10), as every pair term is; damage_i, damage_j as in add_gradient_pair. Units of delta_sph_term.
template <class Real>
IMPACTSPH_HD Real damaged_delta_sph_term(Real damage_i, Real damage_j, Real vol_j, Real rho_i, Real rho_j,
                                         Vec3<Real> xij, Vec3<Real> grad_rho_i, Vec3<Real> grad_rho_j,
                                         Vec3<Real> gw) {
  return damaged_pair_factor(damage_i, damage_j) * delta_sph_term(vol_j, rho_i, rho_j, xij, grad_rho_i, grad_rho_j, gw);
}

// Continuity with delta-SPH (Marrone form, delta_sph.hpp): drho_i/dt = -rho_i tr(grad v_i) + delta h_i c0 D_i
// (kg/m^3/s), D_i the sum of delta_sph_term over neighbours of the same material, c0 the reference sound
// speed of i's material (m/s). Its two parts: the compression of the velocity field and the diffusion.
template <class Real> IMPACTSPH_HD Real compression_density_rate(Real rho_i, const Mat3<Real>& grad_v) {
  return -rho_i * grad_v.trace();
}
template <class Real> IMPACTSPH_HD Real diffusion_density_rate(Real delta, Real h_i, Real c0, Real diffusion) {
  return delta * h_i * c0 * diffusion;
}
template <class Real>
IMPACTSPH_HD Real continuity_rate(Real rho_i, const Mat3<Real>& grad_v, Real delta, Real h_i, Real c0, Real diffusion) {
  return compression_density_rate(rho_i, grad_v) + diffusion_density_rate(delta, h_i, c0, diffusion);
}

}  // namespace impactsph
