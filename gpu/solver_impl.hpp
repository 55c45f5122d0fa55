// The gpu solver, written once for both builds: solver_host.cpp includes it with
// IMPACTSPH_GPU_BACKEND = host (OpenMP loops, Thrust OMP system), solver_cuda.cu with cuda (kernels,
// Thrust CUDA system: radix sort, scans and reductions on the device).
//
// A step is the reference's (reference/solver.hpp): explicit midpoint, each evaluation = mirror ghosts,
// EOS, pass 1, stress rate, pass 2; what a point or a pair computes is a stage of common/stages.hpp, the
// same functions the reference calls. What differs is the storage and the loop shape:
//   * storage: structure of arrays in device memory, one array per field; the real particles are kept in
//     the order of their cells (re-sorted when they have moved enough), and `original` maps back;
//   * neighbours: all points (reals and symmetry ghosts) sorted by cell key (stable radix sort), cell
//     ranges cell_start[c] .. cell_start[c+1]; at each sort one thread per particle gathers over the 5x5x5
//     cells of half the search radius around its own into its Verlet list (count, scan, fill);
//   * each evaluation gathers the fields into work arrays in the sorted order, and every pass is one
//     thread per particle summing over its list (no atomics: each thread owns its sums, in a fixed order);
//   * the sort and the lists are kept while no particle can have moved half the skin (Verlet criterion),
//     so the lists hold every pair that can come within the kernel support or the contact distance.
// Double build: the same pairs and formulas as the reference, summed in another order (round-off only).
// Float build: every field in float except positions, kept in double so that displacements of 1e-7 of a
// spacing are not lost; pair distances are taken in double and then rounded.
#pragma once
#include <thrust/copy.h>
#include <thrust/device_ptr.h>
#include <thrust/device_vector.h>
#include <thrust/fill.h>
#include <thrust/gather.h>
#include <thrust/reduce.h>
#include <thrust/scatter.h>
#include <thrust/scan.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>
#include <thrust/transform_reduce.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "common/errors.hpp"
#include "common/nonlocal.hpp"
#include "common/stage_setup.hpp"
#include "common/stages.hpp"
#include "common/verlet.hpp"
#include "gpu/cells.hpp"
#include "gpu/device_arrays.hpp"
#include "gpu/launch.hpp"
#if !defined(__CUDACC__)
#include "common/lanes.hpp"
#endif
#include "gpu/phase_clock.hpp"
#include "gpu/solver.hpp"

namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND {






#if !defined(__CUDACC__)
// The fields pass 1 reads of the kLanes points of a cluster (gpu/solver_clusters.hpp), lane by lane: one
// cluster's data are contiguous, and each field of it is one SIMD load.
template <class Real>
struct alignas(64) ClusterPoints {
  double x[kLanes<Real>], y[kLanes<Real>], z[kLanes<Real>];  // position, m
  Real h[kLanes<Real>], vol[kLanes<Real>];             // smoothing length (m), volume m/rho (m^3)
  Real vx[kLanes<Real>], vy[kLanes<Real>], vz[kLanes<Real>];  // velocity, m/s
  Real rho[kLanes<Real>], damage[kLanes<Real>];         // density (kg/m^3), pair damage
  std::int32_t slot[kLanes<Real>], body[kLanes<Real>], walls[kLanes<Real>], face[kLanes<Real>];  // sorted point (-1: none), body,
                                                                         // image walls, crack face
};
// What pass 2 reads of the kLanes points of a cluster beyond ClusterPoints, lane by lane (after pass 1 and the
// ghosts' mirrored gradients). The artificial stress and the velocity gradient are packed only where the
// pair terms read them (artificial stress on; limited viscosity).
template <class Real>
struct alignas(64) ClusterRates {
  Real A[6][kLanes<Real>];         // (S - P I) / rho^2 as Sym3 (xx, yy, zz, xy, yz, zx), m^5 kg^-1 s^-2
  Real R[6][kLanes<Real>];         // artificial stress, as A
  Real linv[9][kLanes<Real>];      // correction L^-1, row-major
  Real grad_v[9][kLanes<Real>];    // dv_a/dx_b (1/s), row-major
  Real grad_rho[3][kLanes<Real>];  // kg/m^4
  Real v[3][kLanes<Real>];         // velocity, m/s (pass 2's: the leapfrog's differs from pass 1's)
  Real c[kLanes<Real>], av[kLanes<Real>], m[kLanes<Real>];  // sound speed (m/s), viscosity factor, mass (kg)
  std::int32_t mat[kLanes<Real>];  // material (-1: no point)
};
// What the lane loops read of each real's row: its slot, its clusters cluster[first[i] .. end[i]) (where its
// list entries were), the packed clusters, and each body's penalty-contact bits.
template <class Real>
struct ClusterRows {
  const std::int32_t* slot;
  const std::int64_t* first;
  const std::int64_t* end;
  const std::int32_t* cluster;
  const ClusterPoints<Real>* packed;
  const std::int32_t* penalty_bits;
};
#endif

template <class Real>
class Solver final : public GpuStepper {
 public:
  static constexpr bool kFlush = sizeof(Real) < sizeof(double);  // float: subnormals to zero (launch.hpp)
  Solver(const Scene& scene, const char* build)
      : numerics_(scene.spec.numerics), leapfrog_(scene.spec.numerics.integrator == Integrator::Leapfrog) {
    const bool dbl = sizeof(Real) == sizeof(double);
    name_ = std::string("gpu port (") + (dbl ? "double" : "float") + ", " + build + ")";
    for (const BodyInfo& b : scene.bodies) body_names_.push_back(b.name);
    params_ = make_stage_params<Real>(scene);
    std::vector<MaterialParams<Real>> mats;
    for (const MaterialParams<double>& m : scene.materials) mats.push_back(convert_material<Real>(m));
    materials_ = mats;
    contacts_ = make_pair_contacts<Real>(scene);
    const ContactReach reach = contact_reach(scene);
    contact_reach_ = reach.distance;
    contact_srad_ = reach.srad;
    const std::vector<BodySmoothing<Real>> smoothing = make_body_smoothing<Real>(scene);
    for (const BodySmoothing<Real>& b : smoothing) variable_h_ = variable_h_ || b.variable;
    body_smoothing_ = smoothing;
    upload_nonlocal_grid(build_nonlocal_grid(scene.particles, scene.materials));
#if !defined(__CUDACC__)
    set_cluster_ranks(scene);
#endif
  }

  std::string name() const override { return name_; }
  StepStats last_stats() const override { return stats_; }
  void defer_host_copies(bool defer) override { defer_ = defer; }
  long sorts() const override { return sorts_; }
  void profile_phases(bool on) override { clock_.on = on; }
  std::vector<PhaseTime> phase_times() const override {
    std::vector<PhaseTime> r;
    for (int k = 0; k < PhaseClock::Count; ++k) r.push_back(PhaseTime{PhaseClock::name(k), clock_.calls[k], clock_.seconds[k]});
    return r;
  }

  double stable_time_step(const ParticleSet& p) override {
    if (!resident_) upload(p);
    const std::int64_t n = n_;
    Real* out = raw(scratch_real_);
    const StateView<Real> y = state_view(d_);
    const MaterialParams<Real>* mats = raw(materials_);
    const Real* h = raw(d_.h);
    const std::int32_t* mat = raw(d_.material);
    const Real cfl = params_.cfl;
    clock_.begin();
    // F eq 5.1 per particle, then the minimum (an exact reduction: the same in any order).
    launch<kFlush>("time_step", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      out[i] = point_time_step(mats[mat[i]], cfl, y.rho[i], y.energy[i], h[i], y.vel[i]);
    });
    const Real dt = thrust::reduce(scratch_real_.begin(), scratch_real_.begin() + n, std::numeric_limits<Real>::infinity(),
                                   MinOf{});
    clock_.end(PhaseClock::TimeStep);
    return static_cast<double>(dt);
  }

  // The lists sum each particle's pairs in an order that does not depend on when they were built (see
  // sort_particles), so a run restarted from what the host now holds continues with the same bits
  // without a sort here.
  void copy_to_host(ParticleSet& p) override {
    if (!resident_) return;
    download(p);
  }

  // The device state into p, in the scene's order: every field a step changes (FieldKind::Constant ones
  // are as uploaded), scattered by `original` into scene_order_ (kept, so that a copy allocates nothing on
  // the device), widened to double.
  void download(ParticleSet& p) {
    p.rates_current = rates_current_;
    for_each_field_pair(d_, scene_order_, [&](const FieldInfo& f, const auto& dev, auto& ordered) {
      if (f.kind == FieldKind::Constant) return;
      ordered.resize(dev.size());
      thrust::scatter(dev.begin(), dev.end(), original_.begin(), ordered.begin());
    });
    for_each_field_pair(p, scene_order_, [](const FieldInfo& f, auto& host, const auto& ordered) {
      if (f.kind == FieldKind::Constant) return;
      using D = typename std::decay_t<decltype(ordered)>::value_type;
      using H = typename std::decay_t<decltype(host)>::value_type;
      std::vector<D> staged(ordered.size());
      thrust::copy(ordered.begin(), ordered.end(), staged.begin());
      for (std::size_t i = 0; i < staged.size(); ++i) host[i] = to_host<H>(staged[i]);
    });
  }

  void step(ParticleSet& p, double dt) override {
    if (!resident_) upload(p);
    if (leapfrog_ && !rates_current_) {
      keep_sort(dt);
      evaluate(state_view(d_), dt);
      carry_rates();
      d_.density_diffusion_before = d_.density_diffusion;  // the first diffusion stands for the one before too
    }
    keep_sort(dt);
    if (leapfrog_) leapfrog_step(dt);
    else midpoint_step(dt);
    clock_.time(PhaseClock::Finish, [&] { finish(dt); });
    if (!defer_) download(p);
  }

  // Sorts again unless the lists still hold every pair the step's evaluation can need: pairs approach by at
  // most dt vmax before it (vmax the largest drift speed), while the particles have moved at most
  // max_displacement since the sort. With a variable smoothing length the support grows too: a pair the
  // lists must hold is within reach(h_max now) + 2 (displacement + dt vmax) < reach(h_max at the sort) + skin.
  void keep_sort(double dt) {
    const double vmax = max_drift_speed(dt);
    const double growth = variable_h_ && sorted_ ? search_reach(max_smoothing_length()) - reach_at_sort_ : 0.0;
    if (!sorted_ || !verlet_list_holds(max_displacement(), dt, vmax, growth, skin_))
      clock_.time(PhaseClock::Sort, [&] { sort_particles(); });
  }

  // The explicit midpoint rule (reference/solver.hpp): two evaluations.
  void midpoint_step(double dt) {
    evaluate(state_view(d_), dt);
    clock_.time(PhaseClock::Advance, [&] { advance(state_view(d_), 0.5 * dt, view(y_half_), false); });
    evaluate(view(y_half_), dt);
    clock_.time(PhaseClock::Advance, [&] { advance(state_view(d_), dt, view(y1_), true); });
    clock_.time(PhaseClock::Check, [&] { check_state(dt); });
    stats_.contact_work = dt * contact_power_sum(contact_power_);
    swap_state(d_, y1_);
    rates_current_ = false;
  }

  // Kick-drift-kick leapfrog with the deformation state staggered (common/stages.hpp, "Leapfrog"): one
  // evaluation, split by the deform of density and stress between its two passes.
  void leapfrog_step(double dt) {
    clock_.time(PhaseClock::Advance, [&] { kick_drift(dt); });
    gather(view(y_half_));
    gradients();
    clock_.time(PhaseClock::Advance, [&] { deform(dt); });
    restress(view(y1_));
    rates(dt);
    clock_.time(PhaseClock::Advance, [&] { kick(dt); });
    clock_.time(PhaseClock::Check, [&] { check_state(dt); });
    // The contact forces of both ends of the step each act for half of it.
    stats_.contact_work = 0.5 * dt * (contact_power_sum(d_.contact_power) + contact_power_sum(contact_power_));
    swap_state(d_, y1_);
    carry_rates();
  }

  // The rates of the last evaluation become the particles' carried rates (O(1): the arrays swap).
  void carry_rates() {
    rate_acc_.swap(d_.acceleration);
    rate_de_.swap(d_.energy_rate);
    d_.density_diffusion_before.swap(d_.density_diffusion);
    rate_drho_diffusion_.swap(d_.density_diffusion);
    contact_power_.swap(d_.contact_power);
    rates_current_ = true;
  }

  // The largest speed a particle drifts with in the step: |v_n + dt/2 a_n| in the leapfrog whose carried
  // rates are current, |v_n| otherwise.
  double max_drift_speed(double dt_in) {
    const StateView<Real> y = state_view(d_);
    const Vec3<Real>* acc = raw(d_.acceleration);
    const bool kick = leapfrog_ && rates_current_;
    const Real half_dt = static_cast<Real>(0.5 * dt_in);
    Real* out = raw(scratch_real_);
    launch<kFlush>("speed", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      out[i] = kick ? norm(y.vel[i] + half_dt * acc[i]) : norm(y.vel[i]);
    });
    return static_cast<double>(thrust::reduce(scratch_real_.begin(), scratch_real_.begin() + n_, Real(0), MaxOf{}));
  }

 // The rest is public only because nvcc's extended (device) lambdas may not live in private members.
  void upload(const ParticleSet& p) {
    const std::size_t n = p.size();
    n_ = static_cast<std::int64_t>(n);
    y_half_.resize(n); y1_.resize(n);
    for_each_field_pair(p, d_, [](const FieldInfo&, const auto& host, auto& dev) {
      using D = typename std::decay_t<decltype(dev)>::value_type;
      std::vector<D> staged(host.size());
      for (std::size_t i = 0; i < host.size(); ++i) staged[i] = to_device<D>(host[i]);
      dev = staged;
    });
    rates_current_ = p.rates_current;
    original_.resize(n);
    thrust::sequence(original_.begin(), original_.end());
    for (DVec<Real>* a : {&rate_drho_, &rate_drho_diffusion_, &rate_de_, &strain_rate_, &contact_power_, &d_eps_p_, &d_plastic_work_,
                          &d_temperature_, &history_rate_, &scratch_real_})
      a->resize(n);
    rate_pos_.resize(n); rate_acc_.resize(n); rate_S_.resize(n); grad_v_.resize(n);
    fallback_.resize(n); neighbour_count_.resize(n); pos_at_sort_.resize(n); nonlocal_work_.resize(n);
    sorted_ = false;
    resident_ = true;
  }

  // The grid of the non-local plastic work (common/nonlocal.hpp) on the device, in the scene's order: the
  // initial configuration of the scene this solver was made from (before a checkpoint replaces it).
  void upload_nonlocal_grid(const NonlocalGridData& g) {
    nonlocal_ = !g.empty();
    if (!nonlocal_) return;
    nonlocal_grid_ = NonlocalGrid<Real>{g.origin, g.cell, g.nx, g.ny, g.nz};
    nl_cell_start_ = g.cell_start;
    nl_particle_ = g.particle;
    nl_body_ = g.body;
    nl_entry_of_ = g.entry_of;
    nl_position_ = g.position;
    std::vector<Real> volume(g.volume.begin(), g.volume.end());
    nl_volume_ = volume;
    nonlocal_grid_.cell_start = raw(nl_cell_start_);
    nonlocal_grid_.particle = raw(nl_particle_);
    nonlocal_grid_.body = raw(nl_body_);
    nonlocal_grid_.entry_of = raw(nl_entry_of_);
    nonlocal_grid_.position = raw(nl_position_);
    nonlocal_grid_.volume = raw(nl_volume_);
    work_scene_.resize(g.entry_of.size());
  }

  // Search radius without the skin: the kernel support or the contact distance at the largest h (m).
  double search_reach(double h_max) const {
    return impactsph::search_reach(static_cast<double>(kernel_support(h_max)), contact_reach_, contact_srad_, h_max);
  }

  // A contact power (per particle, W, in the sorted order) summed over the particles in the scene's order, so
  // that the sum does not depend on the order of the last sort either.
  double contact_power_sum(DVec<Real>& contact_power) {
    if (contact_reach_ == 0 && contact_srad_ == 0) return 0.0;
    const Real* power = raw(contact_power);
    const std::int32_t* orig = raw(original_);
    Real* out = raw(scratch_real_);
    launch<kFlush>("contact_power", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) { out[orig[i]] = power[i]; });
    return static_cast<double>(thrust::reduce(scratch_real_.begin(), scratch_real_.begin() + n_, Real(0)));
  }

  double max_smoothing_length() {
    return static_cast<double>(thrust::reduce(d_.h.begin(), d_.h.begin() + n_, Real(0), MaxOf{}));
  }
  double min_smoothing_length() {
    return static_cast<double>(
        thrust::reduce(d_.h.begin(), d_.h.begin() + n_, std::numeric_limits<Real>::max(), MinOf{}));
  }

  double max_displacement() {
    const Vec3p* x = raw(d_.pos);
    const Vec3p* x0 = raw(pos_at_sort_);
    Real* out = raw(scratch_real_);
    launch<kFlush>("displacement", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) { out[i] = static_cast<Real>(norm(x[i] - x0[i])); });
    return static_cast<double>(thrust::reduce(scratch_real_.begin(), scratch_real_.begin() + n_, Real(0), MaxOf{}));
  }

  Grid grid_of(const DVec<Vec3p>& points, std::size_t count, double cell) const {
    const Vec3p first = points[0];
    const Box b = thrust::transform_reduce(points.begin(), points.begin() + static_cast<std::int64_t>(count), PointBox{},
                                           Box{first, first}, MergeBox{});
    Grid g;
    g.cell = cell;
    for (int a = 0; a < 3; ++a) {
      g.lo[a] = b.lo[a];
      g.dims[a] = std::max<std::int64_t>(1, static_cast<std::int64_t>((b.hi[a] - b.lo[a]) / cell) + 1);
    }
    const std::int64_t cells = g.dims[0] * g.dims[1] * g.dims[2];
    if (cells > 32 * static_cast<std::int64_t>(count) + 1000000 || cells >= (std::int64_t(1) << 32))
      throw std::runtime_error("particles spread over too large a box for the cell list (a particle has flown far away?)");
    return g;
  }

  // Permutes every per-particle array of the reals by `perm` (new i <- old perm[i]).
  template <class T> void permute(DVec<T>& a) {
    DVec<T> tmp(a.size());
    thrust::gather(perm_.begin(), perm_.end(), a.begin(), tmp.begin());
    a.swap(tmp);
  }

  // Re-sort: the reals into the order of their cells (so that neighbours are near in memory), the mirror
  // ghosts of the symmetry planes, then all points by cell key with cell ranges.
  void sort_particles();


  // The work arrays by sorted slot, as the stages (common/stages.hpp) read them.
  StagePoints<Real> points() {
    return {raw(wx_), raw(wv_), raw(wrho_), raw(wp_), raw(wc_), raw(wm_), raw(wh_), raw(wvol_), raw(wdamage_),
            raw(wav_), raw(wA_), raw(wS_), params_.art.on() ? raw(wR_) : nullptr, raw(wmat_), raw(wbody_),
            raw(wlet_go_), raw(wimage_walls_), raw(wlinv_), params_.visc.limited ? raw(wgv_) : nullptr,
            raw(wgrad_rho_), raw(contacts_), params_.body_count};
  }

  void evaluate(const StateView<Real>& state, double dt_in) {
    if (params_.kernel == KernelKind::WendlandC2) evaluate_with<KernelKind::WendlandC2>(state, dt_in);
    else evaluate_with<KernelKind::CubicSpline>(state, dt_in);
  }

  // One evaluation of the rates with the kernel fixed at compile time, so the pair loops carry no select
  // between kernels. In the pair loops (IMPACTSPH_SIMD_SUMS, launch.hpp) the only values carried from one
  // neighbour to the next are sums, kept as arrays of Reals; penalty contact, rare and heavy, has a loop of
  // its own after the SPH pairs (its sums in the same list order as before).
  template <KernelKind K>
  void evaluate_with(const StateView<Real>& state, double dt_in);
  void gather(const StateView<Real>& state);
  template <KernelKind K> void gradient_pass();
  template <KernelKind K> void rate_pass(double dt_in);
  void restress(const StateView<Real>& state);
  void gradients() {
    if (params_.kernel == KernelKind::WendlandC2) gradient_pass<KernelKind::WendlandC2>();
    else gradient_pass<KernelKind::CubicSpline>();
  }
  void rates(double dt_in) {
    if (params_.kernel == KernelKind::WendlandC2) rate_pass<KernelKind::WendlandC2>(dt_in);
    else rate_pass<KernelKind::CubicSpline>(dt_in);
  }


  // y = y0 + dt f (advance_point, stages.hpp).
  void advance(const StateView<Real>& y0, double dt_in, const StateView<Real>& out, bool record) {
    const MaterialParams<Real>* mats = raw(materials_);
    const StageParams<Real> prm = params_;
    const Real dt = static_cast<Real>(dt_in);
    const double dtp = dt_in;
    const Vec3<Real>* rpos = raw(rate_pos_);
    const Vec3<Real>* racc = raw(rate_acc_);
    const Real* rdrho = raw(rate_drho_);
    const Real* rde = raw(rate_de_);
    const Sym3<Real>* rS = raw(rate_S_);
    const Real* reps = raw(strain_rate_);
    const Real* eps_p = raw(d_.plastic_strain);
    const Real* T = raw(d_.temperature);
    const Real* D = raw(d_.damage);
    const Real* bulking = raw(d_.bulking_pressure);
    const std::int32_t* material = raw(d_.material);
    Real* h_eps = raw(d_eps_p_);
    Real* h_work = raw(d_plastic_work_);
    Real* h_T = raw(d_temperature_);
    Real* h_rate = raw(history_rate_);
    launch<kFlush>(record ? "advance_full" : "advance_half", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      Vec3p x = y0.pos[i];
      Vec3<Real> v = y0.vel[i];
      Real rho = y0.rho[i], e = y0.energy[i];
      Sym3<Real> S = y0.S[i];
      const PlasticResult<Real> pr = advance_point(prm, mats[material[i]], dt, dtp, x, v, rho, e, S, rpos[i], racc[i],
                                                   rdrho[i], rde[i], rS[i], reps[i], eps_p[i], T[i], bulking[i], D[i]);
      out.pos[i] = x;
      out.vel[i] = v;
      out.rho[i] = rho;
      out.energy[i] = e;
      out.S[i] = S;
      if (record) {
        h_eps[i] = pr.d_eps_p;
        h_work[i] = pr.plastic_work;
        h_T[i] = pr.d_T;
        h_rate[i] = reps[i];
      }
    });
  }

  // The leapfrog's first kick and drift (kick_drift_point, stages.hpp): into y_half_ what pass 1 reads (x_n+1,
  // v_h and the deformation state of t_n), into y1_ what pass 2 will read (x_n+1, v*, e*; rho and S are
  // deform's).
  void kick_drift(double dt) {
    const StageParams<Real> prm = params_;
    const StateView<Real> y0 = state_view(d_), half = view(y_half_), end = view(y1_);
    const Vec3<Real>* acc = raw(d_.acceleration);
    const Real* de = raw(d_.energy_rate);
    const std::uint8_t* fixed = raw(d_.fixed);
    launch<kFlush>("kick_drift", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      const KickDrift<Real> k = kick_drift_point(prm, dt, fixed[i] != 0, y0.pos[i], y0.vel[i], y0.energy[i], acc[i], de[i]);
      half.pos[i] = k.x; half.vel[i] = k.v_half; half.rho[i] = y0.rho[i]; half.energy[i] = y0.energy[i];
      half.S[i] = y0.S[i];
      end.pos[i] = k.x; end.vel[i] = k.v_end; end.rho[i] = y0.rho[i]; end.energy[i] = k.e_end; end.S[i] = y0.S[i];
    });
  }

  // Density and stress from t_n to t_n+1 under pass 1's velocity gradient (deform_point, stages.hpp), in y1_,
  // and the plastic return's increments for finish().
  void deform(double dt_in) {
    const MaterialParams<Real>* mats = raw(materials_);
    const Real dt = static_cast<Real>(dt_in);
    const StateView<Real> end = view(y1_);
    const Mat3<Real>* grad_v = raw(grad_v_);
    const Real* eps_p = raw(d_.plastic_strain);
    const Real* T = raw(d_.temperature);
    const Real* D = raw(d_.damage);
    const Real* bulking = raw(d_.bulking_pressure);
    const std::int32_t* material = raw(d_.material);
    Real* h_eps = raw(d_eps_p_);
    Real* h_work = raw(d_plastic_work_);
    Real* h_T = raw(d_temperature_);
    Real* h_rate = raw(history_rate_);
    const Real* diffusion_last = raw(d_.density_diffusion);
    const Real* diffusion_before = raw(d_.density_diffusion_before);
    launch<kFlush>("deform", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      const DeformInputs<Real> in{grad_v[i], diffusion_at_midstep(diffusion_last[i], diffusion_before[i]), end.energy[i]};
      const PlasticResult<Real> pr = deform_point(mats[material[i]], dt, in, StepHistory<Real>{eps_p[i], T[i], bulking[i], D[i]},
                                                  end.rho[i], end.S[i]);
      h_eps[i] = pr.d_eps_p;
      h_work[i] = pr.plastic_work;
      h_T[i] = pr.d_T;
      h_rate[i] = equivalent_strain_rate(grad_v[i]);
    });
  }

  // The leapfrog's last kick (kick_point, stages.hpp): v, e and the density's diffusion in y1_, from the half
  // state and the rates of this step's evaluation.
  void kick(double dt_in) {
    const Real dt = static_cast<Real>(dt_in);
    const StateView<Real> y0 = state_view(d_), half = view(y_half_), end = view(y1_);
    const Vec3<Real>* acc = raw(rate_acc_);
    const Real* de_start = raw(d_.energy_rate);
    const Real* de_end = raw(rate_de_);
    launch<kFlush>("kick", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      Vec3<Real> v = half.vel[i];
      Real e = y0.energy[i];
      kick_point(dt, acc[i], de_start[i], de_end[i], v, e);
      end.vel[i] = v;
      end.energy[i] = e;
    });
  }

  // History variables of the final stage: plastic strain, heating, pressure, damage, bulking (F 4.7-4.9,
  // X eq 28), and the variable smoothing length (X eqs 9-10) from the velocity gradient of the last
  // evaluation.
  void finish(double dt_in) {
    const StateView<Real> y = state_view(d_);
    const MaterialParams<Real>* mats = raw(materials_);
    const std::int32_t* material = raw(d_.material);
    Real* eps_p = raw(d_.plastic_strain);
    Real* work = raw(d_.plastic_work);
    Real* T = raw(d_.temperature);
    Real* D = raw(d_.damage);
    Real* P = raw(d_.pressure);
    Real* bulking = raw(d_.bulking_pressure);
    Real* h = raw(d_.h);
    const std::int32_t* body = raw(d_.body);
    const BodySmoothing<Real>* smoothing = raw(body_smoothing_);
    const Mat3<Real>* grad_v = raw(grad_v_);
    const Real dt = static_cast<Real>(dt_in);
    const Real* h_eps = raw(d_eps_p_);
    const Real* h_work = raw(d_plastic_work_);
    const Real* h_T = raw(d_temperature_);
    const Real* h_rate = raw(history_rate_);
    Real* nonlocal = raw(nonlocal_work_);
    const bool averages = nonlocal_;
    if (averages) {
      // The non-local plastic work of the particles that may fail on it this step, from every particle's
      // plastic work per unit initial volume after the step in the scene's order (common/nonlocal.hpp).
      Real* density = raw(scratch_real_);
      launch<kFlush>("work_density", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
        density[i] = plastic_work_density(mats[material[i]], work[i] + h_work[i]);
      });
      thrust::scatter(scratch_real_.begin(), scratch_real_.begin() + n_, original_.begin(), work_scene_.begin());
      const NonlocalGrid<Real> grid = nonlocal_grid_;
      const Real* scene_density = raw(work_scene_);
      const std::int32_t* orig = raw(original_);
      launch<kFlush>("nonlocal_work", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
        const MaterialParams<Real>& m = mats[material[i]];
        nonlocal[i] = damage_uses_nonlocal_work(m, D[i], h_eps[i], work[i] + h_work[i])
                          ? nonlocal_work_density(grid, orig[i], damage_nonlocal_radius(m), scene_density)
                          : Real(0);
      });
    }
    launch<kFlush>("finish_step", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      finish_point(mats[material[i]], smoothing[body[i]], grad_v[i], dt, y.rho[i], y.energy[i], y.S[i], eps_p[i],
                   work[i], T[i], D[i], P[i], bulking[i], h[i], h_eps[i], h_work[i], h_T[i], h_rate[i],
                   averages ? nonlocal[i] : Real(0));
    });
  }

  // Stops on a non-finite or non-positive state with the particle (lowest scene index) and its fields;
  // the state of the step start is kept.
  void check_state(double dt) {
    const StateView<Real> y = view(y1_);
    const std::int32_t* orig = raw(original_);
    const std::int64_t n = n_;
    bad_.resize(static_cast<std::size_t>(n));
    std::int64_t* bad = raw(bad_);
    launch<kFlush>("check_state", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      const bool ok = state_is_finite(y.pos[i], y.vel[i], y.rho[i], y.energy[i], y.S[i]);
      bad[i] = ok ? std::numeric_limits<std::int64_t>::max() : (static_cast<std::int64_t>(orig[i]) << 32) | i;
    });
    const std::int64_t first =
        thrust::reduce(bad_.begin(), bad_.end(), std::numeric_limits<std::int64_t>::max(), MinOf{});
    if (first == std::numeric_limits<std::int64_t>::max()) return;
    const std::size_t i = static_cast<std::size_t>(first & 0xffffffff);
    const std::int64_t o = first >> 32;
    const Vec3p x = y1_.pos[i];
    const Vec3<Real> v = y1_.vel[i];
    const Sym3<Real> S = y1_.S[i];
    const std::int32_t b = d_.body[i];
    throw particle_diverged(dt, static_cast<long long>(o), body_names_[static_cast<std::size_t>(b)], {x.x, x.y, x.z},
                            {v.x, v.y, v.z}, Real(y1_.rho[i]), Real(y1_.energy[i]), von_mises(S));
  }

  NumericsSpec numerics_;
  std::string name_;
  std::vector<std::string> body_names_;
  StageParams<Real> params_{};
  DVec<MaterialParams<Real>> materials_;
  DVec<PairContact<Real>> contacts_;
  DVec<BodySmoothing<Real>> body_smoothing_;
  // The non-local plastic work (common/nonlocal.hpp): the grid (scene order, never re-sorted), per scene
  // index the plastic work per unit initial volume (J/m^3), per sorted slot the non-local average (J/m^3).
  bool nonlocal_ = false;
  NonlocalGrid<Real> nonlocal_grid_{};
  DVec<std::int32_t> nl_cell_start_, nl_particle_, nl_body_, nl_entry_of_;
  DVec<Vec3p> nl_position_;
  DVec<Real> nl_volume_, work_scene_, nonlocal_work_;
  bool variable_h_ = false;   // some body has a variable smoothing length
  double contact_reach_ = 0;  // largest penalty contact distance, m
  double contact_srad_ = 0;   // largest SRAD of a penalty contact (touching at srad h)
  double reach_at_sort_ = 0;  // search_reach at the last sort, m
  double skin_ = 0, radius_ = 0;  // m
  bool resident_ = false, sorted_ = false, defer_ = false;
  long sorts_ = 0;
  std::int64_t n_ = 0, ghosts_ = 0;

  // Real particles, in the order of the last sort (original_ maps to the scene's order).
  DeviceParticles<Real> d_;         // the fields of ParticleSet, the state of the step start among them
  StateArrays<Real> y_half_, y1_;   // the midpoint (leapfrog: what pass 1 reads) and the step end
  bool leapfrog_ = false;           // numerics.integrator: leapfrog (else the midpoint rule)
  bool rates_current_ = false;      // d_'s carried rates are those of its state (ParticleSet::rates_current)
  DVec<std::int32_t> original_;
  DeviceParticles<Real> scene_order_;  // download's scratch: the changing fields in the scene's order
  DVec<Vec3p> pos_at_sort_;
  // Rates of an evaluation and the history of the final stage.
  DVec<Vec3<Real>> rate_pos_, rate_acc_;
  DVec<Real> rate_drho_, rate_drho_diffusion_, rate_de_, strain_rate_, contact_power_, d_eps_p_, d_plastic_work_, d_temperature_, history_rate_,
      scratch_real_;
  DVec<Sym3<Real>> rate_S_;
  DVec<Mat3<Real>> grad_v_;
  DVec<std::int32_t> fallback_, neighbour_count_;
  DVec<std::int64_t> bad_;
  // Ghosts and the cell structure.
  DVec<std::int32_t> ghost_count_, ghost_source_, ghost_mask_;
  DVec<std::int64_t> identity_;  // per sorted point: scene index << 8 | plane mask (0 for a real)
  DVec<Vec3p> ghost_sign_, ghost_shift_, points_;
  DVec<std::uint32_t> keys_;
  DVec<std::uint64_t> real_keys_;
  DVec<std::int32_t> perm_, order_, slot_of_, cell_start_, list_;
  DVec<std::int64_t> list_offset_;
  DVec<Vec3p> sorted_points_;
  DVec<double> slot_radius_;  // search radius of each sorted point when reach_per_pair (common/verlet.hpp), m
  Grid grid_{};
  // Work arrays over sorted slots.
  DVec<Vec3p> wx_;
  DVec<Vec3<Real>> wv_, wgrad_rho_;
  DVec<Real> wrho_, wp_, wc_, wm_, wh_, wvol_, wdamage_, wav_;
  DVec<Sym3<Real>> wA_, wS_, wR_;
  DVec<std::int32_t> wmat_, wbody_;
  DVec<unsigned> wlet_go_, wimage_walls_;
  DVec<Mat3<Real>> wlinv_, wgv_;
  StepStats stats_;
  PhaseClock clock_;

#if !defined(__CUDACC__)
 public:
  // The host build's pair passes over cluster pairs (gpu/solver_clusters.hpp), the default; off, they take the
  // rows as the CUDA kernels do.
  void use_cluster_pairs(bool on) override {
    cluster_pairs_ = on;
    sorted_ = false;  // the next step sorts, and builds the clusters
  }
  bool takes_cluster_pairs() const { return cluster_pairs_ && cluster_pairs_possible_; }
  void set_cluster_ranks(const Scene& scene);
  void build_clusters();
  template <class Packed, class Fill> void pack_by_lane(const char* name, std::vector<Packed>& packed, Fill fill);
  void pack_cluster_points(const StagePoints<Real>& w);
  template <class Kernel> void pass1_clusters(const Kernel& kernel, const StagePoints<Real>& w);
  void pack_cluster_rates(const StagePoints<Real>& w);
  ClusterRows<Real> cluster_rows();
  template <class Kernel> void pass2_clusters(const Kernel& kernel, const StagePoints<Real>& w, Real* sums);
  bool cluster_pairs_ = true;
  bool cluster_pairs_possible_ = true;  // fewer than 31 bodies (one bit each in a lane)
  std::vector<std::int32_t> cluster_rank_;     // per scene index: place in the Morton order of the scene
  std::vector<std::int32_t> penalty_bits_;     // per body: bit b set where it is in penalty contact with body b
  std::vector<std::int32_t> cluster_of_slot_;  // per sorted point
  std::vector<std::int32_t> cluster_slot_;     // per cluster lane: the sorted point there, -1 for none
  std::vector<std::int32_t> row_cluster_;      // row i's clusters: [list_offset_[i], row_cluster_end_[i])
  std::vector<std::int64_t> row_cluster_end_;
  std::vector<ClusterPoints<Real>> packed_;    // per cluster: what pass 1 reads of its points
  std::vector<ClusterRates<Real>> packed_rates_;  // per cluster: what pass 2 reads beyond packed_
  std::vector<Real> pair_sums_;                // per real: pass 2's kRateSums sums over the clusters
#endif
};

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND

#include "gpu/solver_passes.hpp"
#include "gpu/solver_sort.hpp"
#if !defined(__CUDACC__)
#include "gpu/solver_clusters.hpp"
#endif

namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND {

inline std::unique_ptr<GpuStepper> make_solver_for(const Scene& scene, Precision precision, const char* build) {
  if (precision == Precision::Double) return std::make_unique<Solver<double>>(scene, build);
  return std::make_unique<Solver<float>>(scene, build);
}

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND
