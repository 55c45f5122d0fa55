// Time integration of one particle, the symmetry-plane images and the end-of-step history update,
// written once for both solvers (design.md, step 5). The solvers loop over particles around them.
#pragma once
#include "common/damage.hpp"
#include "common/material.hpp"

namespace impactsph {

// Lowest density a particle may reach, as a fraction of its material's reference density.
template <class Real> IMPACTSPH_HD Real min_density_ratio() { return Real(0.5); }

// Per-axis sign of a mirror image: x'_a = s_a x_a + t_a.
template <class Real> IMPACTSPH_HD Vec3<Real> hadamard(Vec3<Real> a, Vec3<Real> b) {
  return {a.x * b.x, a.y * b.y, a.z * b.z};
}
// Mirror image of a symmetric tensor under x'_a = sign_a x_a: T'_ab = sign_a sign_b T_ab.
template <class Real> IMPACTSPH_HD Sym3<Real> mirror(Sym3<Real> t, Vec3<Real> s) {
  return {t.xx, t.yy, t.zz, s.x * s.y * t.xy, s.y * s.z * t.yz, s.z * s.x * t.zx};
}
template <class Real> IMPACTSPH_HD Mat3<Real> mirror(const Mat3<Real>& t, Vec3<Real> s) {
  Mat3<Real> r;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) r.m[a][b] = s[a] * s[b] * t.m[a][b];
  return r;
}

// A symmetry plane x_axis = position is also a frictionless wall: a particle that crossed it (side is
// +1 or -1, the side the model lies on) is reflected back with its normal velocity reversed (its mirror
// image crossed the other way). Positions in m, velocities in m/s.
// Returns whether it was reflected.
template <class Pos, class Real>
IMPACTSPH_HD bool reflect_at_plane(Vec3<Pos>& x, Vec3<Real>& v, int axis, Pos position, Pos side) {
  if (!((x[axis] - position) * side < Pos(0))) return false;
  x[axis] = Pos(2) * position - x[axis];
  v[axis] = -v[axis];
  return true;
}

// One reflection of a symmetry-plane image (the mirror particles of both solvers): the image
// x' = sign x + shift (per axis) of the point x is reflected through the plane x_axis = position when it
// lies within `margin` of that plane (m): sign_a -> -sign_a, shift_a -> 2 position - shift_a. Returns
// whether it was; sign and shift are left as they were when it was not.
template <class Pos>
IMPACTSPH_HD bool mirror_through_plane(Vec3<Pos>& sign, Vec3<Pos>& shift, Vec3<Pos> x, int axis, Pos position,
                                       Pos margin) {
  const Pos d = sign[axis] * x[axis] + shift[axis] - position;
  if ((d < Pos(0) ? -d : d) >= margin) return false;
  sign[axis] = -sign[axis];
  shift[axis] = Pos(2) * position - shift[axis];
  return true;
}

// A wall (case file [[boundaries.wall]]) is a mirror plane that pushes but does not pull. A particle lets
// go of a wall when its normal stress there is tensile, sigma_nn = S_nn - P > 0 (Pa; S the deviatoric stress
// after failure, P the EOS pressure), and it moves away from the wall, side v_n > 0 (m/s; side +1 or -1, the
// side of the plane the model lies on). Then its images through the wall carry no mass, and it takes no
// part in pairs with any image through the wall (gradients, momentum, energy, diffusion): it meets a free
// surface there. Both sides of a pair are needed: a particle in tension next to one that still presses
// would otherwise be pulled back through its neighbour's image (an elastic bar then lost a fifth of its
// rebound speed within 30 us, cases/wall-rebound). Tension alone is not enough: a particle in tension at
// the rim of a Taylor bar's face while still moving into the wall switched its pairs off and on, which
// cost 0.44 % of the energy (0.004 % with the velocity condition).
template <class Real>
IMPACTSPH_HD bool lets_go_of_wall(const Sym3<Real>& S, Real P, const Vec3<Real>& v, int axis, Real side) {
  return (axis == 0 ? S.xx : axis == 1 ? S.yy : S.zz) - P > Real(0) && side * v[axis] > Real(0);
}

// Explicit density update rho = rho0 + dt drho/dt with the floor min_density_ratio rho0 (a solid torn apart does not rarefy below it; the explicit
// continuity update can overshoot for a lone pair of separating fragments). kg/m^3, dt in s.
template <class Real>
IMPACTSPH_HD Real advance_density(const MaterialParams<Real>& m, Real rho0, Real drho, Real dt) {
  const Real rho_floor = min_density_ratio<Real>() * m.eos.rho0;
  const Real rho = rho0 + dt * drho;
  return rho_floor < rho ? rho : rho_floor;  // a NaN density stays NaN, for the divergence check
}

// Trial stress S (Pa) -> plastic return at the history variables of the step start (plastic strain
// eps_p, temperature T in K, damage D) and the strain rate eps_rate (1/s) of the evaluation. A
// pressure-dependent strength (JH-2) takes the pressure of the new state: material_pressure at rho
// (kg/m^3), e (J/kg) and the bulking increment dP_bulk (Pa), bounded by the tensile limit at D.
template <class Real>
IMPACTSPH_HD PlasticResult<Real> trial_plastic_return(const MaterialParams<Real>& mat, Sym3<Real>& S, Real eps_p,
                                                      Real eps_rate, Real T, Real rho, Real e, Real dP_bulk,
                                                      Real D) {
  Real P = 0;
  if (strength_needs_pressure(mat)) {
    Real c = 0;
    Sym3<Real> unused = S;
    P = material_pressure(mat, rho, e, dP_bulk, c);
    apply_failure(mat, unused, P, D);
  }
  return plastic_update(mat, S, eps_p, eps_rate, T, rho, D, P);
}

// End of a step for one particle (F 4.7-4.9, X eq 28): accumulate the plastic strain, the plastic work
// per unit mass (J/kg) and the heating of the final stage, recompute the pressure (Pa) from the EOS and the bulking increment dP_bulk, bound it as
// the material carries it at its damage (apply_failure), add the damage increment (D capped at 1), grow
// what the damage model adds to the pressure (the JH-2 bulking: the strength lost becomes pressure),
// and strip a failed particle of what it no longer carries. strain_rate in 1/s; nonlocal_work (J/m^3) the
// non-local plastic work density after the step where damage_uses_nonlocal_work (common/nonlocal.hpp).
template <class Real>
IMPACTSPH_HD void finish_step(const MaterialParams<Real>& mat, Real rho, Real energy, Sym3<Real>& S, Real& plastic_strain,
                              Real& plastic_work, Real& temperature, Real& damage, Real& pressure, Real& dP_bulk,
                              Real d_eps_p, Real d_plastic_work, Real d_temperature, Real strain_rate,
                              Real nonlocal_work = Real(0)) {
  plastic_strain += d_eps_p;
  plastic_work += d_plastic_work;
  temperature += d_temperature;
  Real c = 0;
  pressure = material_pressure(mat, rho, energy, dP_bulk, c);
  apply_failure(mat, S, pressure, damage);
  if (damage < Real(1)) {
    const Real d_old = damage;
    const Real dd = damage_increment(mat, d_eps_p, plastic_strain, plastic_work, pressure, von_mises(S), strain_rate,
                                     temperature, nonlocal_work);
    const Real d = damage + dd;
    damage = d < Real(1) ? d : Real(1);
    const Real bulking = damage_added_pressure(mat, rho, pressure, d_old, damage, strain_rate, dP_bulk);
    if (bulking != dP_bulk) {
      dP_bulk = bulking;
      pressure = material_pressure(mat, rho, energy, dP_bulk, c);
    }
  }
  apply_failure(mat, S, pressure, damage);
}

}  // namespace impactsph
