// The gpu port's sort (in the backend's namespace: included at the end of gpu/solver_impl.hpp): the reals
// into the order of their cells, the mirror ghosts, the cell ranges and the Verlet lists.
#pragma once
#include "gpu/solver_impl.hpp"

namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND {

// Re-sort: the reals into the order of their cells (so that neighbours are near in memory), the mirror
// ghosts of the symmetry planes, then all points by cell key with cell ranges.
template <class Real>
void Solver<Real>::sort_particles() {
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
    const Grid g = grid_of(d_.pos, static_cast<std::size_t>(n), cell);
    real_keys_.resize(static_cast<std::size_t>(n));
    perm_.resize(static_cast<std::size_t>(n));
    std::uint64_t* key = raw(real_keys_);
    const Vec3p* x = raw(d_.pos);
    const std::int32_t* orig = raw(original_);
    launch<kFlush>("real_keys", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
      key[i] = (static_cast<std::uint64_t>(g.key(x[i])) << 32) | static_cast<std::uint32_t>(orig[i]);
    });
    thrust::sequence(perm_.begin(), perm_.end());
    thrust::sort_by_key(real_keys_.begin(), real_keys_.end(), perm_.begin());
    for_each_field(d_, [&](const FieldInfo&, auto& a) { permute(a); });
    permute(original_);
  }
  // Ghosts: count the images of each real, scan, fill.
  const int planes = params_.plane_count;
  const int masks = 1 << planes;
  const StageParams<Real> prm = params_;
  const double margin = radius_;
  ghost_count_.resize(static_cast<std::size_t>(n) + 1);
  std::int32_t* count = raw(ghost_count_);
  const Vec3p* x = raw(d_.pos);
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
  // Two resolutions: a pair is held within the larger of its two points' radii (reach_per_pair).
  const bool per_pair = reach_per_pair(min_smoothing_length(), max_smoothing_length(), variable_h_);
  slot_radius_.resize(per_pair ? static_cast<std::size_t>(total) : 0);
  const double* sr = raw(slot_radius_);
  if (per_pair) {
    double* radius = raw(slot_radius_);
    const Real* h = raw(d_.h);
    const double contact = contact_reach_, srad = contact_srad_, skin = skin_;
    launch<kFlush>("slot_radius", total, [=] IMPACTSPH_LAMBDA(std::int64_t s) {
      const std::int64_t pnt = order[s];
      const double hp = static_cast<double>(h[pnt < n ? pnt : src[pnt - n]]);
      radius[s] = point_search_radius(hp, contact, srad, skin);
    });
  }
  auto held = [=] IMPACTSPH_LAMBDA(std::int64_t s, std::int32_t j, Vec3p xs) {
    if (!per_pair) return norm2(xs - sp[j]) < r2;
    const double r = sr[s] > sr[j] ? sr[s] : sr[j];
    return static_cast<double>(norm2(xs - sp[j])) < r * r;
  };
  launch<kFlush>("list_count", n, [=] IMPACTSPH_LAMBDA(std::int64_t i) {
    const std::int64_t s = slot[i];
    const Vec3p xs = sp[s];
    std::int64_t c = 0;
    cr.for_each_candidate(s, [&](std::int32_t j) {
      if (held(s, j, xs)) ++c;
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
      if (held(s, j, xs)) list[k++] = j;
    });
    for (std::int64_t a = first + 1; a < k; ++a) {  // insertion sort by identity: rows are short
      const std::int32_t j = list[a];
      const std::int64_t id = identity[j];
      std::int64_t b = a;
      for (; b > first && identity[list[b - 1]] > id; --b) list[b] = list[b - 1];
      list[b] = j;
    }
  });
  thrust::copy(d_.pos.begin(), d_.pos.end(), pos_at_sort_.begin());
  const std::size_t t = static_cast<std::size_t>(total);
  wx_.resize(t); wv_.resize(t); wrho_.resize(t); wp_.resize(t); wc_.resize(t); wm_.resize(t); wh_.resize(t);
  wvol_.resize(t); wA_.resize(t); wS_.resize(t); wmat_.resize(t); wbody_.resize(t); wdamage_.resize(t);
  wlinv_.resize(t); wgrad_rho_.resize(t); wav_.resize(t); wR_.resize(params_.art.on() ? t : 0);
  wgv_.resize(params_.visc.limited ? t : 0);
  wlet_go_.resize(t); wimage_walls_.resize(t);
#if !defined(__CUDACC__)
  if (takes_cluster_pairs()) build_clusters();
#endif
  sorted_ = true;
  stats_.ghosts = static_cast<std::size_t>(ghosts_);
}

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND
