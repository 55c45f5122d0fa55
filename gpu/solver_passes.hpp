// The gpu port's evaluation of the rates (in the backend's namespace: included at the end of
// gpu/solver_impl.hpp): the gather, pass 1 and pass 2 as launches over the stages of common/stages.hpp.
#pragma once
#include "gpu/solver_impl.hpp"

namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND {

// The pass 1 sums of a particle as plain Reals, the form IMPACTSPH_SIMD_SUMS reduces: L, L_damaged, G
// (row-major) and the density gradient.
constexpr int kGradientSums = 30;
template <class Real> IMPACTSPH_HD void add_flat(Real* sum, const GradientSums<Real>& g) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      sum[3 * r + c] += g.L.m[r][c];
      sum[9 + 3 * r + c] += g.damaged_L().m[r][c];
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
  g.apart = true;
  return g;
}

// The pass 2 pair sums of a particle: acceleration x, y, z (m/s^2); energy rate (J/kg/s); delta-SPH diffusion.
constexpr int kRateSums = 5;

// One evaluation of the rates with the kernel fixed at compile time, so the pair loops carry no select
// between kernels. In the pair loops (IMPACTSPH_SIMD_SUMS, launch.hpp) the only values carried from one
// neighbour to the next are sums, kept as arrays of Reals; penalty contact, rare and heavy, has a loop of
// its own after the SPH pairs (its sums in the same list order as before).
template <class Real>
template <KernelKind K>
void Solver<Real>::evaluate_with(const StateView<Real>& state, double dt_in) {
  gather(state);
  gradient_pass<K>();
  rate_pass<K>(dt_in);
}

// The work arrays of an evaluation at `state`, in sorted order: reals from the state, ghosts as mirror images
// of their source (gather_point, stages.hpp).
template <class Real>
void Solver<Real>::gather(const StateView<Real>& state) {
  const std::int64_t n = n_, total = n_ + ghosts_;
  const StateView<Real> y = state;
  const StagePoints<Real> w = points();
  const MaterialParams<Real>* mats = raw(materials_);
  const StageParams<Real> prm = params_;
  const std::int32_t* order = raw(order_);
  const std::int32_t* slot = raw(slot_of_);
  const std::int32_t* gsrc = raw(ghost_source_);
  const std::int32_t* gmask = raw(ghost_mask_);
  const Vec3p* gsign = raw(ghost_sign_);
  const Vec3p* gshift = raw(ghost_shift_);
  const Real* mass = raw(d_.mass);
  const Real* h = raw(d_.h);
  const Real* damage = raw(d_.damage);
  const Real* bulking = raw(d_.bulking_pressure);
  const std::int32_t* material = raw(d_.material);
  const std::int32_t* body = raw(d_.body);
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
      const MirroredPoint<Real> image = mirror_point(gsign[pnt - n], gshift[pnt - n], image_walls, let_go, xs, vs, S, m);
      xs = image.x; vs = image.v; S = image.S; m = image.m;
    }
    const Real rho = y.rho[i];
    w.x[s] = xs; w.v[s] = vs; w.rho[s] = rho; w.p[s] = g.P; w.c[s] = g.c; w.m[s] = m; w.h[s] = h[i];
    w.mat[s] = mi; w.body[s] = body[i]; w.damage[s] = g.pair_damage;
    w.S[s] = S;
    w.let_go[s] = pnt < n ? let_go : 0u;
    w.image_walls[s] = image_walls;
    w.vol[s] = m / rho;
    set_stress_terms(prm, w, s, rho);
  });
  clock_.end(PhaseClock::Gather);
}

// Pass 2's view of the deformed state (rho_n+1, e*, S_n+1, v*; the leapfrog, common/stages.hpp) after pass 1
// of the half state: each point's pressure, sound speed, stress at its damage and velocity (ghosts as
// mirror images of their source), and (S - P I)/rho^2 at the new density with the artificial stress and
// the bulk viscosity of pass 1's velocity gradient (a ghost's that of its source: isotropic). The density,
// volume and gradients of pass 1 stay: pass 2's delta-SPH diffusion is that of the density field of pass 1.
template <class Real>
void Solver<Real>::restress(const StateView<Real>& state) {
  const std::int64_t n = n_, total = n_ + ghosts_;
  const StateView<Real> y = state;
  const StagePoints<Real> w = points();
  const MaterialParams<Real>* mats = raw(materials_);
  const StageParams<Real> prm = params_;
  const std::int32_t* order = raw(order_);
  const std::int32_t* gsrc = raw(ghost_source_);
  const std::int32_t* gmask = raw(ghost_mask_);
  const Vec3p* gsign = raw(ghost_sign_);
  const Vec3p* gshift = raw(ghost_shift_);
  const Real* damage = raw(d_.damage);
  const Real* bulking = raw(d_.bulking_pressure);
  const Real* h = raw(d_.h);
  const std::int32_t* material = raw(d_.material);
  const Mat3<Real>* grad_v = raw(grad_v_);
  clock_.begin();
  launch<kFlush>("restress", total, [=] IMPACTSPH_LAMBDA(std::int64_t s) {
    const std::int64_t pnt = order[s];
    const std::int64_t i = pnt < n ? pnt : gsrc[pnt - n];
    const GatheredPoint<Real> g = gather_point(mats[material[i]], y.rho[i], y.energy[i], bulking[i], damage[i], y.S[i]);
    Sym3<Real> S = g.S;
    Vec3<Real> v = y.vel[i];
    if (pnt >= n) {
      const unsigned image_walls = static_cast<unsigned>(gmask[pnt - n]) & prm.wall_planes;
      const MirroredPoint<Real> image =
          mirror_point(gsign[pnt - n], gshift[pnt - n], image_walls, 0u, y.pos[i], v, S, Real(0));
      v = image.v; S = image.S;
    }
    w.v[s] = v; w.p[s] = g.P; w.c[s] = g.c; w.S[s] = S;
    set_stress_terms(prm, w, s, y.rho[i]);
    if (prm.bulk_on) add_bulk_viscosity(prm.bulk, grad_v[i].trace(), y.rho[i], g.c, h[i], w.A[s]);
  });
  clock_.end(PhaseClock::Gather);
}

// Pass 1 (stages.hpp): each real's gradients from its list, then the ghosts' mirrored from their sources.
template <class Real>
template <KernelKind K>
void Solver<Real>::gradient_pass() {
  const std::int64_t n = n_;
  const StagePoints<Real> w = points();
  const FixedKernel<K> kernel{};
  const std::int64_t* list_offset = raw(list_offset_);  // Verlet list of real i: slots list[list_offset[i] ..
  const std::int32_t* list = raw(list_);                 // list_offset[i+1])
  const MaterialParams<Real>* mats = raw(materials_);
  const StageParams<Real> prm = params_;
  const std::int32_t* slot = raw(slot_of_);
  const std::int32_t* gsrc = raw(ghost_source_);
  const Vec3p* gsign = raw(ghost_sign_);
  clock_.begin();
  Mat3<Real>* grad_v = raw(grad_v_);
  std::int32_t* fell = raw(fallback_);
  std::int32_t* ncount = raw(neighbour_count_);
#if !defined(__CUDACC__)
  const bool clusters = takes_cluster_pairs();
  if (clusters) pass1_clusters(kernel, w);
#else
  constexpr bool clusters = false;
#endif
  if (!clusters) launch<kFlush>("pass1", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
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
}

// Pass 2 (stages.hpp): the SPH pairs in a loop whose only carried values are sums (IMPACTSPH_SIMD_SUMS,
// launch.hpp), then penalty contact, rare and heavy, in a loop of its own (its sums in list order), then
// the rates.
template <class Real>
template <KernelKind K>
void Solver<Real>::rate_pass(double dt_in) {
  const std::int64_t n = n_;
  const StagePoints<Real> w = points();
  const FixedKernel<K> kernel{};
  const std::int64_t* list_offset = raw(list_offset_);
  const std::int32_t* list = raw(list_);
  const MaterialParams<Real>* mats = raw(materials_);
  const StageParams<Real> prm = params_;
  const Real dt = static_cast<Real>(dt_in);
  const std::int32_t* slot = raw(slot_of_);
  const std::uint8_t* fixed = raw(d_.fixed);
  const Mat3<Real>* grad_v = raw(grad_v_);
#if !defined(__CUDACC__)
  const bool clusters = takes_cluster_pairs();
#endif
  clock_.begin();
  Vec3<Real>* rpos = raw(rate_pos_);
  Vec3<Real>* racc = raw(rate_acc_);
  Real* rdrho = raw(rate_drho_);
  Real* rdiff = raw(rate_drho_diffusion_);
  Real* rde = raw(rate_de_);
  Sym3<Real>* rS = raw(rate_S_);
  Real* reps = raw(strain_rate_);
  Real* rcp = raw(contact_power_);
  const Real* cluster_sums = nullptr;  // the SPH pairs' sums taken over cluster pairs, when they are
#if !defined(__CUDACC__)
  if (clusters) {
    pair_sums_.resize(static_cast<std::size_t>(n * kRateSums));
    pass2_clusters(kernel, w, pair_sums_.data());
    cluster_sums = pair_sums_.data();
  }
#endif
  launch<kFlush>("pass2", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
    const std::int64_t s = slot[i];
    const RateRow<Real> row = rate_row(prm, w, mats, s);
    const std::int64_t k0 = list_offset[i], k1 = list_offset[i + 1];
    Real sum[kRateSums] = {};
    if (cluster_sums)
      for (int q = 0; q < kRateSums; ++q) sum[q] = cluster_sums[i * kRateSums + q];
    else {
      IMPACTSPH_SIMD_SUMS(sum[:kRateSums])
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
    }
    Vec3<Real> contact{0, 0, 0};
    Real power = 0;
    if (w.in_penalty_contact(row.body))
      for (std::int64_t k = k0; k < k1; ++k) add_contact_neighbour(w, mats, row, list[k], dt, contact, power);
    const PointRates<Real> r = point_rates(prm, w, mats[row.mat], s, grad_v[i], Vec3<Real>{sum[0], sum[1], sum[2]},
                                           sum[3], sum[4], contact, power, fixed[i] != 0);
    rpos[i] = r.vel; racc[i] = r.acc; rdrho[i] = r.drho; rdiff[i] = r.drho_diffusion; rde[i] = r.de; rS[i] = r.dS;
    reps[i] = r.strain_rate;
    rcp[i] = r.contact_power;
  });
  clock_.end(PhaseClock::Pass2);
}

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND
