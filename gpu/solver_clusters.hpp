// The host build's pair passes over cluster pairs (issue 18; in the backend's namespace: included at the end of
// gpu/solver_impl.hpp, host build only). The CUDA kernels take each row's list entries one by one; on a CPU
// the pair terms run kLanes neighbours at a time in SIMD lanes (common/lanes.hpp), which needs each field of
// those neighbours in consecutive memory, not gathered from scattered slots (gpu/README.md).
//
//   * Clusters: every point belongs to the cluster of kLanes ranks that holds its rank, in lane rank %
//     kLanes. The rank is a particle's place in the Morton order of the scene the solver was made from
//     (ties by scene index), so a cluster is a compact group of neighbours for as long as a solid keeps its
//     topology. A ghost belongs to its source's cluster index and lane under its plane mask.
//   * Each row (a real particle) sums over the clusters of its list entries, in the order of their keys
//     (rank / kLanes, plane mask), every lane of each: lanes that are empty, beyond the support or not
//     sharing sums add exact zeros. A particle's sums therefore depend only on the identities of the
//     points near it, not on when the lists were built or on the order of the last sort, so a restart
//     continues with the same bits (tests/test_gpu.cpp).
//   * The fields each pass reads of a neighbour are packed by cluster lane at each evaluation (structure of
//     arrays), so a lane load is one contiguous load.
// The pair terms are those of the row path (pass 1: gradient_row, the kernel, damaged_gradient_weight,
// accumulate_correction, add_gradient_terms; pass 2: rate_row, artificial_stress_pair_factor,
// add_momentum_energy_pair, damaged_delta_sph_term: common/), summed per lane and then over the lanes in order;
// the order of the sums differs from the row path's, so the two agree to round-off (tests/test_pass_loops.cpp).
// Penalty contact, rare and heavy, stays with the rows (solver_passes.hpp).
#pragma once
#include "gpu/solver_impl.hpp"

namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND {

// Morton rank of each scene particle: 21 bits a coordinate on cells of the particle spacing (or, without one,
// the smallest smoothing length), so that the kLanes points of a cluster are a compact block of a lattice.
template <class Real>
void Solver<Real>::set_cluster_ranks(const Scene& scene) {
  const ParticleSet& p = scene.particles;
  const std::size_t n = p.size();
  cluster_rank_.assign(n, 0);
  if (n == 0) return;
  double h_min = p.h[0];
  Vec3d lo = p.pos[0];
  for (std::size_t i = 0; i < n; ++i) {
    h_min = std::min(h_min, p.h[i]);
    lo = Vec3d{std::min(lo.x, p.pos[i].x), std::min(lo.y, p.pos[i].y), std::min(lo.z, p.pos[i].z)};
  }
  auto spread = [](std::uint64_t v) {  // the 21 low bits of v to every third bit
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  };
  const double cell_size = scene.spec.numerics.spacing > 0 ? scene.spec.numerics.spacing : h_min;
  auto cell = [&](double x, double x0) {
    return static_cast<std::uint64_t>(std::min(std::max((x - x0) / cell_size, 0.0), double(0x1fffff)));
  };
  std::vector<std::pair<std::uint64_t, std::int32_t>> keyed(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d x = p.pos[i];
    keyed[i] = {spread(cell(x.x, lo.x)) | spread(cell(x.y, lo.y)) << 1 | spread(cell(x.z, lo.z)) << 2,
                static_cast<std::int32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t r = 0; r < n; ++r) cluster_rank_[static_cast<std::size_t>(keyed[r].second)] = static_cast<std::int32_t>(r);
  // Bodies in penalty contact share no sums: one bit per body for each body's row.
  const int bodies = params_.body_count;
  cluster_pairs_possible_ = bodies < 31;
  penalty_bits_.assign(static_cast<std::size_t>(bodies), 0);
  if (!cluster_pairs_possible_) return;
  const std::vector<PairContact<Real>> contacts(contacts_.begin(), contacts_.end());
  for (int a = 0; a < bodies; ++a)
    for (int b = 0; b < bodies; ++b)
      if (contacts[static_cast<std::size_t>(a * bodies + b)].penalty) penalty_bits_[static_cast<std::size_t>(a)] |= 1 << b;
}

// The clusters of the points of the last sort and each row's clusters (after its list is built).
template <class Real>
void Solver<Real>::build_clusters() {
  const std::int64_t n = n_, total = n_ + ghosts_;
  const std::int64_t* identity = raw(identity_);
  const std::int32_t* rank = cluster_rank_.data();
  std::vector<std::pair<std::int64_t, std::int32_t>> keyed(static_cast<std::size_t>(total));
  parallel_for(total, [&](std::int64_t s) {
    const std::int64_t id = identity[s];
    keyed[static_cast<std::size_t>(s)] = {static_cast<std::int64_t>(rank[id >> 8] / kLanes<Real>) << 8 | (id & 0xff),
                                          static_cast<std::int32_t>(s)};
  });
  std::sort(keyed.begin(), keyed.end());
  cluster_of_slot_.resize(static_cast<std::size_t>(total));
  std::int64_t clusters = 0;
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    if (k == 0 || keyed[k].first != keyed[k - 1].first) ++clusters;
    cluster_of_slot_[static_cast<std::size_t>(keyed[k].second)] = static_cast<std::int32_t>(clusters - 1);
  }
  cluster_slot_.assign(static_cast<std::size_t>(clusters * kLanes<Real>), -1);
  for (std::int64_t s = 0; s < total; ++s)
    cluster_slot_[static_cast<std::size_t>(cluster_of_slot_[static_cast<std::size_t>(s)] * kLanes<Real> +
                                           rank[identity[s] >> 8] % kLanes<Real>)] = static_cast<std::int32_t>(s);
  // Each row's clusters, in the order of their keys (= their index), where its list entries were.
  const std::int64_t* off = raw(list_offset_);
  const std::int32_t* list = raw(list_);
  const std::int32_t* cluster_of = cluster_of_slot_.data();
  row_cluster_.resize(list_.size());
  row_cluster_end_.resize(static_cast<std::size_t>(n));
  std::int32_t* rc = row_cluster_.data();
  std::int64_t* end = row_cluster_end_.data();
  parallel_for(n, [=](std::int64_t i) {
    std::int64_t k = off[i];
    for (std::int64_t e = off[i]; e < off[i + 1]; ++e) rc[k++] = cluster_of[list[e]];
    std::sort(rc + off[i], rc + k);
    end[i] = std::unique(rc + off[i], rc + k) - rc;
  });
}

// What pass 1 reads of the neighbours, by cluster lane; an empty lane sits far away with no volume.
// Fills one Packed per cluster: fill(p, l, s) for each lane l of each cluster, s its sorted point (-1: none).
template <class Real>
template <class Packed, class Fill>
void Solver<Real>::pack_by_lane(const char* name, std::vector<Packed>& packed, Fill fill) {
  const std::int64_t clusters = static_cast<std::int64_t>(cluster_slot_.size()) / kLanes<Real>;
  packed.resize(static_cast<std::size_t>(clusters));
  const std::int32_t* cs = cluster_slot_.data();
  Packed* out = packed.data();
  launch<kFlush>(name, clusters, [=](std::int64_t c) {
    for (int l = 0; l < kLanes<Real>; ++l) fill(out[c], l, cs[c * kLanes<Real> + l]);
  });
}

template <class Real>
void Solver<Real>::pack_cluster_points(const StagePoints<Real>& w) {
  const MaterialParams<Real>* mats = raw(materials_);
  constexpr double kFar = 1e12;  // m: beyond every support, and r^2 still finite in float
  pack_by_lane("pack_clusters", packed_, [=](ClusterPoints<Real>& p, int l, std::int32_t s) {
    p.slot[l] = s;
    if (s < 0) {
      p.x[l] = kFar; p.y[l] = kFar; p.z[l] = kFar;
      p.h[l] = 0; p.vol[l] = 0; p.vx[l] = 0; p.vy[l] = 0; p.vz[l] = 0; p.rho[l] = 0; p.damage[l] = 0;
      p.body[l] = 0; p.walls[l] = 0; p.face[l] = 0;
      return;
    }
    p.x[l] = w.x[s].x; p.y[l] = w.x[s].y; p.z[l] = w.x[s].z;
    p.h[l] = w.h[s]; p.vol[l] = w.vol[s]; p.vx[l] = w.v[s].x; p.vy[l] = w.v[s].y; p.vz[l] = w.v[s].z;
    p.rho[l] = w.rho[s]; p.damage[l] = w.damage[s];
    p.body[l] = w.body[s];
    p.walls[l] = static_cast<std::int32_t>(w.image_walls[s]);
    p.face[l] = compressive_crack_face(mats, w.mat[s], w.damage[s]) ? 1 : 0;
  });
}

namespace cluster_lanes {
template <class T> inline Mat3<Lanes<T>> load_mat(const T (*rows)[kLanes<T>]) {
  Mat3<Lanes<T>> a;
  for (int q = 0; q < 9; ++q) a.m[q / 3][q % 3] = Lanes<T>::load(rows[q]);
  return a;
}
template <class T> inline Mat3<Lanes<T>> load_sym(const T (*rows)[kLanes<T>]) {
  const Lanes<T> xx = Lanes<T>::load(rows[0]), yy = Lanes<T>::load(rows[1]), zz = Lanes<T>::load(rows[2]);
  const Lanes<T> xy = Lanes<T>::load(rows[3]), yz = Lanes<T>::load(rows[4]), zx = Lanes<T>::load(rows[5]);
  return Sym3<Lanes<T>>{xx, yy, zz, xy, yz, zx}.full();
}
template <class T> inline Mat3<Lanes<T>> broadcast(const Mat3<T>& a) {
  Mat3<Lanes<T>> r;
  for (int q = 0; q < 9; ++q) r.m[q / 3][q % 3] = Lanes<T>(a.m[q / 3][q % 3]);
  return r;
}
template <class T> inline Vec3<Lanes<T>> broadcast(const Vec3<T>& a) { return {Lanes<T>(a.x), Lanes<T>(a.y), Lanes<T>(a.z)}; }

// A row's point as the lane loops meet it, against the kLanes points of one cluster at a time.
template <class Real>
struct LanePair {
  Vec3<Lanes<Real>> xij;      // x_i - x_j, m
  Lanes<Real> hij, r;         // pair smoothing length and distance, m
  LaneMask<Real> in, shares;  // within the support (not the point itself); also sharing sums
  Vec3<Lanes<Real>> gw;       // grad_i W_ij where the pair shares sums, 0 elsewhere (1/m^4)
};
template <class Real>
struct LaneRow {
  using L = Lanes<Real>;
  using LD = Lanes<double, kLanes<Real>>;
  using M = LaneMask<Real>;
  using LI = typename M::V;
  LD x, y, z;
  L h;
  LI penalty, let_go, self;
  LaneRow(const Vec3p& xi, Real hi, std::int32_t penalty_bits, unsigned let_go_i, std::int64_t s)
      : x(xi.x), y(xi.y), z(xi.z), h(hi), penalty(LI{} + static_cast<LaneInt<Real>>(penalty_bits)),
        let_go(LI{} + static_cast<LaneInt<Real>>(let_go_i)), self(LI{} + static_cast<LaneInt<Real>>(s)) {}
  // The row's pairs with cluster p (pair_geometry, shares_sums of common/stages.hpp, lane by lane): within
  // the support and not the row's own point (the list has no self pair); sharing sums where also not in
  // penalty contact and not an image behind a wall the row let go of. Inlined: GCC otherwise calls it from
  // pass 2's loop and returns the lanes through memory (pass 2 in double 8.0 instead of 6.9 ms on the block).
  template <class Kernel>
  __attribute__((always_inline)) LanePair<Real> pair(const Kernel& kernel, const ClusterPoints<Real>& p) const {
    LanePair<Real> q;
    q.xij = lanes_cast<Real>(Vec3<LD>{x - LD::load(p.x), y - LD::load(p.y), z - LD::load(p.z)});
    q.hij = L(Real(0.5)) * (h + L::load(p.h));
    q.r = norm(q.xij);
    q.in = (q.r < kernel_support(q.hij)) & M{load_lane_ints<Real>(p.slot) != self};
    const M in_penalty{((penalty >> load_lane_ints<Real>(p.body)) & 1) != 0};
    const M behind{(load_lane_ints<Real>(p.walls) & let_go) != 0};
    q.shares = q.in & !(in_penalty | behind);
    q.gw = choose(q.shares, kernel.grad_factor(q.r, q.hij), L(0)) * q.xij;
    return q;
  }
};
}  // namespace cluster_lanes

template <class Real>
ClusterRows<Real> Solver<Real>::cluster_rows() {
  return {raw(slot_of_), raw(list_offset_), row_cluster_end_.data(), row_cluster_.data(), packed_.data(),
          penalty_bits_.data()};
}

// Pass 1 of every real over its clusters (add_gradient_neighbour's terms, kLanes neighbours at a time).
template <class Real>
template <class Kernel>
void Solver<Real>::pass1_clusters(const Kernel& kernel, const StagePoints<Real>& w) {
  using namespace cluster_lanes;
  using L = Lanes<Real>;
  using M = LaneMask<Real>;
  using LI = typename M::V;
  pack_cluster_points(w);
  const ClusterRows<Real> cr = cluster_rows();
  const MaterialParams<Real>* mats = raw(materials_);
  const StageParams<Real> prm = params_;
  Mat3<Real>* grad_v = raw(grad_v_);
  std::int32_t* fell = raw(fallback_);
  std::int32_t* ncount = raw(neighbour_count_);
  launch<kFlush>("pass1_clusters", n_, [=](std::int64_t i) {
    const std::int64_t s = cr.slot[i];
    const GradientRow<Real> row = gradient_row(w, mats, s);
    const LaneRow<Real> lane_row(row.x, row.h, cr.penalty_bits[row.body], row.let_go, s);
    const L damage_i(row.damage), rho_i(row.rho);
    const Vec3<L> v_i = broadcast(row.v);
    const M face_i = M::every(row.face);
    Mat3<L> L_sum = Mat3<L>::zero(), L_damaged = Mat3<L>::zero(), G = Mat3<L>::zero();
    Vec3<L> grad_rho{L(0), L(0), L(0)};
    LI count{};
    for (std::int64_t k = cr.first[i]; k < cr.end[i]; ++k) {
      const ClusterPoints<Real>& p = cr.packed[cr.cluster[k]];
      const LanePair<Real> q = lane_row.pair(kernel, p);
      count -= q.in.v;
      const M crack_face = face_i | M{load_lane_ints<Real>(p.face) != 0};
      const L vol_j = L::load(p.vol);
      const L vf = damaged_gradient_weight(vol_j, damage_i, L::load(p.damage), crack_face);
      accumulate_correction(L_sum, vol_j, q.gw, q.xij);
      accumulate_correction(L_damaged, vf, q.gw, q.xij);
      const Vec3<L> v_ji = Vec3<L>{L::load(p.vx), L::load(p.vy), L::load(p.vz)} - v_i;
      add_gradient_terms(G, grad_rho, vf, q.gw, v_ji, L::load(p.rho) - rho_i);
    }
    const GradientSums<Real> sums{lane_sum(L_sum), lane_sum(L_damaged), lane_sum(G), lane_sum(grad_rho), true};
    const CorrectedGradients<Real> cg = finish_gradient_row(prm, w, s, sums);
    grad_v[i] = cg.grad_v;
    fell[i] = cg.fell_back ? 1 : 0;
    std::int32_t c = 0;
    for (int l = 0; l < kLanes<Real>; ++l) c += static_cast<std::int32_t>(count[l]);
    ncount[i] = c;
  });
}

// What pass 2 reads of the neighbours beyond packed_, by cluster lane (after pass 1 and the ghosts' mirrored
// gradients); an empty lane has no material and zero fields.
template <class Real>
void Solver<Real>::pack_cluster_rates(const StagePoints<Real>& w) {
  const bool art = params_.art.on(), limited = params_.visc.limited;
  pack_by_lane("pack_cluster_rates", packed_rates_, [=](ClusterRates<Real>& p, int l, std::int32_t s) {
    auto put_sym = [l](Real (*rows)[kLanes<Real>], const Sym3<Real>& a) {
      const Real v[6] = {a.xx, a.yy, a.zz, a.xy, a.yz, a.zx};
      for (int q = 0; q < 6; ++q) rows[q][l] = v[q];
    };
    auto put_mat = [l](Real (*rows)[kLanes<Real>], const Mat3<Real>& a) {
      for (int q = 0; q < 9; ++q) rows[q][l] = a.m[q / 3][q % 3];
    };
    put_sym(p.A, s < 0 ? Sym3<Real>::zero() : w.A[s]);
    put_mat(p.linv, s < 0 ? Mat3<Real>::zero() : w.linv[s]);
    if (art) put_sym(p.R, s < 0 ? Sym3<Real>::zero() : w.R[s]);  // not read (nor written) where off
    if (limited) put_mat(p.grad_v, s < 0 ? Mat3<Real>::zero() : w.grad_v[s]);
    const Vec3<Real> gr = s < 0 ? Vec3<Real>{0, 0, 0} : w.grad_rho[s];
    p.grad_rho[0][l] = gr.x; p.grad_rho[1][l] = gr.y; p.grad_rho[2][l] = gr.z;
    const Vec3<Real> v = s < 0 ? Vec3<Real>{0, 0, 0} : w.v[s];
    p.v[0][l] = v.x; p.v[1][l] = v.y; p.v[2][l] = v.z;
    p.c[l] = s < 0 ? Real(0) : w.c[s];
    p.av[l] = s < 0 ? Real(0) : w.av[s];
    p.m[l] = s < 0 ? Real(0) : w.m[s];
    p.mat[l] = s < 0 ? -1 : w.mat[s];
  });
}

// Pass 2's SPH pair sums of every real over its clusters (add_rate_neighbour's terms, kLanes neighbours at a
// time), kRateSums a row into sums; penalty contact and the rates follow in the row loop (solver_passes.hpp).
template <class Real>
template <class Kernel>
void Solver<Real>::pass2_clusters(const Kernel& kernel, const StagePoints<Real>& w, Real* sums) {
  using namespace cluster_lanes;
  using L = Lanes<Real>;
  using M = LaneMask<Real>;
  using LI = typename M::V;
  pack_cluster_rates(w);
  const ClusterRows<Real> cr = cluster_rows();
  const ClusterRates<Real>* rates = packed_rates_.data();
  const MaterialParams<Real>* mats = raw(materials_);
  const StageParams<Real> prm = params_;
  const bool art = prm.art.on(), limited = prm.visc.limited;
  launch<kFlush>("pass2_clusters", n_, [=](std::int64_t i) {
    const std::int64_t s = cr.slot[i];
    const RateRow<Real> row = rate_row(prm, w, mats, s);
    const LaneRow<Real> lane_row(row.x, row.h, cr.penalty_bits[row.body], row.let_go, s);
    const L damage_i(row.side.damage), rho_i(row.side.rho);
    const Vec3<L> v_i = broadcast(row.v), grad_rho_i = broadcast(row.grad_rho);
    const PairSide<L> side_i{broadcast(row.side.A), broadcast(row.side.l_inverse), damage_i, L(row.side.av_factor),
                             L(row.side.sound_speed), rho_i, M::every(row.side.crack_face),
                             broadcast(row.side.R), broadcast(row.side.grad_v)};
    const LI mat_i = LI{} + static_cast<LaneInt<Real>>(row.mat);
    Vec3<L> acc{L(0), L(0), L(0)};
    L de(0), diffusion(0);
    for (std::int64_t k = cr.first[i]; k < cr.end[i]; ++k) {
      const ClusterPoints<Real>& p = cr.packed[cr.cluster[k]];
      const ClusterRates<Real>& q = rates[cr.cluster[k]];
      const LanePair<Real> pair = lane_row.pair(kernel, p);
      const Vec3<L>& xij = pair.xij;
      const L& hij = pair.hij;
      const M& shares = pair.shares;
      const Vec3<L>& gw = pair.gw;
      const L damage_j = L::load(p.damage), rho_j = L::load(p.rho);
      const PairSide<L> side_j{load_sym(q.A), load_mat(q.linv), damage_j, L::load(q.av), L::load(q.c), rho_j,
                               M{load_lane_ints<Real>(p.face) != 0}, art ? load_sym(q.R) : Mat3<L>::zero(),
                               limited ? load_mat(q.grad_v) : Mat3<L>::zero()};
      const L stress_factor = artificial_stress_pair_factor(prm.art, kernel.kind(), pair.r, hij);
      const Vec3<L> vij = v_i - Vec3<L>{L::load(q.v[0]), L::load(q.v[1]), L::load(q.v[2])};
      Vec3<L> acc_j{L(0), L(0), L(0)};
      L de_j(0);
      add_momentum_energy_pair(side_i, side_j, prm.visc, gw, xij, vij, hij, L::load(q.m), stress_factor, acc_j, de_j);
      acc += choose(shares, acc_j, Vec3<L>{L(0), L(0), L(0)});
      de += choose(shares, de_j, L(0));
      const Vec3<L> grad_rho_j{L::load(q.grad_rho[0]), L::load(q.grad_rho[1]), L::load(q.grad_rho[2])};
      const L d = damaged_delta_sph_term(damage_i, damage_j, L::load(p.vol), rho_i, rho_j, xij, grad_rho_i, grad_rho_j, gw);
      diffusion += choose(shares & M{load_lane_ints<Real>(q.mat) == mat_i}, d, L(0));
    }
    Real* out = sums + i * kRateSums;
    out[0] = lane_sum(acc.x); out[1] = lane_sum(acc.y); out[2] = lane_sum(acc.z);
    out[3] = lane_sum(de);
    out[4] = lane_sum(diffusion);
  });
}

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND
