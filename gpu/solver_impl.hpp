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
#include "common/stage_setup.hpp"
#include "common/stages.hpp"
#include "common/verlet.hpp"
#include "gpu/launch.hpp"
#include "gpu/solver.hpp"

namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND {

template <class T> using DVec = thrust::device_vector<T>;
template <class T> T* raw(DVec<T>& v) { return thrust::raw_pointer_cast(v.data()); }

// Cells of half the search radius in a box; key = (cz dy + cy) dx + cx, so the cells along x are
// contiguous and a row of five cells is one range of sorted points.
struct Grid {
  double lo[3];
  double cell;
  std::int64_t dims[3];
  IMPACTSPH_HD std::int64_t coord(double x, int a) const {
    const std::int64_t c = static_cast<std::int64_t>((x - lo[a]) / cell);
    return c < 0 ? 0 : (c > dims[a] - 1 ? dims[a] - 1 : c);
  }
  IMPACTSPH_HD std::uint32_t key(Vec3p x) const {
    return static_cast<std::uint32_t>((coord(x.z, 2) * dims[1] + coord(x.y, 1)) * dims[0] + coord(x.x, 0));
  }
};

// The sorted points and their cell ranges: cell c holds the slots cell_start[c] .. cell_start[c+1].
struct CellRange {
  const Vec3p* x;
  const std::int32_t* cell_start;
  Grid grid;
  // Calls f(j) for every sorted slot j != s in the 5x5x5 cells around the cell of slot s.
  template <class F> IMPACTSPH_HD void for_each_candidate(std::int64_t s, F&& f) const {
    const Vec3p xs = x[s];
    const std::int64_t cx = grid.coord(xs.x, 0), cy = grid.coord(xs.y, 1), cz = grid.coord(xs.z, 2);
    const std::int64_t x0 = cx - 2 < 0 ? 0 : cx - 2, x1 = cx + 2 > grid.dims[0] - 1 ? grid.dims[0] - 1 : cx + 2;
    const std::int64_t y0 = cy - 2 < 0 ? 0 : cy - 2, y1 = cy + 2 > grid.dims[1] - 1 ? grid.dims[1] - 1 : cy + 2;
    const std::int64_t z0 = cz - 2 < 0 ? 0 : cz - 2, z1 = cz + 2 > grid.dims[2] - 1 ? grid.dims[2] - 1 : cz + 2;
    for (std::int64_t z = z0; z <= z1; ++z)
      for (std::int64_t y = y0; y <= y1; ++y) {
        const std::int64_t row = (z * grid.dims[1] + y) * grid.dims[0];  // cells along x are contiguous
        const std::int32_t first = cell_start[row + x0], last = cell_start[row + x1 + 1];
        for (std::int32_t j = first; j < last; ++j)
          if (j != s) f(j);
      }
  }
};

struct Box {
  Vec3p lo, hi;
};
struct PointBox {
  IMPACTSPH_HD Box operator()(Vec3p x) const { return {x, x}; }
};
struct MergeBox {
  IMPACTSPH_HD Box operator()(Box a, Box b) const {
    return {{a.lo.x < b.lo.x ? a.lo.x : b.lo.x, a.lo.y < b.lo.y ? a.lo.y : b.lo.y, a.lo.z < b.lo.z ? a.lo.z : b.lo.z},
            {a.hi.x > b.hi.x ? a.hi.x : b.hi.x, a.hi.y > b.hi.y ? a.hi.y : b.hi.y, a.hi.z > b.hi.z ? a.hi.z : b.hi.z}};
  }
};
struct MinOf {
  template <class T> IMPACTSPH_HD T operator()(T a, T b) const { return a < b ? a : b; }
};
struct MaxOf {
  template <class T> IMPACTSPH_HD T operator()(T a, T b) const { return a > b ? a : b; }
};

// The pass 1 sums of a particle as plain Reals, the form IMPACTSPH_SIMD_SUMS reduces: L, L_damaged, G
// (row-major) and the density gradient.
constexpr int kGradientSums = 30;
template <class Real> IMPACTSPH_HD void add_flat(Real* sum, const GradientSums<Real>& g) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      sum[3 * r + c] += g.L.m[r][c];
      sum[9 + 3 * r + c] += g.L_damaged.m[r][c];
      sum[18 + 3 * r + c] += g.G.m[r][c];
    }
  sum[27] += g.grad_rho.x;
  sum[28] += g.grad_rho.y;
  sum[29] += g.grad_rho.z;
}
template <class Real> IMPACTSPH_HD GradientSums<Real> unflatten_gradient_sums(const Real* sum) {
  GradientSums<Real> g;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      g.L.m[r][c] = sum[3 * r + c];
      g.L_damaged.m[r][c] = sum[9 + 3 * r + c];
      g.G.m[r][c] = sum[18 + 3 * r + c];
    }
  g.grad_rho = Vec3<Real>{sum[27], sum[28], sum[29]};
  return g;
}

// Wall time of the phases of a step: CUDA events on the device, the steady clock on the host.
class PhaseClock {
 public:
  enum Phase { Sort, TimeStep, Gather, Pass1, Pass2, Advance, Check, Finish, Count };
  static const char* name(int p) {
    static const char* names[Count] = {"sort", "time_step", "gather", "pass1", "pass2", "advance", "check", "finish"};
    return names[p];
  }
  bool on = false;
  // begin(p) ... end(p) around the launches of a phase (extended lambdas may not sit inside a lambda, so
  // the passes use these); time(p, f) around a call.
  void begin() {
    if (!on) return;
#if defined(__CUDACC__)
    if (!events_) {
      check_cuda(cudaEventCreate(&start_), "cudaEventCreate");
      check_cuda(cudaEventCreate(&stop_), "cudaEventCreate");
      events_ = true;
    }
    check_cuda(cudaEventRecord(start_), "cudaEventRecord");
#else
    t0_ = std::chrono::steady_clock::now();
#endif
  }
  void end(Phase p) {
    if (!on) return;
#if defined(__CUDACC__)
    check_cuda(cudaEventRecord(stop_), "cudaEventRecord");
    check_cuda(cudaEventSynchronize(stop_), "cudaEventSynchronize");
    float ms = 0;
    check_cuda(cudaEventElapsedTime(&ms, start_, stop_), "cudaEventElapsedTime");
    seconds[p] += 1e-3 * ms;
#else
    seconds[p] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
#endif
    ++calls[p];
  }
  template <class F> void time(Phase p, F&& f) {
    begin();
    f();
    end(p);
  }
  PhaseClock() = default;
  PhaseClock(const PhaseClock&) = delete;
  PhaseClock& operator=(const PhaseClock&) = delete;
  ~PhaseClock() {
#if defined(__CUDACC__)
    if (events_) {
      cudaEventDestroy(start_);
      cudaEventDestroy(stop_);
    }
#endif
  }
  double seconds[Count] = {};
  long calls[Count] = {};

 private:
#if defined(__CUDACC__)
  bool events_ = false;
  cudaEvent_t start_{}, stop_{};
#else
  std::chrono::steady_clock::time_point t0_{};
#endif
};

template <class Real>
struct StateArrays {
  DVec<Vec3p> pos;
  DVec<Vec3<Real>> vel;
  DVec<Real> rho, energy;
  DVec<Sym3<Real>> S;
  void resize(std::size_t n) { pos.resize(n); vel.resize(n); rho.resize(n); energy.resize(n); S.resize(n); }
};
template <class Real>
struct StateView {
  Vec3p* pos;
  Vec3<Real>* vel;
  Real* rho;
  Real* energy;
  Sym3<Real>* S;
};
template <class Real> StateView<Real> view(StateArrays<Real>& s) {
  return {raw(s.pos), raw(s.vel), raw(s.rho), raw(s.energy), raw(s.S)};
}

template <class Real>
class Solver final : public GpuStepper {
 public:
  static constexpr bool kFlush = sizeof(Real) < sizeof(double);  // float: subnormals to zero (launch.hpp)
  static constexpr int kHostScalars = 9;  // scalar fields copied back to the host (download)
  Solver(const Scene& scene, const char* build) : numerics_(scene.spec.numerics) {
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
    const StateView<Real> y = view(y0_);
    const MaterialParams<Real>* mats = raw(materials_);
    const Real* h = raw(h_);
    const std::int32_t* mat = raw(material_);
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

  // The device state into p, in the scene's order.
  void download(ParticleSet& p) {
    const std::int64_t n = n_;
    const StateView<Real> y = view(y0_);
    const std::int32_t* orig = raw(original_);
    Vec3d* pos = raw(out_vec_[0]);
    Vec3d* vel = raw(out_vec_[1]);
    Sym3d* S = raw(out_sym_);
    double* f = raw(out_scalar_);
    const Real* P = raw(pressure_);
    const Real* eps = raw(plastic_strain_);
    const Real* D = raw(damage_);
    const Real* T = raw(temperature_);
    const Real* B = raw(bulking_);
    const Real* H = raw(h_);
    const Real* W = raw(plastic_work_);
    // Scatter into the scene's order, widened to double.
    launch<kFlush>("copy_to_host", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      const std::int64_t o = orig[i];
      pos[o] = y.pos[i];
      vel[o] = cast3<double>(y.vel[i]);
      const Sym3<Real> s = y.S[i];
      S[o] = Sym3d{double(s.xx), double(s.yy), double(s.zz), double(s.xy), double(s.yz), double(s.zx)};
      f[o] = y.rho[i];
      f[n + o] = y.energy[i];
      f[2 * n + o] = P[i];
      f[3 * n + o] = eps[i];
      f[4 * n + o] = D[i];
      f[5 * n + o] = T[i];
      f[6 * n + o] = B[i];
      f[7 * n + o] = H[i];
      f[8 * n + o] = W[i];
    });
    thrust::copy(out_vec_[0].begin(), out_vec_[0].end(), p.pos.begin());
    thrust::copy(out_vec_[1].begin(), out_vec_[1].end(), p.vel.begin());
    thrust::copy(out_sym_.begin(), out_sym_.end(), p.dev_stress.begin());
    std::vector<double>* fields[kHostScalars] = {&p.rho,    &p.energy,      &p.pressure,         &p.plastic_strain,
                                                 &p.damage, &p.temperature, &p.bulking_pressure, &p.h,
                                                 &p.plastic_work};
    for (int k = 0; k < kHostScalars; ++k)
      thrust::copy(out_scalar_.begin() + k * n, out_scalar_.begin() + (k + 1) * n, fields[k]->begin());
  }

  void step(ParticleSet& p, double dt) override {
    if (!resident_) upload(p);
    // Pairs approach by at most dt vmax before the second evaluation, each particle moves at most
    // dt/2 |v| to the midpoint: keep the sort while displacement + dt vmax stays under half the skin.
    // With a variable smoothing length the support grows too: a pair the lists must hold is within
    // reach(h_max now) + 2 (displacement + dt vmax) < reach(h_max at the sort) + skin.
    const double vmax = max_speed();
    const double growth = variable_h_ && sorted_ ? search_reach(max_smoothing_length()) - reach_at_sort_ : 0.0;
    if (!sorted_ || !verlet_list_holds(max_displacement(), dt, vmax, growth, skin_))
      clock_.time(PhaseClock::Sort, [&] { sort_particles(); });

    evaluate(y0_, dt);
    clock_.time(PhaseClock::Advance, [&] { advance(y0_, 0.5 * dt, y_half_, false); });
    evaluate(y_half_, dt);
    clock_.time(PhaseClock::Advance, [&] { advance(y0_, dt, y1_, true); });
    clock_.time(PhaseClock::Check, [&] { check_state(dt); });
    stats_.contact_work = dt * contact_power_sum();
    std::swap(y0_, y1_);
    clock_.time(PhaseClock::Finish, [&] { finish(dt); });
    if (!defer_) download(p);
  }

 // The rest is public only because nvcc's extended (device) lambdas may not live in private members.
  template <class T> static void upload_converted(const std::vector<double>& src, DVec<T>& dst) {
    std::vector<T> tmp(src.begin(), src.end());
    dst = tmp;
  }

  void upload(const ParticleSet& p) {
    const std::size_t n = p.size();
    n_ = static_cast<std::int64_t>(n);
    y0_.resize(n); y_half_.resize(n); y1_.resize(n);
    y0_.pos = p.pos;
    std::vector<Vec3<Real>> vel(n);
    std::vector<Sym3<Real>> S(n);
    for (std::size_t i = 0; i < n; ++i) {
      vel[i] = cast3<Real>(p.vel[i]);
      const Sym3d& s = p.dev_stress[i];
      S[i] = Sym3<Real>{Real(s.xx), Real(s.yy), Real(s.zz), Real(s.xy), Real(s.yz), Real(s.zx)};
    }
    y0_.vel = vel;
    y0_.S = S;
    upload_converted(p.rho, y0_.rho);
    upload_converted(p.energy, y0_.energy);
    upload_converted(p.pressure, pressure_);
    upload_converted(p.plastic_strain, plastic_strain_);
    upload_converted(p.plastic_work, plastic_work_);
    upload_converted(p.damage, damage_);
    upload_converted(p.temperature, temperature_);
    upload_converted(p.bulking_pressure, bulking_);
    upload_converted(p.mass, mass_);
    upload_converted(p.h, h_);
    material_ = p.material;
    body_ = p.body;
    fixed_ = p.fixed;
    original_.resize(n);
    thrust::sequence(original_.begin(), original_.end());
    for (DVec<Real>* a : {&rate_drho_, &rate_de_, &strain_rate_, &contact_power_, &d_eps_p_, &d_plastic_work_,
                          &d_temperature_, &history_rate_, &scratch_real_})
      a->resize(n);
    rate_pos_.resize(n); rate_acc_.resize(n); rate_S_.resize(n); grad_v_.resize(n);
    fallback_.resize(n); neighbour_count_.resize(n); pos_at_sort_.resize(n);
    out_vec_[0].resize(n); out_vec_[1].resize(n); out_sym_.resize(n); out_scalar_.resize(kHostScalars * n);
    sorted_ = false;
    resident_ = true;
  }

  // Search radius without the skin: the kernel support or the contact distance at the largest h (m).
  double search_reach(double h_max) const {
    return impactsph::search_reach(static_cast<double>(kernel_support(h_max)), contact_reach_, contact_srad_, h_max);
  }

  // The contact power summed over the particles in the scene's order (W), so that the sum does not depend
  // on the order of the last sort either.
  double contact_power_sum() {
    if (contact_reach_ == 0 && contact_srad_ == 0) return 0.0;
    const Real* power = raw(contact_power_);
    const std::int32_t* orig = raw(original_);
    Real* out = raw(scratch_real_);
    launch<kFlush>("contact_power", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) { out[orig[i]] = power[i]; });
    return static_cast<double>(thrust::reduce(scratch_real_.begin(), scratch_real_.begin() + n_, Real(0)));
  }

  double max_smoothing_length() {
    return static_cast<double>(thrust::reduce(h_.begin(), h_.begin() + n_, Real(0), MaxOf{}));
  }

  double max_speed() {
    const StateView<Real> y = view(y0_);
    Real* out = raw(scratch_real_);
    launch<kFlush>("speed", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) { out[i] = norm(y.vel[i]); });
    return static_cast<double>(thrust::reduce(scratch_real_.begin(), scratch_real_.begin() + n_, Real(0), MaxOf{}));
  }

  double max_displacement() {
    const Vec3p* x = raw(y0_.pos);
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
  template <class T> void permute(DVec<T>& a, DVec<T>& tmp) {
    tmp.resize(a.size());
    thrust::gather(perm_.begin(), perm_.end(), a.begin(), tmp.begin());
    a.swap(tmp);
  }

  // Re-sort: the reals into the order of their cells (so that neighbours are near in memory), the mirror
  // ghosts of the symmetry planes, then all points by cell key with cell ranges.
  void sort_particles() {
    const std::int64_t n = n_;
    if (n == 0) return;
    ++sorts_;
    // Search radius: the reach at the largest h now, plus its skin (verlet_skin).
    reach_at_sort_ = search_reach(max_smoothing_length());
    skin_ = verlet_skin(reach_at_sort_);
    radius_ = reach_at_sort_ + skin_;
    const double cell = 0.5 * radius_;
    {
      // Key (cell, index in the scene): the order depends on the positions only, not on the order before,
      // so a run restarted from a checkpoint sorts exactly as the run that wrote it (copy_to_host).
      const Grid g = grid_of(y0_.pos, static_cast<std::size_t>(n), cell);
      real_keys_.resize(static_cast<std::size_t>(n));
      perm_.resize(static_cast<std::size_t>(n));
      std::uint64_t* key = raw(real_keys_);
      const Vec3p* x = raw(y0_.pos);
      const std::int32_t* orig = raw(original_);
      launch<kFlush>("real_keys", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
        key[i] = (static_cast<std::uint64_t>(g.key(x[i])) << 32) | static_cast<std::uint32_t>(orig[i]);
      });
      thrust::sequence(perm_.begin(), perm_.end());
      thrust::sort_by_key(real_keys_.begin(), real_keys_.end(), perm_.begin());
      DVec<Vec3p> t3p; DVec<Vec3<Real>> t3; DVec<Real> t1; DVec<Sym3<Real>> ts; DVec<std::int32_t> ti;
      DVec<std::uint8_t> tb;
      permute(y0_.pos, t3p); permute(y0_.vel, t3); permute(y0_.rho, t1); permute(y0_.energy, t1); permute(y0_.S, ts);
      permute(pressure_, t1); permute(plastic_strain_, t1); permute(plastic_work_, t1); permute(damage_, t1); permute(temperature_, t1);
      permute(bulking_, t1); permute(mass_, t1); permute(h_, t1); permute(material_, ti); permute(body_, ti); permute(fixed_, tb);
      permute(original_, ti);
    }
    // Ghosts: count the images of each real, scan, fill.
    const int planes = params_.plane_count;
    const int masks = 1 << planes;
    const StageParams<Real> prm = params_;
    const double margin = radius_;
    ghost_count_.resize(static_cast<std::size_t>(n) + 1);
    std::int32_t* count = raw(ghost_count_);
    const Vec3p* x = raw(y0_.pos);
    launch<kFlush>("ghost_count", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      std::int32_t c = 0;
      Vec3p sign, shift;
      for (int m = 1; m < masks; ++m)
        if (mirror_image(prm.planes, planes, m, x[i], margin, sign, shift)) ++c;
      count[i] = c;
    });
    thrust::exclusive_scan(ghost_count_.begin(), ghost_count_.begin() + n + 1, ghost_count_.begin());
    ghosts_ = ghost_count_[static_cast<std::size_t>(n)];
    ghost_source_.resize(static_cast<std::size_t>(ghosts_));
    ghost_sign_.resize(static_cast<std::size_t>(ghosts_));
    ghost_shift_.resize(static_cast<std::size_t>(ghosts_));
    ghost_mask_.resize(static_cast<std::size_t>(ghosts_));
    std::int32_t* src = raw(ghost_source_);
    std::int32_t* gmask = raw(ghost_mask_);
    Vec3p* gsign = raw(ghost_sign_);
    Vec3p* gshift = raw(ghost_shift_);
    launch<kFlush>("ghost_fill", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      std::int32_t k = count[i];
      Vec3p sign, shift;
      for (int m = 1; m < masks; ++m)
        if (mirror_image(prm.planes, planes, m, x[i], margin, sign, shift)) {
          src[k] = static_cast<std::int32_t>(i);
          gmask[k] = m;
          gsign[k] = sign;
          gshift[k] = shift;
          ++k;
        }
    });
    // All points, sorted by cell key.
    const std::int64_t total = n + ghosts_;
    points_.resize(static_cast<std::size_t>(total));
    Vec3p* pts = raw(points_);
    launch<kFlush>("points", total, [=] IMPACTSPH_LAMBDA(std::int64_t s) {
      if (s < n) {
        pts[s] = x[s];
      } else {
        const std::int64_t k = s - n;
        pts[s] = hadamard(gsign[k], x[src[k]]) + gshift[k];
      }
    });
    grid_ = grid_of(points_, static_cast<std::size_t>(total), cell);
    const Grid g = grid_;
    keys_.resize(static_cast<std::size_t>(total));
    order_.resize(static_cast<std::size_t>(total));
    slot_of_.resize(static_cast<std::size_t>(total));
    std::uint32_t* key = raw(keys_);
    launch<kFlush>("point_keys", total, [=] IMPACTSPH_LAMBDA(std::int64_t s) { key[s] = g.key(pts[s]); });
    thrust::sequence(order_.begin(), order_.end());
    thrust::stable_sort_by_key(keys_.begin(), keys_.end(), order_.begin());
    const std::int32_t* order = raw(order_);
    std::int32_t* slot = raw(slot_of_);
    launch<kFlush>("slot_of", total, [=] IMPACTSPH_LAMBDA(std::int64_t s) { slot[order[s]] = static_cast<std::int32_t>(s); });
    // cell_start[c] = the first sorted slot whose key is >= c, for c in [0, cells].
    const std::int64_t cells = g.dims[0] * g.dims[1] * g.dims[2];
    cell_start_.resize(static_cast<std::size_t>(cells) + 1);
    std::int32_t* start = raw(cell_start_);
    launch<kFlush>("cell_start", total + 1, [=] IMPACTSPH_LAMBDA(std::int64_t s) {
      const std::int64_t before = s == 0 ? -1 : static_cast<std::int64_t>(key[s - 1]);
      const std::int64_t here = s == total ? cells : static_cast<std::int64_t>(key[s]);
      for (std::int64_t c = before + 1; c <= here; ++c) start[c] = static_cast<std::int32_t>(s);
    });
    // Verlet list of each real: the sorted slots within the search radius, gathered over the 5x5x5 cells
    // around it (count, scan, fill: no atomics), each row then ordered by the identity of its points
    // (scene index of the real, and the planes of a ghost). A pass sums a particle's pairs in that order,
    // which does not depend on when the lists were built: a run restarted from a checkpoint (whose first
    // step sorts) continues with the same bits as the run that wrote it, whatever its sort schedule.
    identity_.resize(static_cast<std::size_t>(total));
    std::int64_t* identity = raw(identity_);
    const std::int32_t* orig = raw(original_);
    launch<kFlush>("point_identity", total, [=] IMPACTSPH_LAMBDA(std::int64_t s) {
      const std::int64_t pnt = order[s];
      identity[s] = pnt < n ? static_cast<std::int64_t>(orig[pnt]) << 8
                            : (static_cast<std::int64_t>(orig[src[pnt - n]]) << 8) | gmask[pnt - n];
    });
    sorted_points_.resize(static_cast<std::size_t>(total));
    Vec3p* sp = raw(sorted_points_);
    launch<kFlush>("sorted_points", total, [=] IMPACTSPH_LAMBDA(std::int64_t s) { sp[s] = pts[order[s]]; });
    list_offset_.resize(static_cast<std::size_t>(n) + 1);
    std::int64_t* off = raw(list_offset_);
    const double r2 = radius_ * radius_;
    const CellRange cr{sp, start, g};
    launch<kFlush>("list_count", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      const std::int64_t s = slot[i];
      const Vec3p xs = sp[s];
      std::int64_t c = 0;
      cr.for_each_candidate(s, [&](std::int32_t j) {
        if (norm2(xs - sp[j]) < r2) ++c;
      });
      off[i] = c;
    });
    thrust::exclusive_scan(list_offset_.begin(), list_offset_.end(), list_offset_.begin());
    list_.resize(static_cast<std::size_t>(list_offset_[static_cast<std::size_t>(n)]));
    std::int32_t* list = raw(list_);
    launch<kFlush>("list_fill", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      const std::int64_t s = slot[i];
      const Vec3p xs = sp[s];
      const std::int64_t first = off[i];
      std::int64_t k = first;
      cr.for_each_candidate(s, [&](std::int32_t j) {
        if (norm2(xs - sp[j]) < r2) list[k++] = j;
      });
      for (std::int64_t a = first + 1; a < k; ++a) {  // insertion sort by identity: rows are short
        const std::int32_t j = list[a];
        const std::int64_t id = identity[j];
        std::int64_t b = a;
        for (; b > first && identity[list[b - 1]] > id; --b) list[b] = list[b - 1];
        list[b] = j;
      }
    });
    thrust::copy(y0_.pos.begin(), y0_.pos.end(), pos_at_sort_.begin());
    const std::size_t t = static_cast<std::size_t>(total);
    wx_.resize(t); wv_.resize(t); wrho_.resize(t); wp_.resize(t); wc_.resize(t); wm_.resize(t); wh_.resize(t);
    wvol_.resize(t); wA_.resize(t); wS_.resize(t); wmat_.resize(t); wbody_.resize(t); wdamage_.resize(t);
    wlinv_.resize(t); wgrad_rho_.resize(t); wav_.resize(t); wR_.resize(params_.art.on() ? t : 0);
    wgv_.resize(params_.visc.limited ? t : 0);
    wlet_go_.resize(t); wimage_walls_.resize(t);
    sorted_ = true;
    stats_.ghosts = static_cast<std::size_t>(ghosts_);
  }

  // Raw pointers to the work arrays (sorted slots, reals and ghosts), captured by the pass kernels.
  // The work arrays by sorted slot, as the stages (common/stages.hpp) read them.
  StagePoints<Real> points() {
    return {raw(wx_), raw(wv_), raw(wrho_), raw(wp_), raw(wc_), raw(wm_), raw(wh_), raw(wvol_), raw(wdamage_),
            raw(wav_), raw(wA_), raw(wS_), params_.art.on() ? raw(wR_) : nullptr, raw(wmat_), raw(wbody_),
            raw(wlet_go_), raw(wimage_walls_), raw(wlinv_), params_.visc.limited ? raw(wgv_) : nullptr,
            raw(wgrad_rho_), raw(contacts_), params_.body_count};
  }

  void evaluate(StateArrays<Real>& state, double dt_in) {
    if (params_.kernel == KernelKind::WendlandC2) evaluate_with<KernelKind::WendlandC2>(state, dt_in);
    else evaluate_with<KernelKind::CubicSpline>(state, dt_in);
  }

  // One evaluation of the rates with the kernel fixed at compile time, so the pair loops carry no select
  // between kernels. In the pair loops (IMPACTSPH_SIMD_SUMS, launch.hpp) the only values carried from one
  // neighbour to the next are sums, kept as arrays of Reals; penalty contact, rare and heavy, has a loop of
  // its own after the SPH pairs (its sums in the same list order as before).
  template <KernelKind K>
  void evaluate_with(StateArrays<Real>& state, double dt_in) {
    const std::int64_t n = n_, total = n_ + ghosts_;
    const StateView<Real> y = view(state);
    const StagePoints<Real> w = points();
    const FixedKernel<K> kernel{};
    const std::int64_t* list_offset = raw(list_offset_);  // Verlet list of real i: slots list[list_offset[i] ..
    const std::int32_t* list = raw(list_);                 // list_offset[i+1])
    const MaterialParams<Real>* mats = raw(materials_);
    const StageParams<Real> prm = params_;
    const Real dt = static_cast<Real>(dt_in);
    const std::int32_t* order = raw(order_);
    const std::int32_t* slot = raw(slot_of_);
    const std::int32_t* gsrc = raw(ghost_source_);
    const std::int32_t* gmask = raw(ghost_mask_);
    const Vec3p* gsign = raw(ghost_sign_);
    const Vec3p* gshift = raw(ghost_shift_);
    const Real* mass = raw(mass_);
    const Real* h = raw(h_);
    const Real* damage = raw(damage_);
    const Real* bulking = raw(bulking_);
    const std::int32_t* material = raw(material_);
    const std::int32_t* body = raw(body_);
    const std::uint8_t* fixed = raw(fixed_);

    // Work arrays in sorted order: reals from the state, ghosts as mirror images of their source
    // (gather_point, stages.hpp).
    clock_.begin();
    launch<kFlush>("gather", total, [=] IMPACTSPH_LAMBDA(std::int64_t s) {
      const std::int64_t pnt = order[s];
      const std::int64_t i = pnt < n ? pnt : gsrc[pnt - n];
      const std::int32_t mi = material[i];
      const GatheredPoint<Real> g = gather_point(mats[mi], y.rho[i], y.energy[i], bulking[i], damage[i], y.S[i]);
      Sym3<Real> S = g.S;
      Vec3p xs = y.pos[i];
      Vec3<Real> vs = y.vel[i];
      Real m = mass[i];
      const unsigned let_go = walls_let_go(prm.planes, prm.plane_count, S, g.P, vs);
      unsigned image_walls = 0;
      if (pnt >= n) {
        image_walls = static_cast<unsigned>(gmask[pnt - n]) & prm.wall_planes;
        if (image_walls & let_go) m = 0;  // its source let go of a wall it is mirrored through
        const Vec3p sg = gsign[pnt - n];
        xs = hadamard(sg, xs) + gshift[pnt - n];
        const Vec3<Real> sr = cast3<Real>(sg);
        vs = hadamard(sr, vs);
        S = mirror(S, sr);
      }
      const Real rho = y.rho[i];
      w.x[s] = xs; w.v[s] = vs; w.rho[s] = rho; w.p[s] = g.P; w.c[s] = g.c; w.m[s] = m; w.h[s] = h[i];
      w.mat[s] = mi; w.body[s] = body[i]; w.damage[s] = g.pair_damage;
      w.S[s] = S;
      w.let_go[s] = pnt < n ? let_go : 0u;
      w.image_walls[s] = image_walls;
      w.vol[s] = m / rho;
      w.A[s] = stress_over_rho2(S, g.P, rho);
      if (prm.art.on()) w.R[s] = artificial_stress(prm.art, w.A[s]);  // before any viscosity joins A
    });

    clock_.end(PhaseClock::Gather);

    // Pass 1 (stages.hpp): each real's gradients from its list, then the ghosts' mirrored from their sources.
    clock_.begin();
    Mat3<Real>* grad_v = raw(grad_v_);
    std::int32_t* fell = raw(fallback_);
    std::int32_t* ncount = raw(neighbour_count_);
    launch<kFlush>("pass1", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      const std::int64_t s = slot[i];
      const GradientRow<Real> row = gradient_row(w, mats, s);
      Real sum[kGradientSums] = {};
      std::int32_t count = 0;
      const std::int64_t k0 = list_offset[i], k1 = list_offset[i + 1];
      IMPACTSPH_SIMD_SUMS(count, sum[:kGradientSums])
      for (std::int64_t k = k0; k < k1; ++k) {
        GradientSums<Real> one = GradientSums<Real>::zero();
        if (add_gradient_neighbour(kernel, w, mats, row, list[k], one)) {
          ++count;
          add_flat(sum, one);
        }
      }
      const CorrectedGradients<Real> cg = finish_gradient_row(prm, w, s, unflatten_gradient_sums(sum));
      grad_v[i] = cg.grad_v;
      fell[i] = cg.fell_back ? 1 : 0;
      ncount[i] = count;
    });
    launch<kFlush>("ghost_pass1", ghosts_, [=] IMPACTSPH_LAMBDA(std::int64_t k) {
      mirror_gradient_row(prm, w, slot[n + k], slot[gsrc[k]], cast3<Real>(gsign[k]));
    });
    stats_.correction_fallbacks =
        static_cast<std::size_t>(thrust::reduce(fallback_.begin(), fallback_.begin() + n, std::int64_t(0)));
    clock_.end(PhaseClock::Pass1);
    stats_.mean_neighbours =
        n ? static_cast<double>(thrust::reduce(neighbour_count_.begin(), neighbour_count_.begin() + n, std::int64_t(0))) /
                static_cast<double>(n)
          : 0.0;

    // Pass 2 (stages.hpp): the SPH pairs in a loop whose only carried values are sums (IMPACTSPH_SIMD_SUMS,
    // launch.hpp), then penalty contact, rare and heavy, in a loop of its own (its sums in list order), then
    // the rates.
    clock_.begin();
    Vec3<Real>* rpos = raw(rate_pos_);
    Vec3<Real>* racc = raw(rate_acc_);
    Real* rdrho = raw(rate_drho_);
    Real* rde = raw(rate_de_);
    Sym3<Real>* rS = raw(rate_S_);
    Real* reps = raw(strain_rate_);
    Real* rcp = raw(contact_power_);
    launch<kFlush>("pass2", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      const std::int64_t s = slot[i];
      const RateRow<Real> row = rate_row(prm, w, mats, s);
      const std::int64_t k0 = list_offset[i], k1 = list_offset[i + 1];
      Real sum[5] = {};  // acceleration x, y, z; energy rate; delta-SPH diffusion
      IMPACTSPH_SIMD_SUMS(sum[:5])
      for (std::int64_t k = k0; k < k1; ++k) {
        Vec3<Real> acc{0, 0, 0};
        Real de = 0, diffusion = 0;
        if (add_rate_neighbour(kernel, prm, w, mats, row, list[k], acc, de, diffusion)) {
          sum[0] += acc.x;
          sum[1] += acc.y;
          sum[2] += acc.z;
          sum[3] += de;
          sum[4] += diffusion;
        }
      }
      Vec3<Real> contact{0, 0, 0};
      Real power = 0;
      if (w.in_penalty_contact(row.body))
        for (std::int64_t k = k0; k < k1; ++k) add_contact_neighbour(w, mats, row, list[k], dt, contact, power);
      const PointRates<Real> r = point_rates(prm, w, mats[row.mat], s, grad_v[i], Vec3<Real>{sum[0], sum[1], sum[2]},
                                             sum[3], sum[4], contact, power, fixed[i] != 0);
      rpos[i] = r.vel; racc[i] = r.acc; rdrho[i] = r.drho; rde[i] = r.de; rS[i] = r.dS; reps[i] = r.strain_rate;
      rcp[i] = r.contact_power;
    });
    clock_.end(PhaseClock::Pass2);
  }

  // y = y0 + dt f (advance_point, stages.hpp).
  void advance(StateArrays<Real>& from, double dt_in, StateArrays<Real>& to, bool record) {
    const StateView<Real> y0 = view(from), out = view(to);
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
    const Real* eps_p = raw(plastic_strain_);
    const Real* T = raw(temperature_);
    const Real* D = raw(damage_);
    const Real* bulking = raw(bulking_);
    const std::int32_t* material = raw(material_);
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

  // History variables of the final stage: plastic strain, heating, pressure, damage, bulking (F 4.7-4.9,
  // X eq 28), and the variable smoothing length (X eqs 9-10) from the velocity gradient of the last
  // evaluation.
  void finish(double dt_in) {
    const StateView<Real> y = view(y0_);
    const MaterialParams<Real>* mats = raw(materials_);
    const std::int32_t* material = raw(material_);
    Real* eps_p = raw(plastic_strain_);
    Real* work = raw(plastic_work_);
    Real* T = raw(temperature_);
    Real* D = raw(damage_);
    Real* P = raw(pressure_);
    Real* bulking = raw(bulking_);
    Real* h = raw(h_);
    const std::int32_t* body = raw(body_);
    const BodySmoothing<Real>* smoothing = raw(body_smoothing_);
    const Mat3<Real>* grad_v = raw(grad_v_);
    const Real dt = static_cast<Real>(dt_in);
    const Real* h_eps = raw(d_eps_p_);
    const Real* h_work = raw(d_plastic_work_);
    const Real* h_T = raw(d_temperature_);
    const Real* h_rate = raw(history_rate_);
    launch<kFlush>("finish_step", n_, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      finish_point(mats[material[i]], smoothing[body[i]], grad_v[i], dt, y.rho[i], y.energy[i], y.S[i], eps_p[i],
                   work[i], T[i], D[i], P[i], bulking[i], h[i], h_eps[i], h_work[i], h_T[i], h_rate[i]);
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
    const std::int32_t b = body_[i];
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
  bool variable_h_ = false;   // some body has a variable smoothing length
  double contact_reach_ = 0;  // largest penalty contact distance, m
  double contact_srad_ = 0;   // largest SRAD of a penalty contact (touching at srad h)
  double reach_at_sort_ = 0;  // search_reach at the last sort, m
  double skin_ = 0, radius_ = 0;  // m
  bool resident_ = false, sorted_ = false, defer_ = false;
  long sorts_ = 0;
  std::int64_t n_ = 0, ghosts_ = 0;

  // Real particles, in the order of the last sort (original_ maps to the scene's order).
  StateArrays<Real> y0_, y_half_, y1_;
  DVec<Real> pressure_, plastic_strain_, plastic_work_, damage_, temperature_, bulking_, mass_, h_;
  DVec<std::int32_t> material_, body_, original_;
  DVec<std::uint8_t> fixed_;
  DVec<Vec3p> pos_at_sort_;
  // Rates of an evaluation and the history of the final stage.
  DVec<Vec3<Real>> rate_pos_, rate_acc_;
  DVec<Real> rate_drho_, rate_de_, strain_rate_, contact_power_, d_eps_p_, d_plastic_work_, d_temperature_, history_rate_,
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
  Grid grid_{};
  // Work arrays over sorted slots.
  DVec<Vec3p> wx_;
  DVec<Vec3<Real>> wv_, wgrad_rho_;
  DVec<Real> wrho_, wp_, wc_, wm_, wh_, wvol_, wdamage_, wav_;
  DVec<Sym3<Real>> wA_, wS_, wR_;
  DVec<std::int32_t> wmat_, wbody_;
  DVec<unsigned> wlet_go_, wimage_walls_;
  DVec<Mat3<Real>> wlinv_, wgv_;
  // Copies back to the host, in the scene's order.
  DVec<Vec3d> out_vec_[2];
  DVec<Sym3d> out_sym_;
  DVec<double> out_scalar_;
  StepStats stats_;
  PhaseClock clock_;
};

inline std::unique_ptr<GpuStepper> make_solver_for(const Scene& scene, Precision precision, const char* build) {
  if (precision == Precision::Double) return std::make_unique<Solver<double>>(scene, build);
  return std::make_unique<Solver<float>>(scene, build);
}

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND
