#include "reference/solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/artificial_stress.hpp"
#include "common/contact.hpp"
#include "common/correction.hpp"
#include "common/damage.hpp"
#include "common/delta_sph.hpp"
#include "common/integration.hpp"
#include "common/errors.hpp"
#include "common/kernels.hpp"
#include "common/pair_terms.hpp"
#include "common/smoothing_length.hpp"
#include "common/material.hpp"
#include "common/timestep.hpp"
#include "common/verlet.hpp"
#include "common/viscosity.hpp"

namespace impactsph::reference {

namespace {

bool finite(Vec3d v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(Sym3d s) {
  return std::isfinite(s.xx) && std::isfinite(s.yy) && std::isfinite(s.zz) && std::isfinite(s.xy) && std::isfinite(s.yz) &&
         std::isfinite(s.zx);
}

}  // namespace

ReferenceSolver::ReferenceSolver(const Scene& scene)
    : numerics_(scene.spec.numerics), symmetry_(scene.spec.symmetry), materials_(scene.materials),
      contacts_(scene.spec.contacts) {
  for (const BodyInfo& b : scene.bodies) body_names_.push_back(b.name);
  body_count_ = scene.bodies.size();
  // The model lies on one side of each symmetry plane (the scene builder guarantees it).
  for (const SymmetryPlaneSpec& plane : symmetry_) {
    double side = 0;
    for (const Vec3d& x : scene.particles.pos) side += x[plane.axis] - plane.position;
    plane_side_.push_back(side >= 0 ? 1.0 : -1.0);
    if (plane.wall) wall_planes_ |= 1u << (plane_side_.size() - 1);
  }
  contact_of_pair_.assign(body_count_ * body_count_, nullptr);
  for (const ContactSpec& c : contacts_) {
    if (c.kind != ContactSpec::Kind::Penalty) continue;
    const std::size_t a = static_cast<std::size_t>(c.index_a), b = static_cast<std::size_t>(c.index_b);
    contact_of_pair_[a * body_count_ + b] = &c;
    contact_of_pair_[b * body_count_ + a] = &c;
    if (c.srad > 0) contact_srad_ = std::max(contact_srad_, c.srad);
    else contact_reach_ = std::max(contact_reach_, c.contact_distance * numerics_.spacing);
  }
  const double h0 = numerics_.h_factor * numerics_.spacing;
  for (const BodySpec& b : scene.spec.bodies) {
    body_variable_h_.push_back(b.variable_h ? 1 : 0);
    body_h_lo_.push_back(b.h_min_factor * h0);
    body_h_hi_.push_back(b.h_max_factor * h0);
  }
}

double ReferenceSolver::stable_time_step(const ParticleSet& p) {
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  double dt = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(min : dt)
  for (std::int64_t i = 0; i < n; ++i) {
    const MaterialParams<double>& mat = materials_[static_cast<std::size_t>(p.material[i])];
    double c = 0;
    eos_pressure(mat.eos, p.rho[i], p.energy[i], c);
    const double ci = signal_speed(mat, c, p.rho[i]);
    dt = std::min(dt, cfl_time_step(numerics_.cfl, p.h[i], ci, norm(p.vel[i])));
  }
  return dt;
}

// Mirror particles for the symmetry planes and walls. Planes are taken in turn and each mirrors the real
// particles and the ghosts made so far, so the corner of two planes gets its double image.
void ReferenceSolver::find_ghosts(const std::vector<Vec3d>& pos, double margin) {
  ghosts_.clear();
  const std::size_t n = pos.size();
  for (std::size_t k_plane = 0; k_plane < symmetry_.size(); ++k_plane) {
    const SymmetryPlaneSpec& plane = symmetry_[k_plane];
    const std::size_t existing = ghosts_.size();
    for (std::size_t k = 0; k < n + existing; ++k) {
      Ghost g = k < n ? Ghost{static_cast<std::int32_t>(k), Vec3d{1, 1, 1}, Vec3d{0, 0, 0}, 0u} : ghosts_[k - n];
      if (mirror_through_plane(g.sign, g.shift, pos[static_cast<std::size_t>(g.source)], plane.axis, plane.position,
                               margin)) {
        if (plane.wall) g.walls |= 1u << k_plane;
        ghosts_.push_back(g);
      }
    }
  }
}

void ReferenceSolver::evaluate(const State& y, Rates& f, double dt) {
  const std::size_t n = y.pos.size();
  const std::size_t total = n + ghosts_.size();
  const std::int64_t ni = static_cast<std::int64_t>(n);

  // Fill the work arrays: real particles, then ghosts from their sources.
  x_.resize(total); v_.resize(total); rho_.resize(total); pressure_.resize(total); sound_speed_.resize(total);
  m_.resize(total); hh_.resize(total); mat_.resize(total); s_over_rho2_.resize(total); l_inverse_.resize(total);
  grad_rho_.resize(total); grad_v_.resize(total); volume_.resize(total); bb_.resize(total); damage_all_.resize(total);
  pair_damage_.resize(total); let_go_.resize(n); image_walls_.resize(total);
  std::vector<Sym3d>& stress = stress_;
  stress.resize(total);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < ni; ++i) {
    x_[i] = y.pos[i]; v_[i] = y.vel[i]; rho_[i] = y.rho[i]; m_[i] = mass_[i]; hh_[i] = h_[i];
    mat_[i] = material_[i]; stress[i] = y.dev_stress[i]; bb_[i] = body_[i]; damage_all_[i] = damage_[i];
    const MaterialParams<double>& mat = materials_[static_cast<std::size_t>(mat_[i])];
    pressure_[i] = material_pressure(mat, rho_[i], y.energy[i], bulking_[i], sound_speed_[i]);
    apply_failure(mat, stress[i], pressure_[i], damage_all_[i]);  // failed: no deviator, no tension (JH-2: limit)
    pair_damage_[i] = pair_damage(mat, damage_all_[i]);
    unsigned let_go = 0;
    for (std::size_t k = 0; k < symmetry_.size(); ++k)
      if (((wall_planes_ >> k) & 1u) &&
          lets_go_of_wall(stress[i], pressure_[i], v_[i], symmetry_[k].axis, plane_side_[k]))
        let_go |= 1u << k;  // it lets go of wall k: no pairs with images behind it, and no images of its own
    let_go_[i] = let_go;
    image_walls_[i] = 0;
  }
  for (std::size_t k = 0; k < ghosts_.size(); ++k) {
    const Ghost& g = ghosts_[k];
    const std::size_t s = static_cast<std::size_t>(g.source), i = n + k;
    x_[i] = hadamard(g.sign, y.pos[s]) + g.shift;
    v_[i] = hadamard(g.sign, y.vel[s]);
    rho_[i] = rho_[s]; hh_[i] = hh_[s]; mat_[i] = mat_[s]; bb_[i] = bb_[s];
    m_[i] = (g.walls & let_go_[s]) ? 0.0 : m_[s];  // its source let go of a wall it is mirrored through
    image_walls_[i] = g.walls;
    damage_all_[i] = damage_all_[s];
    pair_damage_[i] = pair_damage_[s];
    pressure_[i] = pressure_[s]; sound_speed_[i] = sound_speed_[s];
    stress[i] = mirror(stress[s], g.sign);
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(total); ++i) {
    volume_[i] = m_[i] / rho_[i];
    const double inv_rho2 = 1.0 / (rho_[i] * rho_[i]);
    const Sym3d& s = stress[i];
    s_over_rho2_[i] = inv_rho2 * Sym3d{s.xx - pressure_[i], s.yy - pressure_[i], s.zz - pressure_[i], s.xy, s.yz, s.zx};
  }
  // Artificial stress of each particle and ghost from its own stress, before any viscosity joins it.
  const ArtificialStressParams<double> art = make_artificial_stress(
      numerics_.artificial_stress, numerics_.artificial_stress_exponent, numerics_.kernel, numerics_.h_factor,
      numerics_.artificial_stress_deviatoric);
  artificial_stress_.resize(art.on() ? total : 0);
  if (art.on()) {
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(total); ++i)
      artificial_stress_[i] = artificial_stress(art, s_over_rho2_[i]);
  }

