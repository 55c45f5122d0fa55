#include "reference/solver.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/parallel.hpp"
#include "common/verlet.hpp"

namespace impactsph::reference {

ReferenceSolver::ReferenceSolver(const Scene& scene)
    : numerics_(scene.spec.numerics), leapfrog_(scene.spec.numerics.integrator == Integrator::Leapfrog),
      params_(make_stage_params<double>(scene)),
      contacts_(make_pair_contacts<double>(scene)), smoothing_(make_body_smoothing<double>(scene)),
      contact_reach_(contact_reach(scene)), materials_(scene.materials),
      nonlocal_grid_(build_nonlocal_grid(scene.particles, scene.materials)) {
  for (const BodyInfo& b : scene.bodies) body_names_.push_back(b.name);
  for (const BodySpec& b : scene.spec.bodies) variable_h_ = variable_h_ || b.variable_h;
}

double ReferenceSolver::stable_time_step(const ParticleSet& p) {
  return parallel_min(static_cast<std::int64_t>(p.size()), [&](std::int64_t i) {
    return point_time_step(materials_[static_cast<std::size_t>(p.material[i])], params_.cfl, p.rho[i], p.energy[i],
                           p.h[i], p.vel[i]);
  });
}

// Mirror particles for the symmetry planes and walls. Planes are taken in turn and each mirrors the real
// particles and the ghosts made so far, so the corner of two planes gets its double image.
void ReferenceSolver::find_ghosts(const std::vector<Vec3d>& pos, double margin) {
  ghosts_.clear();
  const std::size_t n = pos.size();
  for (int k_plane = 0; k_plane < params_.plane_count; ++k_plane) {
    const Plane& plane = params_.planes[k_plane];
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

StagePoints<double> ReferenceSolver::points() {
  return {x_.data(), v_.data(), rho_.data(), pressure_.data(), sound_speed_.data(), m_.data(), hh_.data(),
          volume_.data(), pair_damage_.data(), av_factor_.data(), s_over_rho2_.data(), stress_.data(),
          artificial_stress_.empty() ? nullptr : artificial_stress_.data(), mat_.data(), bb_.data(), let_go_.data(),
          image_walls_.data(), l_inverse_.data(), grad_v_.data(), grad_rho_.data(), contacts_.data(),
          params_.body_count};
}

// r and the kernel gradient factor of a row's candidates c.j[0, count) at x_i, h_i (pair_geometry,
// Kernel::grad_factor: the same operations in the same order), into c.r and c.factor: a loop of its own,
// without branches, that the compiler takes in SIMD lanes.
static_assert(sizeof(Vec3d) == 3 * sizeof(double), "candidate_kernel reads the positions as x, y, z in turn");
constexpr double kCandidateMargin = 1 + 1e-9;  // on r^2 <= support^2, far above a rounding of the square root

template <class Kernel>
void ReferenceSolver::candidate_kernel(Kernel kernel, Vec3d x_i, double h_i, std::int64_t count,
                                       RowCandidates& c) const {
  const double xi = x_i.x, yi = x_i.y, zi = x_i.z;
  const double* __restrict x = &x_[0].x;
  const double* __restrict h = hh_.data();
  const std::int32_t* __restrict cand = c.j.data();
  double* __restrict r_out = c.r.data();
  double* __restrict factor_out = c.factor.data();
#pragma omp simd
  for (std::int64_t k = 0; k < count; ++k) {
    const std::int64_t j = cand[k];
    const double r = norm(Vec3d{xi - x[3 * j], yi - x[3 * j + 1], zi - x[3 * j + 2]});  // pair_geometry's x_ij
    const double hij = 0.5 * (h_i + h[j]);
    r_out[k] = r;
    factor_out[k] = kernel.grad_factor(r, hij);
  }
}

void ReferenceSolver::evaluate(const State& y, Rates& f, double dt) {
  gather(y);
  gradient_pass();
  rate_pass(f, dt);
}

// The work arrays of an evaluation at state y: real particles (gather_point), then ghosts from their sources;
// each point's volume, (S - P I)/rho^2 and artificial stress.
void ReferenceSolver::gather(const State& y) {
  const std::size_t n = y.pos.size();
  const std::size_t total = n + ghosts_.size();
  const std::int64_t ni = static_cast<std::int64_t>(n);
  const MaterialParams<double>* mats = materials_.data();
  x_.resize(total); v_.resize(total); rho_.resize(total); pressure_.resize(total); sound_speed_.resize(total);
  m_.resize(total); hh_.resize(total); mat_.resize(total); s_over_rho2_.resize(total); l_inverse_.resize(total);
  grad_rho_.resize(total); grad_v_.resize(total); volume_.resize(total); bb_.resize(total); damage_all_.resize(total);
  pair_damage_.resize(total); let_go_.resize(total); image_walls_.resize(total); stress_.resize(total);
  av_factor_.resize(total);
  parallel_for(ni, [&](std::int64_t i) IMPACTSPH_FLATTEN {
    x_[i] = y.pos[i]; v_[i] = y.vel[i]; rho_[i] = y.rho[i]; m_[i] = mass_[i]; hh_[i] = h_[i];
    mat_[i] = material_[i]; bb_[i] = body_[i]; damage_all_[i] = damage_[i];
    const GatheredPoint<double> g =
        gather_point(mats[mat_[i]], rho_[i], y.energy[i], bulking_[i], damage_all_[i], y.dev_stress[i]);
    pressure_[i] = g.P; sound_speed_[i] = g.c; stress_[i] = g.S; pair_damage_[i] = g.pair_damage;
    // the walls it lets go of: no pairs with images behind them, and no images of its own
    let_go_[i] = walls_let_go(params_.planes, params_.plane_count, stress_[i], pressure_[i], v_[i]);
    image_walls_[i] = 0;
  });
  for (std::size_t k = 0; k < ghosts_.size(); ++k) {
    const Ghost& g = ghosts_[k];
    const std::size_t s = static_cast<std::size_t>(g.source), i = n + k;
    const MirroredPoint<double> image =
        mirror_point(g.sign, g.shift, g.walls, let_go_[s], y.pos[s], y.vel[s], stress_[s], m_[s]);
    x_[i] = image.x; v_[i] = image.v; stress_[i] = image.S; m_[i] = image.m;
    rho_[i] = rho_[s]; hh_[i] = hh_[s]; mat_[i] = mat_[s]; bb_[i] = bb_[s];
    let_go_[i] = 0;
    image_walls_[i] = g.walls;
    damage_all_[i] = damage_all_[s];
    pair_damage_[i] = pair_damage_[s];
    pressure_[i] = pressure_[s]; sound_speed_[i] = sound_speed_[s];
  }
  // Artificial stress of each particle and ghost from its own stress, before any viscosity joins it.
  artificial_stress_.resize(params_.art.on() ? total : 0);
  const StagePoints<double> w = points();
  parallel_for(static_cast<std::int64_t>(total), [&](std::int64_t i) {
    volume_[i] = m_[i] / rho_[i];
    set_stress_terms(params_, w, i, rho_[i]);
  });
}

// Pass 1 (stages.hpp): each real's gradients from its neighbours, then the ghosts' mirrored from their sources.
// It sorts the row's list entries as it goes (pair_j_): the SPH pairs to the front, the penalty contact
// pairs to the back (in reverse), those outside the support and behind let-go walls nowhere.
void ReferenceSolver::gradient_pass() {
  const std::size_t n = x_.size() - ghosts_.size();
  const std::int64_t ni = static_cast<std::int64_t>(n);
  const MaterialParams<double>* mats = materials_.data();
  const StagePoints<double> w = points();
  const RuntimeKernel kernel{params_.kernel};
  const std::int64_t* off = neighbours_.offsets.data();
  const std::int32_t* nb = neighbours_.indices.data();

  row_neighbours_.resize(n);
  fell_back_.resize(n);
  pair_j_.resize(neighbours_.indices.size());
  pair_grad_factor_.resize(neighbours_.indices.size());
  sph_end_.resize(n);
  contact_begin_.resize(n);
  parallel_for(ni, [&](std::int64_t i) IMPACTSPH_FLATTEN {
    GradientSums<double> sums = GradientSums<double>::zero();
    const GradientRow<double> row = gradient_row(w, mats, i);
    std::int32_t neighbours = 0;  // within the kernel support, for the statistics
    std::int64_t sph = off[i], contact = off[i + 1];
    static thread_local RowCandidates c;
    const std::size_t row_length = static_cast<std::size_t>(off[i + 1] - off[i]);
    if (c.j.size() < row_length) { c.j.resize(row_length); c.r.resize(row_length); c.factor.resize(row_length); }
    std::int64_t candidates = 0;
    // The list's skin first, with no branch: the candidates are the entries that may lie within the support
    // (r^2 against the support's square, with a margin above the rounding, so that no pair that pair_geometry
    // takes in is dropped) and every penalty contact pair.
    for (std::int64_t k = off[i]; k < off[i + 1]; ++k) {
      const std::int32_t j = nb[k];
      const double support = kernel_support(0.5 * (row.h + w.h[j]));
      c.j[static_cast<std::size_t>(candidates)] = j;
      candidates += (norm2(row.x - w.x[j]) <= support * support * kCandidateMargin) | w.pair(row.body, bb_[j]).penalty;
    }
    if (kernel.kind() == KernelKind::WendlandC2)
      candidate_kernel(FixedKernel<KernelKind::WendlandC2>{}, row.x, row.h, candidates, c);
    else
      candidate_kernel(FixedKernel<KernelKind::CubicSpline>{}, row.x, row.h, candidates, c);
    const double* cand_r = c.r.data();
    const double* cand_factor = c.factor.data();
    for (std::int64_t k = 0; k < candidates; ++k) {
      const std::int32_t j = c.j[static_cast<std::size_t>(k)];
      const bool penalty = w.pair(row.body, bb_[j]).penalty;
      if (penalty) pair_j_[--contact] = j;
      const PairGeometry<double> g = pair_geometry_at(w, row.x, row.h, j, cand_r[k]);
      if (!g.in_support()) continue;
      ++neighbours;
      if (penalty || !shares_sums(w, row.body, row.let_go, j)) continue;
      const double factor = cand_factor[k];
      pair_j_[sph] = j; pair_grad_factor_[sph] = factor; ++sph;
      add_gradient_sph_pair(w, mats, row, j, g.xij, factor * g.xij, sums);
    }
    sph_end_[i] = sph;
    contact_begin_[i] = contact;
    const CorrectedGradients<double> cg = finish_gradient_row(params_, w, i, sums);
    row_neighbours_[i] = neighbours;
    fell_back_[i] = cg.fell_back ? 1 : 0;
    grad_v_[i] = cg.grad_v;
  });
  stats_.correction_fallbacks = static_cast<std::size_t>(parallel_count(ni, [&](std::int64_t i) { return fell_back_[i]; }));
  const std::int64_t pairs = parallel_count(ni, [&](std::int64_t i) { return row_neighbours_[i]; });
  stats_.mean_neighbours = ni ? static_cast<double>(pairs) / static_cast<double>(ni) : 0.0;
  for (std::size_t k = 0; k < ghosts_.size(); ++k)
    mirror_gradient_row(params_, w, static_cast<std::int64_t>(n + k), ghosts_[k].source, ghosts_[k].sign);
}

// Pass 2 (stages.hpp): the SPH pairs of each real that pass 1 kept, then its penalty contact pairs in list
// order (the two add into sums of their own), then its rates.
void ReferenceSolver::rate_pass(Rates& f, double dt) {
  const std::size_t n = x_.size() - ghosts_.size();
  const std::int64_t ni = static_cast<std::int64_t>(n);
  const MaterialParams<double>* mats = materials_.data();
  const StagePoints<double> w = points();
  const RuntimeKernel kernel{params_.kernel};
  const std::int64_t* off = neighbours_.offsets.data();
  f.vel.resize(n); f.acc.resize(n); f.drho.resize(n); f.drho_diffusion.resize(n); f.denergy.resize(n);
  f.dstress.resize(n); f.strain_rate.resize(n); f.contact_power.resize(n);
  const KernelKind kind = kernel.kind();
  parallel_for(ni, [&](std::int64_t i) IMPACTSPH_FLATTEN {
    const RateRow<double> row = rate_row(params_, w, mats, i);
    Vec3d acc{0, 0, 0}, contact{0, 0, 0};
    double de = 0, diffusion = 0, contact_power = 0;
    for (std::int64_t k = off[i]; k < sph_end_[i]; ++k) {
      const std::int32_t j = pair_j_[k];
      const PairGeometry<double> g = pair_geometry(w, row.x, row.h, j);
      add_rate_sph_pair(kind, params_, w, mats, row, j, g, pair_grad_factor_[k] * g.xij, acc, de, diffusion);
    }
    for (std::int64_t k = off[i + 1]; k-- > contact_begin_[i];)
      add_contact_neighbour(w, mats, row, pair_j_[k], dt, contact, contact_power);
    const PointRates<double> r = point_rates(params_, w, mats[mat_[i]], i, grad_v_[i], acc, de, diffusion, contact,
                                             contact_power, fixed_[i] != 0);
    f.vel[i] = r.vel; f.acc[i] = r.acc; f.drho[i] = r.drho; f.drho_diffusion[i] = r.drho_diffusion;
    f.denergy[i] = r.de; f.dstress[i] = r.dS;
    f.strain_rate[i] = r.strain_rate; f.contact_power[i] = r.contact_power;
  });
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
  parallel_for(n, [&](std::int64_t i) IMPACTSPH_FLATTEN {
    out.pos[i] = y0.pos[i]; out.vel[i] = y0.vel[i]; out.rho[i] = y0.rho[i]; out.energy[i] = y0.energy[i];
    out.dev_stress[i] = y0.dev_stress[i];
    const PlasticResult<double> pr =
        advance_point(params_, materials_[static_cast<std::size_t>(material_[i])], dt, dt, out.pos[i], out.vel[i],
                      out.rho[i], out.energy[i], out.dev_stress[i], f.vel[i], f.acc[i], f.drho[i], f.denergy[i],
                      f.dstress[i], f.strain_rate[i], plastic_strain_[i], temperature_[i], bulking_[i], damage_[i]);
    if (history) {
      history->d_eps_p[i] = pr.d_eps_p;
      history->d_plastic_work[i] = pr.plastic_work;
      history->d_temperature[i] = pr.d_T;
      history->strain_rate[i] = f.strain_rate[i];
    }
  });
}

void ReferenceSolver::check_state(const State& y, double dt) const {
  const std::size_t n = y.pos.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (state_is_finite(y.pos[i], y.vel[i], y.rho[i], y.energy[i], y.dev_stress[i])) continue;
    const Vec3d x = y.pos[i], v = y.vel[i];
    throw particle_diverged(dt, static_cast<long long>(i), body_names_[static_cast<std::size_t>(body_[i])],
                            {x.x, x.y, x.z}, {v.x, v.y, v.z}, y.rho[i], y.energy[i], von_mises(y.dev_stress[i]));
  }
}

void ReferenceSolver::load_constants(const ParticleSet& p) {
  mass_ = p.mass; h_ = p.h; material_ = p.material; fixed_ = p.fixed; body_ = p.body;
  damage_ = p.damage; plastic_strain_ = p.plastic_strain; temperature_ = p.temperature;
  bulking_ = p.bulking_pressure;
  h_max_ = p.size() ? *std::max_element(h_.begin(), h_.end()) : 0.0;
  h_min_ = p.size() ? *std::min_element(h_.begin(), h_.end()) : 0.0;
}

double ReferenceSolver::search_reach() const {
  return impactsph::search_reach(kernel_support(h_max_), contact_reach_.distance, contact_reach_.srad, h_max_);
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
  const std::vector<double>* point_radius = nullptr;
  if (reach_per_pair(h_min_, h_max_, variable_h_)) {
    point_radius_.resize(points.size());
    auto radius_of = [&](double h) {
      return point_search_radius(h, contact_reach_.distance, contact_reach_.srad, skin);
    };
    for (std::size_t i = 0; i < pos.size(); ++i) point_radius_[i] = radius_of(h_[i]);
    for (std::size_t g = 0; g < ghosts_.size(); ++g)
      point_radius_[pos.size() + g] = radius_of(h_[static_cast<std::size_t>(ghosts_[g].source)]);
    point_radius = &point_radius_;
  }
  build_neighbour_list(points, pos.size(), reach + skin, neighbours_, point_radius);
  parallel_for(static_cast<std::int64_t>(pos.size()), [&](std::int64_t i) {
    std::sort(neighbours_.indices.begin() + neighbours_.offsets[i], neighbours_.indices.begin() + neighbours_.offsets[i + 1]);
  });
  stats_.ghosts = ghosts_.size();
}

// The list is kept while verlet_list_holds (common/verlet.hpp); the skin is verlet_skin of the reach.
void ReferenceSolver::update_neighbours(const ParticleSet& p, double dt) {
  const std::size_t n = p.size();
  const std::int64_t ni = static_cast<std::int64_t>(n);
  const bool same = list_valid_ && pos_at_build_.size() == n;
  const double vmax = std::max(0.0, parallel_max(ni, [&](std::int64_t i) { return norm(drift_velocity(p, i, dt)); }));
  const double moved =
      same ? std::max(0.0, parallel_max(ni, [&](std::int64_t i) { return norm(p.pos[i] - pos_at_build_[i]); })) : 0.0;
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

// The velocity a particle drifts with in the step: v_n + dt/2 a_n in the leapfrog (whose carried a_n is
// current), v_n before the first evaluation and in the midpoint rule.
Vec3d ReferenceSolver::drift_velocity(const ParticleSet& p, std::int64_t i, double dt) const {
  return leapfrog_ && p.rates_current ? p.vel[i] + 0.5 * dt * p.acceleration[i] : p.vel[i];
}

void ReferenceSolver::step(ParticleSet& p, double dt) {
  load_constants(p);
  update_neighbours(p, dt);
  if (leapfrog_) leapfrog_step(p, dt);
  else midpoint_step(p, dt);
  finish_history(p, dt);
}

// The explicit midpoint rule: y_1/2 = y_n + dt/2 f(y_n), y_n+1 = y_n + dt f(y_1/2); two evaluations.
void ReferenceSolver::midpoint_step(ParticleSet& p, double dt) {
  const std::size_t n = p.size();
  State& y0 = y0_;
  y0.pos = p.pos; y0.vel = p.vel; y0.rho = p.rho; y0.energy = p.energy; y0.dev_stress = p.dev_stress;
  Rates& f = rates_;
  State& y_half = y_half_;
  State& y1 = y1_;
  evaluate(y0, f, dt);
  advance(y0, f, 0.5 * dt, y_half, nullptr);
  evaluate(y_half, f, dt);
  advance(y0, f, dt, y1, &history_);
  check_state(y1, dt);
  double contact_power = 0;
  for (std::size_t i = 0; i < n; ++i) contact_power += f.contact_power[i];
  stats_.contact_work = dt * contact_power;
  p.rates_current = false;
  std::swap(p.pos, y1.pos);
  std::swap(p.vel, y1.vel);
  std::swap(p.rho, y1.rho);
  std::swap(p.energy, y1.energy);
  std::swap(p.dev_stress, y1.dev_stress);
}

// The rates of the particles' current state into their carried rate fields (the leapfrog's first step, or
// a state whose rates are not current).
void ReferenceSolver::evaluate_carried_rates(ParticleSet& p, double dt) {
  State& y0 = y0_;
  y0.pos = p.pos; y0.vel = p.vel; y0.rho = p.rho; y0.energy = p.energy; y0.dev_stress = p.dev_stress;
  evaluate(y0, rates_, dt);
  carry_rates(p);
  p.density_diffusion_before = p.density_diffusion;  // the first diffusion stands for the one before too
  // The list was checked for a drift at v_n; the drift at v_n + dt/2 a_n may need a new one.
  update_neighbours(p, dt);
}

// The rates of the last evaluation become the particles' carried rates (O(1): the arrays swap).
void ReferenceSolver::carry_rates(ParticleSet& p) {
  Rates& f = rates_;
  std::swap(p.acceleration, f.acc);
  std::swap(p.energy_rate, f.denergy);
  std::swap(p.density_diffusion_before, p.density_diffusion);
  std::swap(p.density_diffusion, f.drho_diffusion);
  std::swap(p.contact_power, f.contact_power);
  p.rates_current = true;
}

// Kick-drift-kick leapfrog with the deformation state staggered (common/stages.hpp, "Leapfrog"): one
// evaluation, split by the deform of density and stress between its two passes.
void ReferenceSolver::leapfrog_step(ParticleSet& p, double dt) {
  if (!p.rates_current) evaluate_carried_rates(p, dt);
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  State& half = y_half_;  // x_n+1, v_h and the deformation state of t_n: what pass 1 reads
  State& y1 = y1_;        // x_n+1, v*, rho_n+1, e*, S_n+1: what pass 2 reads; then the step end
  for (State* s : {&half, &y1}) resize_state(*s, static_cast<std::size_t>(n));
  parallel_for(n, [&](std::int64_t i) IMPACTSPH_FLATTEN {
    const KickDrift<double> k = kick_drift_point(params_, dt, fixed_[i] != 0, p.pos[i], p.vel[i], p.energy[i],
                                                 p.acceleration[i], p.energy_rate[i]);
    half.pos[i] = y1.pos[i] = k.x;
    half.vel[i] = k.v_half;
    y1.vel[i] = k.v_end;
    half.rho[i] = y1.rho[i] = p.rho[i];
    half.energy[i] = p.energy[i];
    y1.energy[i] = k.e_end;
    half.dev_stress[i] = y1.dev_stress[i] = p.dev_stress[i];
  });
  gather(half);
  gradient_pass();
  History& history = history_;
  resize_history(static_cast<std::size_t>(n));
  parallel_for(n, [&](std::int64_t i) IMPACTSPH_FLATTEN {
    const Mat3d& G = grad_v_[static_cast<std::size_t>(i)];
    const DeformInputs<double> in{G, diffusion_at_midstep(p.density_diffusion[i], p.density_diffusion_before[i]),
                                  y1.energy[i]};
    const PlasticResult<double> pr = deform_point(materials_[static_cast<std::size_t>(material_[i])], dt, in,
                                                  step_history(i), y1.rho[i], y1.dev_stress[i]);
    history.d_eps_p[i] = pr.d_eps_p;
    history.d_plastic_work[i] = pr.plastic_work;
    history.d_temperature[i] = pr.d_T;
    history.strain_rate[i] = equivalent_strain_rate(G);
  });
  restress(y1);
  Rates& f = rates_;
  rate_pass(f, dt);
  parallel_for(n, [&](std::int64_t i) IMPACTSPH_FLATTEN {
    y1.vel[i] = half.vel[i];
    y1.energy[i] = p.energy[i];
    kick_point(dt, f.acc[i], p.energy_rate[i], f.denergy[i], y1.vel[i], y1.energy[i]);
  });
  check_state(y1, dt);
  // The contact forces of both ends of the step each act for half of it.
  double contact_power = 0;
  for (std::int64_t i = 0; i < n; ++i) contact_power += p.contact_power[i] + f.contact_power[i];
  stats_.contact_work = 0.5 * dt * contact_power;
  std::swap(p.pos, y1.pos);
  std::swap(p.vel, y1.vel);
  std::swap(p.rho, y1.rho);
  std::swap(p.energy, y1.energy);
  std::swap(p.dev_stress, y1.dev_stress);
  carry_rates(p);
}

// Pass 2's view of the deformed state y (rho_n+1, e*, S_n+1, v*) after pass 1 of the half state: the reals'
// pressure, sound speed, stress at their damage and velocity, the ghosts' from their sources, then (S - P I)/rho^2
// at the new density with the artificial stress and the bulk viscosity of pass 1's velocity gradient. The
// density, volume and gradients of pass 1 stay: pass 2's delta-SPH diffusion is that of the density field of
// pass 1.
void ReferenceSolver::restress(const State& y) {
  const std::size_t n = y.pos.size();
  const std::int64_t ni = static_cast<std::int64_t>(n);
  const MaterialParams<double>* mats = materials_.data();
  const StagePoints<double> w = points();
  parallel_for(ni, [&](std::int64_t i) IMPACTSPH_FLATTEN {
    const GatheredPoint<double> g =
        gather_point(mats[mat_[i]], y.rho[i], y.energy[i], bulking_[i], damage_all_[i], y.dev_stress[i]);
    pressure_[i] = g.P; sound_speed_[i] = g.c; stress_[i] = g.S; v_[i] = y.vel[i];
    set_stress_terms(params_, w, i, y.rho[i]);
    if (params_.bulk_on) add_bulk_viscosity(params_.bulk, grad_v_[i].trace(), y.rho[i], g.c, hh_[i], s_over_rho2_[i]);
  });
  for (std::size_t k = 0; k < ghosts_.size(); ++k) {
    const Ghost& g = ghosts_[k];
    const std::size_t s = static_cast<std::size_t>(g.source), i = n + k;
    const MirroredPoint<double> image =
        mirror_point(g.sign, g.shift, g.walls, let_go_[s], y.pos[s], y.vel[s], stress_[s], m_[s]);
    v_[i] = image.v; stress_[i] = image.S;
    pressure_[i] = pressure_[s]; sound_speed_[i] = sound_speed_[s];
    set_stress_terms(params_, w, static_cast<std::int64_t>(i), y.rho[s]);
    if (params_.bulk_on) s_over_rho2_[i] = mirror(s_over_rho2_[s], cast3<double>(g.sign));
  }
}

void ReferenceSolver::resize_state(State& y, std::size_t n) {
  y.pos.resize(n); y.vel.resize(n); y.rho.resize(n); y.energy.resize(n); y.dev_stress.resize(n);
}

void ReferenceSolver::resize_history(std::size_t n) {
  history_.d_eps_p.resize(n);
  history_.d_plastic_work.resize(n);
  history_.d_temperature.resize(n);
  history_.strain_rate.resize(n);
}

StepHistory<double> ReferenceSolver::step_history(std::int64_t i) const {
  return {plastic_strain_[i], temperature_[i], bulking_[i], damage_[i]};
}

// History variables after the step: the non-local plastic work, then plastic strain, heating, damage and
// bulking and the smoothing length (finish_point).
void ReferenceSolver::finish_history(ParticleSet& p, double dt) {
  const std::size_t n = p.size();
  History& history = history_;
  // The non-local plastic work of the particles that may fail on it this step (common/nonlocal.hpp), from
  // every particle's plastic work after the step.
  nonlocal_work_.assign(n, 0.0);
  if (!nonlocal_grid_.empty()) {
    work_density_.resize(n);
    parallel_for(static_cast<std::int64_t>(n), [&](std::int64_t i) {
      work_density_[i] = plastic_work_density(materials_[static_cast<std::size_t>(p.material[i])],
                                              p.plastic_work[i] + history.d_plastic_work[i]);
    });
    const NonlocalGrid<double> grid = nonlocal_grid_.view();
    parallel_for(static_cast<std::int64_t>(n), [&](std::int64_t i) {
      const MaterialParams<double>& mat = materials_[static_cast<std::size_t>(p.material[i])];
      if (damage_uses_nonlocal_work(mat, p.damage[i], history.d_eps_p[i], p.plastic_work[i] + history.d_plastic_work[i]))
        nonlocal_work_[i] = nonlocal_work_density(grid, static_cast<std::int32_t>(i), damage_nonlocal_radius(mat),
                                                  work_density_.data());
    });
  }
  // History variables of the final stage: plastic strain, adiabatic heating, damage, bulking (F 4.7-4.9,
  // X eq 28; integration.hpp), and the smoothing length.
  parallel_for(static_cast<std::int64_t>(n), [&](std::int64_t i) IMPACTSPH_FLATTEN {
    finish_point(materials_[static_cast<std::size_t>(p.material[i])], smoothing_[static_cast<std::size_t>(p.body[i])],
                 grad_v_[static_cast<std::size_t>(i)], dt, p.rho[i], p.energy[i], p.dev_stress[i], p.plastic_strain[i],
                 p.plastic_work[i], p.temperature[i], p.damage[i], p.pressure[i], p.bulking_pressure[i], p.h[i],
                 history.d_eps_p[i], history.d_plastic_work[i], history.d_temperature[i], history.strain_rate[i],
                 nonlocal_work_[static_cast<std::size_t>(i)]);
  });
}

}  // namespace impactsph::reference
