// The stages of a step, per particle and per pair, written once for both solvers (issue 16). The reference
// (reference/solver.cpp) and the gpu port (gpu/solver_impl.hpp) hold the arrays and run the loops, each in
// its own order and storage; what a point computes in the gather, what a neighbour adds in pass 1 and pass
// 2, how a row's sums become its gradients and rates, the advance, the history update, the time step and
// the finiteness check are the functions below. Every formula they apply is a common/ function with its
// equation; these only say which fields go where.
//
// An evaluation's points are the real particles and the mirror images (ghosts) of the symmetry planes.
// StagePoints points into the work arrays that hold them: reals then ghosts in the reference, sorted slots
// in the gpu port. Positions are double in both precisions (displacements of 1e-7 of a spacing must not be
// lost); a pair's separation is taken in double and then rounded to Real.
#pragma once
#include <cstdint>

#include "common/artificial_stress.hpp"
#include "common/contact.hpp"
#include "common/damage.hpp"
#include "common/delta_sph.hpp"
#include "common/hd.hpp"
#include "common/integration.hpp"
#include "common/kernels.hpp"
#include "common/material.hpp"
#include "common/pair_terms.hpp"
#include "common/smoothing_length.hpp"
#include "common/timestep.hpp"
#include "common/viscosity.hpp"

namespace impactsph {

using Vec3p = Vec3<double>;  // positions, m, double in both precisions
constexpr int kMaxPlanes = 6;

template <class To, class From> IMPACTSPH_HD Vec3<To> cast3(Vec3<From> a) {
  return {static_cast<To>(a.x), static_cast<To>(a.y), static_cast<To>(a.z)};
}

// A symmetry plane or wall of the scene.
struct Plane {
  int axis;
  double position;  // m
  double side;      // +1 or -1: the side the model lies on
  bool wall;        // pushes but does not pull (lets_go_of_wall, common/integration.hpp)
};

// How two bodies interact: shared SPH sums (penalty = 0) or penalty contact (F 4.1-4.6).
template <class Real>
struct PairContact {
  int penalty;
  Real scale;     // K_p
  Real distance;  // contact distance, m (when srad is 0)
  Real srad;      // > 0: the particles touch at srad (h_i + h_j)/2 instead (X eqs 18, 20)
  IMPACTSPH_HD Real touch(Real h_i, Real h_j) const { return contact_touch_distance(srad, distance, h_i, h_j); }
};

// Variable smoothing length of a body (X eqs 9-10): on or off, and the bounds of h (m).
template <class Real>
struct BodySmoothing {
  int variable;
  Real h_lo, h_hi;
};

// The numerics and the planes of a scene, as the stages read them (common/stage_setup.hpp builds them).
template <class Real>
struct StageParams {
  KernelKind kernel;
  ViscosityParams<Real> visc;
  CorrectionParams<Real> correction;
  Real delta;
  Real cfl;
  bool balsara;
  BulkViscosityParams<Real> bulk;  // volumetric viscosity in compression (common/viscosity.hpp)
  bool bulk_on;
  ArtificialStressParams<Real> art;  // artificial stress against the tensile instability (common/artificial_stress.hpp)
  int body_count;
  int plane_count;
  Plane planes[kMaxPlanes];
  unsigned wall_planes;  // bit k: plane k is a wall
};

// The kernel of the pair loops: chosen at run time (the reference) or fixed at compile time (the gpu port,
// whose loops then carry no select); both give kernel_grad_factor's bits.
struct RuntimeKernel {
  KernelKind k;
  IMPACTSPH_HD KernelKind kind() const { return k; }
  template <class Real> IMPACTSPH_HD Real grad_factor(Real r, Real h) const { return kernel_grad_factor(k, r, h); }
};
template <KernelKind K>
struct FixedKernel {
  IMPACTSPH_HD KernelKind kind() const { return K; }
  template <class Real> IMPACTSPH_HD Real grad_factor(Real r, Real h) const { return kernel_grad_factor_of<K>(r, h); }
};

// Mirror image of a point through the planes of `mask`, taken in plane order (each plane mirrors the reals
// and the images made so far): exists when the point, as mirrored so far, lies within `margin` of each plane
// it is mirrored in. x' = sign x + shift per axis.
IMPACTSPH_HD bool mirror_image(const Plane* planes, int plane_count, int mask, Vec3p x, double margin, Vec3p& sign,
                               Vec3p& shift) {
  sign = Vec3p{1, 1, 1};
  shift = Vec3p{0, 0, 0};
  for (int k = 0; k < plane_count; ++k)
    if ((mask & (1 << k)) && !mirror_through_plane(sign, shift, x, planes[k].axis, planes[k].position, margin))
      return false;
  return true;
}

// The walls (bit k for plane k) that a particle with deviatoric stress S and pressure P lets go of
// (lets_go_of_wall, common/integration.hpp).
template <class Real>
IMPACTSPH_HD unsigned walls_let_go(const Plane* planes, int plane_count, const Sym3<Real>& S, Real P,
                                   const Vec3<Real>& v) {
  unsigned let_go = 0;
  for (int k = 0; k < plane_count; ++k)
    if (planes[k].wall && lets_go_of_wall(S, P, v, planes[k].axis, static_cast<Real>(planes[k].side)))
      let_go |= 1u << k;
  return let_go;
}

// The work arrays of one evaluation, by point (real or ghost).
template <class Real>
struct StagePoints {
  Vec3p* x;
  Vec3<Real>* v;
  Real *rho, *p, *c, *m, *h, *vol;
  Real* damage;           // what the point brings into the damaged pair factor (pair_damage)
  Real* av;               // viscosity factor: 1, or Balsara's
  Sym3<Real>* A;          // (S - P I) / rho^2, with the bulk viscosity in P once pass 1 has added it
  Sym3<Real>* S;          // deviatoric stress after apply_failure
  Sym3<Real>* R;          // artificial stress (null when off)
  std::int32_t *mat, *body;
  unsigned* let_go;       // walls a real lets go of (bit k for plane k; ghosts 0)
  unsigned* image_walls;  // walls a ghost is mirrored through (reals 0): a pair takes no part when
                          // image_walls[j] & let_go[i] (lets_go_of_wall, common/integration.hpp)
  Mat3<Real>* linv;
  Mat3<Real>* grad_v;     // velocity gradient, ghosts mirrored (null unless the viscosity is limited)
  Vec3<Real>* grad_rho;
  const PairContact<Real>* contact;  // [body_a * body_count + body_b]
  int body_count;
  IMPACTSPH_HD const PairContact<Real>& pair(std::int32_t a, std::int32_t b) const { return contact[a * body_count + b]; }
  IMPACTSPH_HD bool in_penalty_contact(std::int32_t a) const {
    for (std::int32_t b = 0; b < body_count; ++b)
      if (pair(a, b).penalty) return true;
    return false;
  }
};

// ---------------------------------------------------------------------------------------------------
// Gather: what a point carries from its own state.

// EOS pressure (with the JH-2 bulking increment) and sound speed; the stress and pressure at its damage
// (apply_failure: a failed metal no deviator and no tension, F 4.2; JH-2 the tensile limit); the damage it
// brings into the pair factor (its material's choice, pair_damage).
template <class Real>
struct GatheredPoint {
  Real P, c, pair_damage;
  Sym3<Real> S;
};
template <class Real>
IMPACTSPH_HD GatheredPoint<Real> gather_point(const MaterialParams<Real>& mat, Real rho, Real energy, Real bulking,
                                              Real damage, const Sym3<Real>& S) {
  GatheredPoint<Real> g;
  g.c = 0;
  g.P = material_pressure(mat, rho, energy, bulking, g.c);
  g.S = S;
  apply_failure(mat, g.S, g.P, damage);
  g.pair_damage = pair_damage(mat, damage);
  return g;
}

// A ghost as its source's mirror image x' = sign x + shift (mirror_image): the position, velocity and
// deviatoric stress mirrored, and no mass when the source let go of a wall the image is mirrored through
// (image_walls & source_let_go, lets_go_of_wall), so that the image takes no part in the pairs.
template <class Real>
struct MirroredPoint {
  Vec3p x;
  Vec3<Real> v;
  Sym3<Real> S;
  Real m;
};
template <class Real>
IMPACTSPH_HD MirroredPoint<Real> mirror_point(const Vec3p& sign, const Vec3p& shift, unsigned image_walls,
                                              unsigned source_let_go, const Vec3p& x, const Vec3<Real>& v,
                                              const Sym3<Real>& S, Real m) {
  const Vec3<Real> s = cast3<Real>(sign);
  return {hadamard(sign, x) + shift, hadamard(s, v), mirror(S, s), (image_walls & source_let_go) ? Real(0) : m};
}

// (S - P I) / rho^2 (m^5 kg^-1 s^-2), the stress term of the momentum and energy pairs (F 2.11-2.12).
template <class Real> IMPACTSPH_HD Sym3<Real> stress_over_rho2(const Sym3<Real>& S, Real P, Real rho) {
  const Real inv_rho2 = Real(1) / (rho * rho);
  return inv_rho2 * Sym3<Real>{S.xx - P, S.yy - P, S.zz - P, S.xy, S.yz, S.zx};
}

// The stress terms pass 2 reads of point s at density rho (kg/m^3), from its stress and pressure in the work
// arrays: (S - P I) / rho^2, and the artificial stress from it (before any viscosity joins it).
template <class Real>
IMPACTSPH_HD void set_stress_terms(const StageParams<Real>& prm, const StagePoints<Real>& w, std::int64_t s, Real rho) {
  w.A[s] = stress_over_rho2(w.S[s], w.p[s], rho);
  if (prm.art.on()) w.R[s] = artificial_stress(prm.art, w.A[s]);
}

// ---------------------------------------------------------------------------------------------------
// Pass 1: correction matrix L_i (F 2.13), velocity gradient, renormalised density gradient (F 2.19), the
// gradients scaled by the damage factor 1 - D_ij (F 4.10) as the pass 2 terms are.

// What a row of pass 1 reads of its own point i.
template <class Real>
struct GradientRow {
  Vec3p x;
  Vec3<Real> v;
  Real rho, h, damage;
  bool face;
  std::int32_t body;
  unsigned let_go;
};
template <class Real>
IMPACTSPH_HD GradientRow<Real> gradient_row(const StagePoints<Real>& w, const MaterialParams<Real>* mats, std::int64_t i) {
  return {w.x[i], w.v[i], w.rho[i], w.h[i], w.damage[i], compressive_crack_face(mats, w.mat[i], w.damage[i]), w.body[i],
          w.let_go[i]};
}

// The geometry of list entry j of row i: x_ij = x_i - x_j (taken in double, then rounded to Real), the
// pair smoothing length h_ij = (h_i + h_j) / 2 and r = |x_ij| (m). Both passes take it of every pair.
template <class Real>
struct PairGeometry {
  Vec3<Real> xij;
  Real hij, r;
  IMPACTSPH_HD bool in_support() const { return r < kernel_support(hij); }
};
// The same with r given: the reference's pass loops take r once, in pass 1's candidate loop, as norm(x_ij).
template <class Real>
IMPACTSPH_HD PairGeometry<Real> pair_geometry_at(const StagePoints<Real>& w, const Vec3p& x_i, Real h_i, std::int32_t j,
                                                 Real r) {
  return {cast3<Real>(x_i - w.x[j]), Real(0.5) * (h_i + w.h[j]), r};
}
template <class Real>
IMPACTSPH_HD PairGeometry<Real> pair_geometry(const StagePoints<Real>& w, const Vec3p& x_i, Real h_i, std::int32_t j) {
  PairGeometry<Real> g = pair_geometry_at(w, x_i, h_i, j, Real(0));
  g.r = norm(g.xij);
  return g;
}

// Whether row i (of body body_i, letting go of the walls let_go_i) shares SPH sums with point j within its
// support: not bodies in penalty contact, not an image behind a wall i let go of.
template <class Real>
IMPACTSPH_HD bool shares_sums(const StagePoints<Real>& w, std::int32_t body_i, unsigned let_go_i, std::int32_t j) {
  return !(w.pair(body_i, w.body[j]).penalty || (w.image_walls[j] & let_go_i));
}

// Neighbour j's share of row i's pass 1 sums (add_gradient_pair) where the two share sums, with the pair's
// x_ij and kernel gradient gw = grad_i W_ij (1/m^4).
template <class Real>
IMPACTSPH_HD void add_gradient_sph_pair(const StagePoints<Real>& w, const MaterialParams<Real>* mats,
                                        const GradientRow<Real>& i, std::int32_t j, const Vec3<Real>& xij,
                                        const Vec3<Real>& gw, GradientSums<Real>& sums) {
  const bool face = i.face || compressive_crack_face(mats, w.mat[j], w.damage[j]);
  add_gradient_pair(sums, w.vol[j], gw, xij, w.v[j] - i.v, w.rho[j] - i.rho, i.damage, w.damage[j], face);
}

// Neighbour j's share of row i's pass 1 sums (add_gradient_pair). Returns whether j lies within the kernel
// support (a neighbour, for the statistics); bodies in penalty contact share no sums, nor does i with an
// image behind a wall it let go of.
template <class Kernel, class Real>
IMPACTSPH_HD bool add_gradient_neighbour(const Kernel& kernel, const StagePoints<Real>& w, const MaterialParams<Real>* mats,
                                         const GradientRow<Real>& i, std::int32_t j, GradientSums<Real>& sums) {
  const PairGeometry<Real> g = pair_geometry(w, i.x, i.h, j);
  if (!g.in_support()) return false;
  if (!shares_sums(w, i.body, i.let_go, j)) return true;
  add_gradient_sph_pair(w, mats, i, j, g.xij, kernel.grad_factor(g.r, g.hij) * g.xij, sums);
  return true;
}

// A row's gradients from its sums, and what follows from them for the point: the viscosity factor (1, or
// the Balsara shear limiter) and the bulk viscosity from its own div v, added to the pressure in
// (S - P I)/rho^2 (viscosity.hpp; pass 1 does not read A). Writes linv, grad_rho, av, A (and grad_v where
// the limited viscosity keeps it) of point s; returns the gradients.
template <class Real>
IMPACTSPH_HD CorrectedGradients<Real> finish_gradient_row(const StageParams<Real>& prm, const StagePoints<Real>& w,
                                                          std::int64_t s, const GradientSums<Real>& sums) {
  const CorrectedGradients<Real> cg = corrected_gradients(sums, prm.correction);
  w.linv[s] = cg.l_inverse;
  w.grad_rho[s] = cg.grad_rho;
  if (prm.visc.limited) w.grad_v[s] = cg.grad_v;
  w.av[s] = prm.balsara ? balsara_factor(cg.grad_v, w.c[s], w.h[s]) : Real(1);
  if (prm.bulk_on) add_bulk_viscosity(prm.bulk, cg.grad_v.trace(), w.rho[s], w.c[s], w.h[s], w.A[s]);
  return cg;
}

// A ghost takes its source's pass 1 results, mirrored by `sign` (the viscosity factor and the bulk
// viscosity's share of A are its source's: isotropic, or mirrored with A).
template <class Real>
IMPACTSPH_HD void mirror_gradient_row(const StageParams<Real>& prm, const StagePoints<Real>& w, std::int64_t ghost,
                                      std::int64_t source, const Vec3<Real>& sign) {
  w.linv[ghost] = mirror(w.linv[source], sign);
  w.grad_rho[ghost] = hadamard(sign, w.grad_rho[source]);
  w.av[ghost] = w.av[source];
  if (prm.bulk_on) w.A[ghost] = mirror(w.A[source], sign);
  if (prm.visc.limited) w.grad_v[ghost] = mirror(w.grad_v[source], sign);
}

// ---------------------------------------------------------------------------------------------------
// Pass 2: continuity with delta-SPH (Marrone form), momentum (F 2.11) and energy (consistent F 2.12), the
// pair terms (diffusion included) scaled by the damage factor 1 - D_ij (F 4.10); penalty contact
// (F 4.1-4.6) between bodies that do not share sums.

// What point s carries into the pairs of pass 2.
template <class Real>
IMPACTSPH_HD PairSide<Real> pair_side(const StageParams<Real>& prm, const StagePoints<Real>& w,
                                      const MaterialParams<Real>* mats, std::int64_t s) {
  return {w.A[s].full(), w.linv[s], w.damage[s], w.av[s], w.c[s], w.rho[s],
          compressive_crack_face(mats, w.mat[s], w.damage[s]), prm.art.on() ? w.R[s].full() : Mat3<Real>::zero(),
          prm.visc.limited ? w.grad_v[s] : Mat3<Real>::zero()};
}

// What a row of pass 2 reads of its own point i.
template <class Real>
struct RateRow {
  Vec3p x;
  Vec3<Real> v, grad_rho;
  Real h, m;
  std::int32_t mat, body;
  unsigned let_go;
  PairSide<Real> side;
};
template <class Real>
IMPACTSPH_HD RateRow<Real> rate_row(const StageParams<Real>& prm, const StagePoints<Real>& w,
                                    const MaterialParams<Real>* mats, std::int64_t i) {
  return {w.x[i], w.v[i], w.grad_rho[i], w.h[i], w.m[i], w.mat[i], w.body[i], w.let_go[i], pair_side(prm, w, mats, i)};
}

// Neighbour j's share of row i's momentum and energy rates and delta-SPH diffusion (same material only),
// where the two share sums, with the pair's geometry g and kernel gradient gw = grad_i W_ij (1/m^4). acc in
// m/s^2, de in J/kg/s, diffusion in the units of delta_sph_term.
template <class Real>
IMPACTSPH_HD void add_rate_sph_pair(KernelKind kernel, const StageParams<Real>& prm, const StagePoints<Real>& w,
                                    const MaterialParams<Real>* mats, const RateRow<Real>& i, std::int32_t j,
                                    const PairGeometry<Real>& g, const Vec3<Real>& gw, Vec3<Real>& acc, Real& de,
                                    Real& diffusion) {
  const Real stress_factor = artificial_stress_pair_factor(prm.art, kernel, g.r, g.hij);
  add_momentum_energy_pair(i.side, pair_side(prm, w, mats, j), prm.visc, gw, g.xij, i.v - w.v[j], g.hij, w.m[j],
                           stress_factor, acc, de);
  if (w.mat[j] == i.mat)
    diffusion += damaged_delta_sph_term(i.side.damage, w.damage[j], w.vol[j], i.side.rho, w.rho[j], g.xij, i.grad_rho,
                                        w.grad_rho[j], gw);
}

// Neighbour j's share of row i's rates (add_rate_sph_pair) where j shares SPH sums with i: within the kernel
// support, not in penalty contact, not an image behind a wall i let go of. Returns whether j added anything.
template <class Kernel, class Real>
IMPACTSPH_HD bool add_rate_neighbour(const Kernel& kernel, const StageParams<Real>& prm, const StagePoints<Real>& w,
                                     const MaterialParams<Real>* mats, const RateRow<Real>& i, std::int32_t j,
                                     Vec3<Real>& acc, Real& de, Real& diffusion) {
  const PairGeometry<Real> g = pair_geometry(w, i.x, i.h, j);
  if (!g.in_support() || !shares_sums(w, i.body, i.let_go, j)) return false;
  add_rate_sph_pair(kernel.kind(), prm, w, mats, i, j, g, kernel.grad_factor(g.r, g.hij) * g.xij, acc, de, diffusion);
  return true;
}

// Neighbour j's penalty contact force on row i (F 4.1-4.6; N) and half the pair's contact energy rate (W),
// where the two bodies are in penalty contact; nothing otherwise. dt: the step (s), which sets the spring.
template <class Real>
IMPACTSPH_HD void add_contact_neighbour(const StagePoints<Real>& w, const MaterialParams<Real>* mats,
                                        const RateRow<Real>& i, std::int32_t j, Real dt, Vec3<Real>& force,
                                        Real& power) {
  const PairContact<Real>& pc = w.pair(i.body, w.body[j]);
  if (!pc.penalty) return;
  const Vec3<Real> xij = cast3<Real>(i.x - w.x[j]);
  const Vec3<Real> vij = i.v - w.v[j];
  const Vec3<Real> f = penalty_contact_force(PenaltyContactParams<Real>{pc.scale}, xij, vij, pc.touch(i.h, w.h[j]),
                                             i.m, w.m[j], i.h, w.h[j], mats[i.mat].strength.shear_modulus,
                                             mats[w.mat[j]].strength.shear_modulus, i.side.rho, w.rho[j], dt);
  force += f;
  power += Real(0.5) * penalty_contact_energy_rate(f, vij);
}

// The rates of a real particle from its row's sums.
template <class Real>
struct PointRates {
  Vec3<Real> vel, acc;   // dx/dt (m/s), dv/dt (m/s^2)
  Real drho, de;         // kg/m^3/s, J/kg/s
  Real drho_diffusion;   // the delta-SPH diffusion's share of drho, kg/m^3/s
  Sym3<Real> dS;         // Jaumann deviatoric stress rate of the strength model (F 3.5-3.7), Pa/s
  Real strain_rate;      // equivalent strain rate, 1/s
  Real contact_power;    // W
};
template <class Real>
IMPACTSPH_HD PointRates<Real> point_rates(const StageParams<Real>& prm, const StagePoints<Real>& w,
                                          const MaterialParams<Real>& mat, std::int64_t s, const Mat3<Real>& grad_v,
                                          const Vec3<Real>& acc, Real de, Real diffusion, const Vec3<Real>& contact,
                                          Real contact_power, bool fixed) {
  PointRates<Real> f;
  f.dS = deviatoric_stress_rate(mat, w.S[s], grad_v);
  f.strain_rate = equivalent_strain_rate(grad_v);
  const Real c0 = std::sqrt(eos_reference_sound_speed2(mat.eos));
  f.drho_diffusion = diffusion_density_rate(prm.delta, w.h[s], c0, diffusion);
  f.drho = compression_density_rate(w.rho[s], grad_v) + f.drho_diffusion;
  f.de = de;
  f.contact_power = contact_power;
  if (fixed) {
    f.vel = Vec3<Real>{0, 0, 0};
    f.acc = Vec3<Real>{0, 0, 0};
  } else {
    f.vel = w.v[s];
    f.acc = acc + (Real(1) / w.m[s]) * contact;
  }
  return f;
}

// ---------------------------------------------------------------------------------------------------
// Advance, history, time step, finiteness.

// y = y0 + dt f with the plane reflection, the density floor and the plastic return at the history variables
// of the step start (integration.hpp, material.hpp). The state is (x, v, rho, e, S); eps_p, T, bulking and D
// are the step start's. Returns the plastic return's increments for finish_point.
// dt_x is the step for the positions, in double: the same dt, not rounded to a float Real.
template <class Real>
IMPACTSPH_HD PlasticResult<Real> advance_point(const StageParams<Real>& prm, const MaterialParams<Real>& mat, Real dt,
                                               double dt_x, Vec3p& x, Vec3<Real>& v, Real& rho, Real& e, Sym3<Real>& S,
                                               const Vec3<Real>& dx, const Vec3<Real>& dv, Real drho, Real de,
                                               const Sym3<Real>& dS, Real strain_rate, Real eps_p, Real T,
                                               Real bulking, Real D) {
  x = x + dt_x * cast3<double>(dx);
  v = v + dt * dv;
  for (int k = 0; k < prm.plane_count; ++k)
    reflect_at_plane(x, v, prm.planes[k].axis, prm.planes[k].position, prm.planes[k].side);
  rho = advance_density(mat, rho, drho, dt);
  e = e + dt * de;
  S = S + dt * dS;
  return trial_plastic_return(mat, S, eps_p, strain_rate, T, rho, e, bulking, D);
}

// ---------------------------------------------------------------------------------------------------
// Leapfrog: kick-drift-kick (velocity Verlet) with a staggered deformation state, one evaluation of the
// rates per step (numerics.integrator = "leapfrog"; docs/time-integration.md).
//
// A step from t_n to t_n+1 = t_n + dt, with a_n and (de/dt)_n carried from the evaluation of the step before:
//   kick, drift   v_h = v_n + dt/2 a_n,   x_n+1 = x_n + dt v_h
//   pass 1        at x_n+1 with v_h: the velocity gradient G of the half-step velocity
//   deform        rho and S from t_n to t_n+1 at the rates G gives them (continuity, Jaumann; the state they
//                 read taken at t_n+1/2 by the midpoint rule per particle) and the density's delta-SPH
//                 diffusion (below), S through the plastic return
//   pass 2        at x_n+1 with rho_n+1, S_n+1, the predicted v* = v_h + dt/2 a_n and e* = e_n + dt (de/dt)_n:
//                 a_n+1, (de/dt)_n+1 and the delta-SPH diffusion
//   kick          v_n+1 = v_h + dt/2 a_n+1,   e_n+1 = e_n + dt/2 ((de/dt)_n + (de/dt)_n+1)
// Positions and velocities are velocity Verlet. Density and deviatoric stress are functions of the
// deformation, as positions are: they live at the ends of the step with x and are advanced by the rates of
// the half-step velocity, so that the elastic wave (v against S and rho) is integrated as a mass against
// its spring is in velocity Verlet, stable up to omega dt = 2 without growth (the midpoint rule grows by
// (omega dt)^4/8 a step). The internal energy lives with the velocity: its rate is the stress power of the
// pairs, which takes the velocity at the end of the step (v*, to O(dt^2)), and the trapezoidal rule over
// both ends then conserves kinetic plus internal energy to O(dt^2) per unit time without a secular drift.
// The delta-SPH diffusion of the density field of pass 1 (at t_n) is known only after pass 2, while pass 2's
// pressure already needs rho_n+1: the deform takes the diffusion at t_n+1/2 extrapolated from the last two
// evaluations (of the density at t_n-1 and t_n-2), D = (5 D_n-1 - 3 D_n-2)/2, second order (both are carried;
// the extrapolation is stable for the diffusion's small rates, lambda dt > -1/2).

// A particle's kick and drift: the half-step velocity v_h, the position x_n+1 and the predicted velocity v*
// and energy e*. A fixed particle does not move; a particle that crossed a symmetry plane is reflected back
// with the normal components of v_h and v* reversed.
template <class Real>
struct KickDrift {
  Vec3p x;                   // x_n+1, m
  Vec3<Real> v_half, v_end;  // v_h and v*, m/s
  Real e_end;                // e*, J/kg
};
template <class Real>
IMPACTSPH_HD KickDrift<Real> kick_drift_point(const StageParams<Real>& prm, double dt, bool fixed, const Vec3p& x,
                                              const Vec3<Real>& v, Real e, const Vec3<Real>& acc, Real de) {
  const Real half_dt = static_cast<Real>(0.5 * dt);
  KickDrift<Real> k;
  k.v_half = v + half_dt * acc;
  k.v_end = k.v_half + half_dt * acc;
  k.x = fixed ? x : x + dt * cast3<double>(k.v_half);
  for (int a = 0; a < prm.plane_count; ++a)
    if (reflect_at_plane(k.x, k.v_half, prm.planes[a].axis, prm.planes[a].position, prm.planes[a].side)) {
      const int axis = prm.planes[a].axis;
      k.v_end[axis] = -k.v_end[axis];
    }
  k.e_end = e + static_cast<Real>(dt) * de;
  return k;
}

// The history variables of the step start that the plastic return reads: plastic strain, temperature (K),
// the JH-2 bulking pressure (Pa) and damage.
template <class Real>
struct StepHistory {
  Real eps_p, T, bulking, D;
};

// The delta-SPH diffusion rate (kg/m^3/s) a deform takes: the rates of the last two evaluations D_n-1 and
// D_n-2 extrapolated to the middle of the step.
template <class Real> IMPACTSPH_HD Real diffusion_at_midstep(Real diffusion_last, Real diffusion_before) {
  return Real(2.5) * diffusion_last - Real(1.5) * diffusion_before;
}

// A particle's density (kg/m^3) and deviatoric stress (Pa) from t_n to t_n+1 under the velocity gradient G
// (1/s) of the half-step velocity: drho/dt = -rho tr G + diffusion (the continuity equation, its delta-SPH
// diffusion rate given, kg/m^3/s) and the Jaumann rate of the strength model, each taken at the midpoint of
// the step (rho_n+1/2, S_n+1/2 from a half step), the density floor, and S through the plastic return at the
// step start's history, the equivalent strain rate of G and the new density and predicted energy e (J/kg).
// Returns the return's increments.
template <class Real>
struct DeformInputs {
  Mat3<Real> G;     // velocity gradient of the half-step velocity, 1/s
  Real diffusion;   // delta-SPH diffusion rate of the density, kg/m^3/s
  Real e;           // predicted specific internal energy at t_n+1, J/kg
};
template <class Real>
IMPACTSPH_HD PlasticResult<Real> deform_point(const MaterialParams<Real>& mat, Real dt, const DeformInputs<Real>& in,
                                              const StepHistory<Real>& history, Real& rho, Sym3<Real>& S) {
  const Real half_dt = Real(0.5) * dt;
  const Mat3<Real>& G = in.G;
  const Real e = in.e;
  const Real rho_half = rho + half_dt * (compression_density_rate(rho, G) + in.diffusion);
  rho = advance_density(mat, rho, compression_density_rate(rho_half, G) + in.diffusion, dt);
  const Sym3<Real> S_half = S + half_dt * deviatoric_stress_rate(mat, S, G);
  S = S + dt * deviatoric_stress_rate(mat, S_half, G);
  return trial_plastic_return(mat, S, history.eps_p, equivalent_strain_rate(G), history.T, rho, e, history.bulking,
                              history.D);
}

// A particle's last kick: v_n+1 = v_h + dt/2 a_n+1 (m/s) and e_n+1 = e_n + dt/2 (de_start + de_end) (J/kg),
// with a_n+1 (m/s^2) and the energy rates of the last evaluation and this one (J/kg/s).
template <class Real>
IMPACTSPH_HD void kick_point(Real dt, const Vec3<Real>& acc, Real de_start, Real de_end, Vec3<Real>& v, Real& e) {
  const Real half_dt = Real(0.5) * dt;
  v = v + half_dt * acc;
  e = e + half_dt * (de_start + de_end);
}

// History variables of the final stage (plastic strain, heating, pressure, damage, bulking: F 4.7-4.9,
// X eq 28; finish_step) and the variable smoothing length (X eqs 9-10: dh/dt = (1/3) h div v within the
// body's bounds) from the velocity gradient of the last evaluation. nonlocal_work (J/m^3): the particle's
// non-local plastic work density after the step where damage_uses_nonlocal_work, else 0.
template <class Real>
IMPACTSPH_HD void finish_point(const MaterialParams<Real>& mat, const BodySmoothing<Real>& smoothing,
                               const Mat3<Real>& grad_v, Real dt, Real rho, Real energy, Sym3<Real>& S,
                               Real& plastic_strain, Real& plastic_work, Real& temperature, Real& damage,
                               Real& pressure, Real& bulking, Real& h, Real d_eps_p, Real d_plastic_work, Real d_T,
                               Real strain_rate, Real nonlocal_work) {
  finish_step(mat, rho, energy, S, plastic_strain, plastic_work, temperature, damage, pressure, bulking, d_eps_p,
              d_plastic_work, d_T, strain_rate, nonlocal_work);
  if (smoothing.variable) h = advance_smoothing_length(h, grad_v.trace(), dt, smoothing.h_lo, smoothing.h_hi);
}

// The stable step of one particle (F eq 5.1, s): the solvers take the minimum.
template <class Real>
IMPACTSPH_HD Real point_time_step(const MaterialParams<Real>& mat, Real cfl, Real rho, Real energy, Real h,
                                  const Vec3<Real>& v) {
  Real c = 0;
  eos_pressure(mat.eos, rho, energy, c);
  return cfl_time_step(cfl, h, signal_speed(mat, c, rho), norm(v));
}

// Whether a particle's state is finite, with a positive density (a step that breaks it diverged).
template <class Real>
IMPACTSPH_HD bool state_is_finite(const Vec3p& x, const Vec3<Real>& v, Real rho, Real e, const Sym3<Real>& S) {
  using std::isfinite;
  return isfinite(x.x) && isfinite(x.y) && isfinite(x.z) && isfinite(v.x) && isfinite(v.y) && isfinite(v.z) &&
         isfinite(rho) && rho > Real(0) && isfinite(e) && isfinite(S.xx) && isfinite(S.yy) && isfinite(S.zz) &&
         isfinite(S.xy) && isfinite(S.yz) && isfinite(S.zx);
}

}  // namespace impactsph
