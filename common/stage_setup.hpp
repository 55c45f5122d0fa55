// The set-up of the stages (common/stages.hpp) from a Scene, one for both solvers (host only).
#pragma once
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/scene.hpp"
#include "common/stages.hpp"

namespace impactsph {

// The numerics and planes in the stages' precision. The model lies on one side of each plane (the scene
// builder guarantees it); the side is that of the particles' mean offset from it.
template <class Real>
StageParams<Real> make_stage_params(const Scene& scene) {
  const NumericsSpec& nu = scene.spec.numerics;
  if (scene.spec.symmetry.size() > static_cast<std::size_t>(kMaxPlanes))
    throw std::runtime_error("the scene has " + std::to_string(scene.spec.symmetry.size()) +
                             " symmetry planes and walls; the solvers handle at most " + std::to_string(kMaxPlanes));
  StageParams<Real> prm{};
  prm.kernel = nu.kernel;
  prm.visc.linear = static_cast<Real>(nu.viscosity.linear);
  prm.visc.quadratic = static_cast<Real>(nu.viscosity.quadratic);
  prm.visc.limited = nu.viscosity.limited;
  prm.visc.close_eta = static_cast<Real>(nu.viscosity.close_eta);
  prm.visc.close_fold = static_cast<Real>(nu.viscosity.close_fold);
  prm.correction.max_condition = static_cast<Real>(nu.correction.max_condition);
  prm.delta = static_cast<Real>(nu.delta);
  prm.cfl = static_cast<Real>(nu.cfl);
  prm.balsara = nu.viscosity_balsara;
  prm.bulk = BulkViscosityParams<Real>{static_cast<Real>(nu.bulk_viscosity.linear),
                                       static_cast<Real>(nu.bulk_viscosity.quadratic)};
  prm.bulk_on = nu.bulk_viscosity.linear > 0 || nu.bulk_viscosity.quadratic > 0;
  prm.art = make_artificial_stress(static_cast<Real>(nu.artificial_stress), nu.artificial_stress_exponent, nu.kernel,
                                   static_cast<Real>(nu.h_factor), nu.artificial_stress_of);
  prm.body_count = static_cast<int>(scene.bodies.size());
  prm.plane_count = static_cast<int>(scene.spec.symmetry.size());
  prm.wall_planes = 0;
  for (int k = 0; k < prm.plane_count; ++k) {
    const SymmetryPlaneSpec& plane = scene.spec.symmetry[static_cast<std::size_t>(k)];
    double side = 0;
    for (const Vec3d& x : scene.particles.pos) side += x[plane.axis] - plane.position;
    prm.planes[k] = Plane{plane.axis, plane.position, side >= 0 ? 1.0 : -1.0, plane.wall};
    if (plane.wall) prm.wall_planes |= 1u << k;
  }
  return prm;
}

// How each pair of bodies interacts, [a * body_count + b]: penalty contact or shared SPH sums.
template <class Real>
std::vector<PairContact<Real>> make_pair_contacts(const Scene& scene) {
  const std::size_t bc = scene.bodies.size();
  std::vector<PairContact<Real>> table(bc * bc, PairContact<Real>{0, Real(0), Real(0), Real(0)});
  for (const ContactSpec& c : scene.spec.contacts) {
    if (c.kind != ContactSpec::Kind::Penalty) continue;
    const PairContact<Real> pc{1, static_cast<Real>(c.penalty_scale),
                               static_cast<Real>(c.contact_distance * scene.spec.numerics.spacing),
                               static_cast<Real>(c.srad)};
    table[static_cast<std::size_t>(c.index_a) * bc + static_cast<std::size_t>(c.index_b)] = pc;
    table[static_cast<std::size_t>(c.index_b) * bc + static_cast<std::size_t>(c.index_a)] = pc;
  }
  return table;
}

// How far the penalty contacts reach: the largest contact distance (m) of those that touch at a distance,
// and the largest SRAD of those that touch at srad h (the search reaches srad times the largest h).
struct ContactReach {
  double distance = 0;  // m
  double srad = 0;
};
inline ContactReach contact_reach(const Scene& scene) {
  ContactReach r;
  for (const ContactSpec& c : scene.spec.contacts) {
    if (c.kind != ContactSpec::Kind::Penalty) continue;
    if (c.srad > 0) r.srad = std::max(r.srad, c.srad);
    else r.distance = std::max(r.distance, c.contact_distance * scene.spec.numerics.spacing);
  }
  return r;
}

// Variable smoothing length per body (X eqs 9-10): on or off, and the bounds of h (m).
template <class Real>
std::vector<BodySmoothing<Real>> make_body_smoothing(const Scene& scene) {
  const double h0 = scene.spec.numerics.h_factor * scene.spec.numerics.spacing;
  std::vector<BodySmoothing<Real>> smoothing;
  for (const BodySpec& b : scene.spec.bodies)
    smoothing.push_back(BodySmoothing<Real>{b.variable_h ? 1 : 0, static_cast<Real>(b.h_min_factor * h0),
                                            static_cast<Real>(b.h_max_factor * h0)});
  return smoothing;
}

}  // namespace impactsph