  const KernelKind kernel = numerics_.kernel;
  const std::int64_t* off = neighbours_.offsets.data();
  const std::int32_t* nb = neighbours_.indices.data();

  // Pass 1: correction matrix L_i (F 2.13), velocity gradient, renormalised density gradient (F 2.19), the
  // gradients scaled by the damage factor 1 - D_ij (F 4.10) as the pass 2 terms are.
  std::size_t fallbacks = 0;
  std::int64_t pairs = 0;  // neighbours within the kernel support, for the statistics
#pragma omp parallel for schedule(static) reduction(+ : fallbacks, pairs)
  for (std::int64_t i = 0; i < ni; ++i) {
    GradientSums<double> sums = GradientSums<double>::zero();
    const Vec3d xi = x_[i], vi = v_[i];
    const double rhoi = rho_[i], hi = hh_[i], di = pair_damage_[i];
    const bool face_i = crack_face(static_cast<std::size_t>(i));
    const std::int32_t bi = bb_[i];
    for (std::int64_t k = off[i]; k < off[i + 1]; ++k) {
      const std::int32_t j = nb[k];
      const Vec3d xij = xi - x_[j];
      const double hij = 0.5 * (hi + hh_[j]);
      const double r = norm(xij);
      if (r >= kernel_support(hij)) continue;
      ++pairs;
      if (penalty_between(bi, bb_[j])) continue;  // bodies in penalty contact do not share sums
      if (image_walls_[j] & let_go_[i]) continue;  // i let go of the wall this image lies behind
      const Vec3d gw = kernel_grad_factor(kernel, r, hij) * xij;
      add_gradient_pair(sums, volume_[j], gw, xij, v_[j] - vi, rho_[j] - rhoi, di, pair_damage_[j],
                        face_i || crack_face(static_cast<std::size_t>(j)));
    }
    const CorrectedGradients<double> cg = corrected_gradients(sums, numerics_.correction);
    if (cg.fell_back) ++fallbacks;
    l_inverse_[i] = cg.l_inverse;
    grad_v_[i] = cg.grad_v;
    grad_rho_[i] = cg.grad_rho;
  }
  stats_.correction_fallbacks = fallbacks;
  stats_.mean_neighbours = ni ? static_cast<double>(pairs) / static_cast<double>(ni) : 0.0;
  // Viscosity factor per particle: 1, or the Balsara shear limiter of its velocity gradient.
  av_factor_.resize(total);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < ni; ++i)
    av_factor_[i] = numerics_.viscosity_balsara ? balsara_factor(grad_v_[i], sound_speed_[i], hh_[i]) : 1.0;
  // Bulk viscosity (viscosity.hpp) from each particle's own div v, added to its pressure in (S - P I)/rho^2;
  // a ghost carries its source's (isotropic, so its mirror is itself).
  const BulkViscosityParams<double> bulk = numerics_.bulk_viscosity;
  const bool bulk_on = bulk.linear > 0 || bulk.quadratic > 0;
  if (bulk_on) {
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < ni; ++i)
      add_bulk_viscosity(bulk, grad_v_[i].trace(), rho_[i], sound_speed_[i], hh_[i], s_over_rho2_[i]);
  }
  for (std::size_t k = 0; k < ghosts_.size(); ++k) {
    const Ghost& g = ghosts_[k];
    const std::size_t s = static_cast<std::size_t>(g.source);
    l_inverse_[n + k] = mirror(l_inverse_[s], g.sign);
    grad_rho_[n + k] = hadamard(g.sign, grad_rho_[s]);
    av_factor_[n + k] = av_factor_[s];
    if (bulk_on) s_over_rho2_[n + k] = mirror(s_over_rho2_[s], g.sign);
    if (numerics_.viscosity.limited) grad_v_[n + k] = mirror(grad_v_[s], g.sign);
  }

  // Constitutive rate: Jaumann deviatoric stress rate of the body's strength model (F 3.5-3.7).
  f.vel.resize(n); f.acc.resize(n); f.drho.resize(n); f.denergy.resize(n); f.dstress.resize(n);
  f.strain_rate.resize(n); f.contact_power.resize(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < ni; ++i) {
    f.dstress[i] = deviatoric_stress_rate(materials_[static_cast<std::size_t>(mat_[i])], stress[i], grad_v_[i]);
    f.strain_rate[i] = equivalent_strain_rate(grad_v_[i]);
  }

  // Pass 2: continuity with delta-SPH (Marrone form), momentum (F 2.11) and energy (consistent F 2.12),
  // the pair terms (diffusion included) scaled by the damage factor 1 - D_ij (F 4.10); penalty contact
  // (F 4.1-4.6) between bodies that do not share sums.
  const ViscosityParams<double> visc = numerics_.viscosity;
  const double delta = numerics_.delta;
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < ni; ++i) {
    const Vec3d xi = x_[i], vi = v_[i], gri = grad_rho_[i];
    const double rhoi = rho_[i], hi = hh_[i];
    const std::int32_t mi = mat_[i], bi = bb_[i];
    const PairSide<double> side_i = pair_side(i);
    const unsigned let_go_i = let_go_[i];
    Vec3d acc{0, 0, 0}, contact{0, 0, 0};
    double de = 0, diffusion = 0, contact_power = 0;
    for (std::int64_t k = off[i]; k < off[i + 1]; ++k) {
      const std::int32_t j = nb[k];
      const Vec3d xij = xi - x_[j];
      if (const ContactSpec* c = penalty_between(bi, bb_[j])) {
        const MaterialParams<double>& mat_i = materials_[static_cast<std::size_t>(mi)];
        const MaterialParams<double>& mat_j = materials_[static_cast<std::size_t>(mat_[j])];
        const Vec3d vij = vi - v_[j];
        const double touch = contact_touch_distance(c->srad, c->contact_distance * numerics_.spacing, hi, hh_[j]);
        const Vec3d force = penalty_contact_force(PenaltyContactParams<double>{c->penalty_scale}, xij, vij,
                                                  touch, m_[i], m_[j], hi, hh_[j],
                                                  mat_i.strength.shear_modulus, mat_j.strength.shear_modulus, rhoi,
                                                  rho_[j], dt);
        contact += force;
        contact_power += 0.5 * penalty_contact_energy_rate(force, vij);
        continue;
      }
      const double hij = 0.5 * (hi + hh_[j]);
      const double r = norm(xij);
      if (r >= kernel_support(hij) || (image_walls_[j] & let_go_i)) continue;
      const Vec3d gw = kernel_grad_factor(kernel, r, hij) * xij;
      const double stress_factor = artificial_stress_pair_factor(art, kernel, r, hij);
      add_momentum_energy_pair(side_i, pair_side(j), visc, gw, xij, vi - v_[j], hij, m_[j], stress_factor, acc, de);
      if (mat_[j] == mi)
        diffusion += damaged_delta_sph_term(side_i.damage, pair_damage_[j], volume_[j], rhoi, rho_[j], xij, gri,
                                            grad_rho_[j], gw);
    }
    const double c0 = std::sqrt(eos_reference_sound_speed2(materials_[static_cast<std::size_t>(mi)].eos));
    f.drho[i] = continuity_rate(rhoi, grad_v_[i], delta, hi, c0, diffusion);
    f.denergy[i] = de;
    f.contact_power[i] = contact_power;
    if (fixed_[i]) {
      f.vel[i] = Vec3d{0, 0, 0};
      f.acc[i] = Vec3d{0, 0, 0};
    } else {
      f.vel[i] = vi;
      f.acc[i] = acc + (1.0 / m_[i]) * contact;
    }
  }
}

bool ReferenceSolver::crack_face(std::size_t i) const {
  return compressive_crack_face(materials_.data(), mat_[i], pair_damage_[i]);
}

PairSide<double> ReferenceSolver::pair_side(std::size_t i) const {
  return {s_over_rho2_[i].full(), l_inverse_[i], pair_damage_[i], av_factor_[i], sound_speed_[i], rho_[i], crack_face(i),
          artificial_stress_.empty() ? Mat3d::zero() : artificial_stress_[i].full(),
          numerics_.viscosity.limited ? grad_v_[i] : Mat3d::zero()};
}

void ReferenceSolver::advance(const State& y0, const Rates& f, double dt, State& out, History* history) const {
  const std::int64_t n = static_cast<std::int64_t>(y0.pos.size());
  out.pos.resize(n); out.vel.resize(n); out.rho.resize(n); out.energy.resize(n); out.dev_stress.resize(n);
  if (history) {
    history->d_eps_p.resize(static_cast<std::size_t>(n));
    history->d_plastic_work.resize(static_cast<std::size_t>(n));
    history->d_temperature.resize(static_cast<std::size_t>(n));
    history->strain_rate.resize(static_cast<std::size_t>(n));
  }
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    out.pos[i] = y0.pos[i] + dt * f.vel[i];
    out.vel[i] = y0.vel[i] + dt * f.acc[i];
    for (std::size_t k = 0; k < symmetry_.size(); ++k)
      reflect_at_plane(out.pos[i], out.vel[i], symmetry_[k].axis, symmetry_[k].position, plane_side_[k]);
    out.rho[i] = advance_density(materials_[static_cast<std::size_t>(material_[i])], y0.rho[i], f.drho[i], dt);
    out.energy[i] = y0.energy[i] + dt * f.denergy[i];
    // Trial stress, then the plastic return at the history variables of the step start.
    Sym3d s = y0.dev_stress[i] + dt * f.dstress[i];
    const MaterialParams<double>& mat = materials_[static_cast<std::size_t>(material_[i])];
    const PlasticResult<double> pr = trial_plastic_return(mat, s, plastic_strain_[i], f.strain_rate[i], temperature_[i],
                                                          out.rho[i], out.energy[i], bulking_[i], damage_[i]);
    out.dev_stress[i] = s;
    if (history) {
      history->d_eps_p[i] = pr.d_eps_p;
      history->d_plastic_work[i] = pr.plastic_work;
      history->d_temperature[i] = pr.d_T;
      history->strain_rate[i] = f.strain_rate[i];
    }
  }
}

void ReferenceSolver::check_state(const State& y, double dt) const {
  const std::size_t n = y.pos.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (finite(y.pos[i]) && finite(y.vel[i]) && std::isfinite(y.rho[i]) && y.rho[i] > 0 && std::isfinite(y.energy[i]) &&
        finite(y.dev_stress[i]))
      continue;
    std::ostringstream msg;
    msg.precision(6);
    msg << "the solution diverged in the step of dt = " << dt << " s at particle " << i << " of body '"
        << body_names_[static_cast<std::size_t>(body_[i])] << "': position (" << y.pos[i].x << ", " << y.pos[i].y << ", "
        << y.pos[i].z << ") m, velocity (" << y.vel[i].x << ", " << y.vel[i].y << ", " << y.vel[i].z
        << ") m/s, density " << y.rho[i] << " kg/m^3, specific energy " << y.energy[i] << " J/kg, von Mises "
        << von_mises(y.dev_stress[i]) << " Pa. Try a smaller numerics.cfl or larger viscosity coefficients.";
    throw DivergenceError(msg.str());
  }
}

void ReferenceSolver::load_constants(const ParticleSet& p) {
  mass_ = p.mass; h_ = p.h; material_ = p.material; fixed_ = p.fixed; body_ = p.body;
  damage_ = p.damage; plastic_strain_ = p.plastic_strain; temperature_ = p.temperature;
  bulking_ = p.bulking_pressure;
  h_max_ = p.size() ? *std::max_element(h_.begin(), h_.end()) : 0.0;
}

double ReferenceSolver::search_reach() const {
  return impactsph::search_reach(kernel_support(h_max_), contact_reach_, contact_srad_, h_max_);
}

// Each row of the list is sorted by neighbour index, so that the pair sums are taken in an order that
// does not depend on when the list was built (the cell order does): a run continues with the same bits
// whether its list is reused or rebuilt, and a restart (which starts with a build) matches the run that
// wrote the checkpoint.
void ReferenceSolver::build_neighbours(const std::vector<Vec3d>& pos, double skin) {
  const double reach = search_reach();
  find_ghosts(pos, reach + skin);
  std::vector<Vec3d> points(pos);
  points.reserve(pos.size() + ghosts_.size());
  for (const Ghost& g : ghosts_) points.push_back(hadamard(g.sign, pos[static_cast<std::size_t>(g.source)]) + g.shift);
  build_neighbour_list(points, pos.size(), reach + skin, neighbours_);
  const std::int64_t rows = static_cast<std::int64_t>(pos.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < rows; ++i)
    std::sort(neighbours_.indices.begin() + neighbours_.offsets[i], neighbours_.indices.begin() + neighbours_.offsets[i + 1]);
  stats_.ghosts = ghosts_.size();
}

// The list is kept while verlet_list_holds (common/verlet.hpp); the skin is verlet_skin of the reach.
void ReferenceSolver::update_neighbours(const ParticleSet& p, double dt) {
  const std::size_t n = p.size();
  const std::int64_t ni = static_cast<std::int64_t>(n);
  double vmax = 0, moved = 0;
  const bool same = list_valid_ && pos_at_build_.size() == n;
#pragma omp parallel for schedule(static) reduction(max : vmax, moved)
  for (std::int64_t i = 0; i < ni; ++i) {
    vmax = std::max(vmax, norm(p.vel[i]));
    if (same) moved = std::max(moved, norm(p.pos[i] - pos_at_build_[i]));
  }
  const double reach = search_reach();
  const double growth = std::max(0.0, reach - reach_at_build_);
  if (same && verlet_list_holds(moved, dt, vmax, growth, skin_)) return;
  reach_at_build_ = reach;
  skin_ = verlet_skin(reach);
  build_neighbours(p.pos, skin_);
  pos_at_build_ = p.pos;
  list_valid_ = true;
}

std::size_t ReferenceSolver::velocity_gradients(const ParticleSet& p, std::vector<Mat3d>& grad_v) {
  load_constants(p);
  State y{p.pos, p.vel, p.rho, p.energy, p.dev_stress};
  build_neighbours(y.pos, 0.0);
  list_valid_ = false;
  Rates f;
  evaluate(y, f, 0.0);
  grad_v.assign(grad_v_.begin(), grad_v_.begin() + static_cast<std::ptrdiff_t>(p.pos.size()));
  return stats_.correction_fallbacks;
}

void ReferenceSolver::step(ParticleSet& p, double dt) {
  const std::size_t n = p.size();
  load_constants(p);
  State& y0 = y0_;
  y0.pos = p.pos; y0.vel = p.vel; y0.rho = p.rho; y0.energy = p.energy; y0.dev_stress = p.dev_stress;
  update_neighbours(p, dt);

  Rates& f = rates_;
  State& y_half = y_half_;
  State& y1 = y1_;
  History& history = history_;
  evaluate(y0, f, dt);
  advance(y0, f, 0.5 * dt, y_half, nullptr);
  evaluate(y_half, f, dt);
  advance(y0, f, dt, y1, &history);
  check_state(y1, dt);
  double contact_power = 0;
  for (std::size_t i = 0; i < n; ++i) contact_power += f.contact_power[i];
  stats_.contact_work = dt * contact_power;

  std::swap(p.pos, y1.pos);
  std::swap(p.vel, y1.vel);
  std::swap(p.rho, y1.rho);
  std::swap(p.energy, y1.energy);
  std::swap(p.dev_stress, y1.dev_stress);
  // History variables of the final stage: plastic strain, adiabatic heating, damage, bulking (F 4.7-4.9,
  // X eq 28; integration.hpp), and the smoothing length.
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i) {
    const MaterialParams<double>& mat = materials_[static_cast<std::size_t>(p.material[i])];
    finish_step(mat, p.rho[i], p.energy[i], p.dev_stress[i], p.plastic_strain[i], p.plastic_work[i], p.temperature[i],
                p.damage[i], p.pressure[i], p.bulking_pressure[i], history.d_eps_p[i], history.d_plastic_work[i],
                history.d_temperature[i], history.strain_rate[i]);
    // Variable smoothing length (X eqs 9-10): dh/dt = (1/3) h div v, within the body's bounds.
    const std::size_t b = static_cast<std::size_t>(p.body[i]);
    if (body_variable_h_[b])
      p.h[i] = advance_smoothing_length(p.h[i], grad_v_[static_cast<std::size_t>(i)].trace(), dt, body_h_lo_[b],
                                        body_h_hi_[b]);
  }
}

}  // namespace impactsph::reference
