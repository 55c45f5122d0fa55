// The host build's pass 1 over cluster pairs (issue 18; in the backend's namespace: included at the end of
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
//   * The fields pass 1 reads of a neighbour are packed by cluster lane at each evaluation (structure of
//     arrays), so a lane load is one contiguous load.
// The pair terms are those of the row path (gradient_row, the kernel, damaged_gradient_weight,
// accumulate_correction, add_gradient_terms: common/), summed per lane and then over the lanes in order;
// the order of the sums differs from the row path's, so the two agree to round-off (tests/test_pass_loops.cpp).
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
    keyed[static_cast<std::size_t>(s)] = {static_cast<std::int64_t>(rank[id >> 8] / kLanes) << 8 | (id & 0xff),
                                          static_cast<std::int32_t>(s)};
  });
  std::sort(keyed.begin(), keyed.end());
  cluster_of_slot_.resize(static_cast<std::size_t>(total));
  std::int64_t clusters = 0;
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    if (k == 0 || keyed[k].first != keyed[k - 1].first) ++clusters;
    cluster_of_slot_[static_cast<std::size_t>(keyed[k].second)] = static_cast<std::int32_t>(clusters - 1);
  }
  cluster_slot_.assign(static_cast<std::size_t>(clusters * kLanes), -1);
  for (std::int64_t s = 0; s < total; ++s)
    cluster_slot_[static_cast<std::size_t>(cluster_of_slot_[static_cast<std::size_t>(s)] * kLanes +
                                           rank[identity[s] >> 8] % kLanes)] = static_cast<std::int32_t>(s);
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
template <class Real>
void Solver<Real>::pack_cluster_points(const StagePoints<Real>& w) {
  const std::int64_t clusters = static_cast<std::int64_t>(cluster_slot_.size()) / kLanes;
  packed_.resize(static_cast<std::size_t>(clusters));
  const std::int32_t* cs = cluster_slot_.data();
  ClusterPoints<Real>* out = packed_.data();
  const MaterialParams<Real>* mats = raw(materials_);
  constexpr double kFar = 1e12;  // m: beyond every support, and r^2 still finite in float
  launch<kFlush>("pack_clusters", clusters, [=](std::int64_t c) {
    ClusterPoints<Real>& p = out[c];
    for (int l = 0; l < kLanes; ++l) {
      const std::int32_t s = cs[c * kLanes + l];
      p.slot[l] = s;
      if (s < 0) {
        p.x[l] = kFar; p.y[l] = kFar; p.z[l] = kFar;
        p.h[l] = 0; p.vol[l] = 0; p.vx[l] = 0; p.vy[l] = 0; p.vz[l] = 0; p.rho[l] = 0; p.damage[l] = 0;
        p.body[l] = 0; p.walls[l] = 0; p.face[l] = 0;
        continue;
      }
      p.x[l] = w.x[s].x; p.y[l] = w.x[s].y; p.z[l] = w.x[s].z;
      p.h[l] = w.h[s]; p.vol[l] = w.vol[s]; p.vx[l] = w.v[s].x; p.vy[l] = w.v[s].y; p.vz[l] = w.v[s].z;
      p.rho[l] = w.rho[s]; p.damage[l] = w.damage[s];
      p.body[l] = w.body[s];
      p.walls[l] = static_cast<std::int32_t>(w.image_walls[s]);
      p.face[l] = compressive_crack_face(mats, w.mat[s], w.damage[s]) ? 1 : 0;
    }
  });
}

// Pass 1 of every real over its clusters (add_gradient_neighbour's terms, kLanes neighbours at a time).
template <class Real>
template <class Kernel>
void Solver<Real>::pass1_clusters(const Kernel& kernel, const StagePoints<Real>& w) {
  using L = Lanes<Real>;
  using LD = Lanes<double>;
  using M = LaneMask<Real>;
  using LI = typename M::V;
  pack_cluster_points(w);
  const std::int64_t n = n_;
  const std::int32_t* slot = raw(slot_of_);
  const std::int64_t* off = raw(list_offset_);
  const std::int32_t* rc = row_cluster_.data();
  const std::int64_t* rc_end = row_cluster_end_.data();
  const ClusterPoints<Real>* packed = packed_.data();
  const std::int32_t* penalty_bits = penalty_bits_.data();
  const MaterialParams<Real>* mats = raw(materials_);
  const StageParams<Real> prm = params_;
  Mat3<Real>* grad_v = raw(grad_v_);
  std::int32_t* fell = raw(fallback_);
  std::int32_t* ncount = raw(neighbour_count_);
  launch<kFlush>("pass1_clusters", n, [=](std::int64_t i) {
    const std::int64_t s = slot[i];
    const GradientRow<Real> row = gradient_row(w, mats, s);
    const LD xi(row.x.x), yi(row.x.y), zi(row.x.z);
    const L hi(row.h), damage_i(row.damage), rho_i(row.rho);
    const Vec3<L> v_i{L(row.v.x), L(row.v.y), L(row.v.z)};
    const LI penalty_i = LI{} + static_cast<LaneInt<Real>>(penalty_bits[row.body]);
    const LI let_go_i = LI{} + static_cast<LaneInt<Real>>(row.let_go);
    const LI self = LI{} + static_cast<LaneInt<Real>>(s);
    const M face_i{LI{} + (row.face ? -1 : 0)};
    Mat3<L> L_sum = Mat3<L>::zero(), L_damaged = Mat3<L>::zero(), G = Mat3<L>::zero();
    Vec3<L> grad_rho{L(0), L(0), L(0)};
    LI count{};
    for (std::int64_t k = off[i]; k < rc_end[i]; ++k) {
      const ClusterPoints<Real>& p = packed[rc[k]];
      const Vec3<L> xij = lanes_cast<Real>(Vec3<LD>{xi - LD::load(p.x), yi - LD::load(p.y), zi - LD::load(p.z)});
      const L hij = L(Real(0.5)) * (hi + L::load(p.h));
      const L r = norm(xij);
      const M in = (r < kernel_support(hij)) & M{load_lane_ints<Real>(p.slot) != self};  // the list has no self pair
      count -= in.v;
      const M penalty{((penalty_i >> load_lane_ints<Real>(p.body)) & 1) != 0};
      const M behind{(load_lane_ints<Real>(p.walls) & let_go_i) != 0};
      const M shares = in & !(penalty | behind);
      const Vec3<L> gw = choose(shares, kernel.grad_factor(r, hij), L(0)) * xij;
      const M crack_face = face_i | M{load_lane_ints<Real>(p.face) != 0};
      const L vol_j = L::load(p.vol);
      const L vf = damaged_gradient_weight(vol_j, damage_i, L::load(p.damage), crack_face);
      accumulate_correction(L_sum, vol_j, gw, xij);
      accumulate_correction(L_damaged, vf, gw, xij);
      const Vec3<L> v_ji = Vec3<L>{L::load(p.vx), L::load(p.vy), L::load(p.vz)} - v_i;
      add_gradient_terms(G, grad_rho, vf, gw, v_ji, L::load(p.rho) - rho_i);
    }
    const GradientSums<Real> sums{lane_sum(L_sum), lane_sum(L_damaged), lane_sum(G), lane_sum(grad_rho), true};
    const CorrectedGradients<Real> cg = finish_gradient_row(prm, w, s, sums);
    grad_v[i] = cg.grad_v;
    fell[i] = cg.fell_back ? 1 : 0;
    std::int32_t c = 0;
    for (int l = 0; l < kLanes; ++l) c += static_cast<std::int32_t>(count[l]);
    ncount[i] = c;
  });
}

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND
