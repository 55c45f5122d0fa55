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
template <class Pos, class Real>
IMPACTSPH_HD void reflect_at_plane(Vec3<Pos>& x, Vec3<Real>& v, int axis, Pos position, Pos side) {
  if ((x[axis] - position) * side < Pos(0)) {
    x[axis] = Pos(2) * position - x[axis];
    v[axis] = -v[axis];
  }
}

// Explicit density update rho = rho0 + dt drho/dt with the floor min_density_ratio rho0 (a solid torn apart does not rarefy below it; the explicit
// continuity update can overshoot for a lone pair of separating fragments). kg/m^3, dt in s.
template <class Real>
IMPACTSPH_HD Real advance_density(const MaterialParams<Real>& m, Real rho0, Real drho, Real dt) {
  const Real rho_floor = min_density_ratio<Real>() * m.eos.rho0;
  const Real rho = rho0 + dt * drho;
  return rho_floor < rho ? rho : rho_floor;  // a NaN density stays NaN, for the divergence check
}

// End of a step for one particle (F 4.7-4.9): accumulate the plastic strain and heating of the final
// stage, recompute the pressure (Pa) from the EOS, add the damage increment (D capped at 1), and strip a
// failed particle of its deviator and tension (apply_failure).
template <class Real>
IMPACTSPH_HD void finish_step(const MaterialParams<Real>& mat, Real rho, Real energy, Sym3<Real>& S, Real& plastic_strain,
                              Real& temperature, Real& damage, Real& pressure, Real d_eps_p, Real d_temperature,
                              Real strain_rate) {
  plastic_strain += d_eps_p;
  temperature += d_temperature;
  Real c = 0;
  pressure = eos_pressure(mat.eos, rho, energy, c);
  if (damage < Real(1)) {
    const Real dd = damage_increment(mat, d_eps_p, plastic_strain, pressure, von_mises(S), strain_rate, temperature);
    const Real d = damage + dd;
    damage = d < Real(1) ? d : Real(1);
  }
  apply_failure(S, pressure, damage);
}

}  // namespace impactsph
