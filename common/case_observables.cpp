#include "common/case_observables.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <numeric>
#include <limits>
#include <map>
#include <unordered_map>

#include "common/damage.hpp"

namespace impactsph {

namespace {

Vec3d unit(Vec3d v) {
  const double n = norm(v);
  return n > 0 ? (1.0 / n) * v : Vec3d{0, 0, 0};
}

// Union-find with path halving; the smaller index becomes the root so the result is order-independent.
struct DisjointSets {
  std::vector<std::size_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Connects the listed particles closer than `link` with a hash grid of cells of size `link`; with
// `link_of` (per particle, none above `link`), a pair closer than the larger of its two links.
DisjointSets connect(const ParticleSet& p, const std::vector<std::size_t>& members, double link,
                     const std::vector<double>* link_of = nullptr) {
  DisjointSets sets(members.size());
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
  auto key = [&](std::int64_t x, std::int64_t y, std::int64_t z) { return (x * 73856093) ^ (y * 19349663) ^ (z * 83492791); };
  auto coord = [&](double v) { return static_cast<std::int64_t>(std::floor(v / link)); };
  for (std::size_t k = 0; k < members.size(); ++k) {
    const Vec3d& x = p.pos[members[k]];
    cells[key(coord(x.x), coord(x.y), coord(x.z))].push_back(k);
  }
  const double link2 = link * link;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const Vec3d& x = p.pos[members[k]];
    const std::int64_t cx = coord(x.x), cy = coord(x.y), cz = coord(x.z);
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const auto it = cells.find(key(cx + dx, cy + dy, cz + dz));
          if (it == cells.end()) continue;
          for (std::size_t q : it->second) {
            if (q <= k) continue;
            const double d2 = norm2(p.pos[members[q]] - x);
            if (!link_of) {
              if (d2 < link2) sets.join(k, q);
            } else {
              const double l = std::max((*link_of)[members[k]], (*link_of)[members[q]]);
              if (d2 < l * l) sets.join(k, q);
            }
          }
        }
  }
  return sets;
}

}  // namespace

CaseObservables measure_observables(const Scene& scene, const ParticleSet& p) {
  const CaseSpec& spec = scene.spec;
  const ObservablesSpec& os = spec.observables;
  const double dx = spec.numerics.spacing;
  CaseObservables out;

  if (os.taylor_bar_index >= 0) {
    // The wall is the plane (a wall, or a symmetry plane) normal to the bar's axis; the bar rests on it, or
    // has left it (a wall that does not pull): the gap between the wall and the bar's face is not counted.
    const int body = os.taylor_bar_index;
    const BodySpec& b = spec.bodies[static_cast<std::size_t>(body)];
    const int axis = b.shape == Shape::Cylinder ? b.axis : 2;
    double wall = 0;
    for (const SymmetryPlaneSpec& plane : spec.symmetry)
      if (plane.axis == axis) wall = plane.position;
    // The bar's lattice: layers dz apart along its axis, cross-section spacing ds (scene.cpp).
    const Vec3d& cell = scene.bodies[static_cast<std::size_t>(body)].lattice_spacing;
    const double dz = cell[axis], ds = cell[(axis + 1) % 3];
    // The gap: how far the nearest centre lies beyond half a layer from the wall (0 on the wall).
    double near = 1e300;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.body[i] == body) near = std::min(near, std::abs(p.pos[i][axis] - wall));
    const double gap = std::max(0.0, near - 0.5 * dz);
    // The outermost centre radius and the volume of the layer within dz of the face.
    double far = 0, r_face = 0, layer_volume = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.body[i] != body) continue;
      const double along = std::abs(p.pos[i][axis] - wall) - gap;
      far = std::max(far, along);
      if (along < dz) {
        double r2 = 0;
        for (int a = 0; a < 3; ++a)
          if (a != axis) r2 += sqr(p.pos[i][a] - b.base[a]);
        r_face = std::max(r_face, std::sqrt(r2));
        layer_volume += p.mass[i] / p.rho[i];
      }
    }
    const double r_face0 = scene.bodies[static_cast<std::size_t>(body)].outer_centre_radius;  // as built, t = 0
    const double copies = symmetry_multiplicity(spec, body);  // the planes through the bar's axis
    // A particle stands for its cell: the body extends half a cell past the outermost centres.
    out.taylor_bar = true;
    out.final_length = far + 0.5 * dz;
    out.impact_face_diameter = 2 * (r_face + 0.5 * ds);
    out.impact_face_diameter_shifted = 2 * (r_face + b.radius - r_face0);
    out.impact_face_diameter_area = 2 * std::sqrt(copies * layer_volume / (dz * Constants<double>::pi));
  }

  Vec3d direction{0, 0, 0};
  if (os.projectile_index >= 0) {
    const int body = os.projectile_index;
    direction = unit(spec.bodies[static_cast<std::size_t>(body)].velocity);
    double m = 0, mv = 0, failed = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.body[i] != body) continue;
      m += p.mass[i];
      mv += p.mass[i] * dot(p.vel[i], direction);
      if (p.damage[i] >= kFailedDamage) failed += p.mass[i];
    }
    out.projectile = true;
    out.residual_velocity = m > 0 ? mv / m : 0.0;
    out.residual_mass = symmetry_multiplicity(spec, body) * (m - failed);
    out.eroded_mass = symmetry_multiplicity(spec, body) * failed;
  }

  if (os.target_index >= 0) {
    // The plug: a piece of the target cut out of the plate that leaves with the projectile. The target's
    // intact particles (damage < kFailedDamage: a failed particle carries no tension, so it holds nothing together)
    // are linked into pieces by distance (1.5 dx; in a two-resolution target 1.5 times each particle's own
    // spacing). The plate is the piece, or pieces, holding a clamped
    // particle (the heaviest piece when nothing is clamped); the plug is the heaviest other piece whose
    // mass-weighted velocity along the impact direction exceeds half the projectile's residual velocity,
    // together with the failed particles that travel with it (faster than that, within 1.5 dx of it: the
    // sheared rim it carries away). So a plate that dishes under the projectile, its centre moving with
    // it but joined to the clamped rim through intact material, has no plug. Perforated: the projectile
    // still moves on, a plug left with it, and its nose has passed the rear face of the plate (the
    // clamped particles mark where the plate is).
    const int body = os.target_index;
    const double v_cut = 0.5 * out.residual_velocity;
    std::vector<std::size_t> members;
    if (out.residual_velocity > os.settle_tolerance)
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.body[i] == body && p.damage[i] < kFailedDamage) members.push_back(i);
    // A two-resolution target links each particle at 1.5 times its own spacing (h / h_factor): its coarse
    // part is 2 dx apart.
    std::vector<double> link_of;
    double link = 1.5 * dx;
    if (scene.bodies[static_cast<std::size_t>(body)].coarse_particle_count > 0) {
      link_of.assign(p.size(), 1.5 * dx);
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.body[i] == body) link_of[i] = 1.5 * p.h[i] / spec.numerics.h_factor, link = std::max(link, link_of[i]);
    }
    const std::vector<double>* links = link_of.empty() ? nullptr : &link_of;
    DisjointSets sets = connect(p, members, link, links);
    struct Piece {
      double mass = 0, momentum = 0;
      bool clamped = false;
    };
    std::map<std::size_t, Piece> pieces;  // ordered by root: ties resolve the same way every run
    for (std::size_t k = 0; k < members.size(); ++k) {
      const std::size_t i = members[k];
      Piece& piece = pieces[sets.find(k)];
      piece.mass += p.mass[i];
      piece.momentum += p.mass[i] * dot(p.vel[i], direction);
      piece.clamped = piece.clamped || p.fixed[i] != 0;
    }
    bool any_clamped = false;
    std::size_t heaviest = 0;
    double heaviest_mass = -1;
    for (const auto& [root, piece] : pieces) {
      any_clamped = any_clamped || piece.clamped;
      if (piece.mass > heaviest_mass) {
        heaviest_mass = piece.mass;
        heaviest = root;
      }
    }
    double plug_mass = 0, plug_momentum = 0;
    std::size_t plug_root = 0;
    for (const auto& [root, piece] : pieces) {
      const bool plate = any_clamped ? piece.clamped : root == heaviest;
      if (!plate && piece.momentum > v_cut * piece.mass && piece.mass > plug_mass) {
        plug_mass = piece.mass;
        plug_momentum = piece.momentum;
        plug_root = root;
      }
    }
    if (plug_mass > 0) {
      std::vector<std::size_t> carried;  // the plug's particles, then the failed ones moving with it
      for (std::size_t k = 0; k < members.size(); ++k)
        if (sets.find(k) == plug_root) carried.push_back(members[k]);
      const std::size_t plug_count = carried.size();
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.body[i] == body && p.damage[i] >= kFailedDamage && dot(p.vel[i], direction) > v_cut) carried.push_back(i);
      DisjointSets with_rim = connect(p, carried, link, links);
      std::vector<char> joins_plug(carried.size(), 0);
      for (std::size_t k = 0; k < plug_count; ++k) joins_plug[with_rim.find(k)] = 1;
      for (std::size_t k = plug_count; k < carried.size(); ++k)
        if (joins_plug[with_rim.find(k)]) {
          plug_mass += p.mass[carried[k]];
          plug_momentum += p.mass[carried[k]] * dot(p.vel[carried[k]], direction);
        }
    }
    double plate_rear = -std::numeric_limits<double>::max(), projectile_nose = -std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.body[i] == body && p.fixed[i]) plate_rear = std::max(plate_rear, dot(p.pos[i], direction));
      if (p.body[i] == os.projectile_index) projectile_nose = std::max(projectile_nose, dot(p.pos[i], direction));
    }
    double target_mass = 0, target_failed = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.body[i] == body) {
        target_mass += p.mass[i];
        if (p.damage[i] >= kFailedDamage) target_failed += p.mass[i];
      }
    out.damage_fraction = target_mass > 0 ? target_failed / target_mass : 0.0;
    out.target = true;
    out.plug_mass = symmetry_multiplicity(spec, body) * plug_mass;
    out.plug_velocity = plug_mass > 0 ? plug_momentum / plug_mass : 0.0;
    out.perforated = out.residual_velocity > os.settle_tolerance && plug_mass > 0 &&
                     (plate_rear == -std::numeric_limits<double>::max() || projectile_nose > plate_rear + dx);
  }
  return out;
}

namespace {

// A projectile still moving (|v| above the tolerance) whose velocity, at the rate it drifted over the
// current window, would come down to the tolerance within kSettleHorizonWindows windows is on its way to
// a stop, not steady: near the ballistic limit one slowing 0.6 m/s per 20 us at 3.6 m/s passes the
// tolerance test and would be called a perforation. Not settled until it stops or the drift is slow
// against its speed.
constexpr double kSettleHorizonWindows = 10;

bool slowing_to_a_stop(const ObservablesSpec& spec, double span, double v, const RunClock& c) {
  const double speed_left = std::abs(v) - spec.settle_tolerance;  // m/s
  if (speed_left <= 0) return false;
  const double drift_rate = (c.settle_max - c.settle_min) / span;  // m/s per s over the window
  return drift_rate * kSettleHorizonWindows * spec.settle_window > speed_left;
}

}  // namespace

void track_settling(const ObservablesSpec& spec, double time, double v, RunClock& c) {
  if (c.settle_observations++ == 0) {
    c.settle_initial_velocity = v;
    return;
  }
  if (c.settle_window_start < 0) {
    if (std::abs(v - c.settle_initial_velocity) <= spec.settle_tolerance) return;
    c.settle_window_start = time;
    c.settle_min = c.settle_max = v;
    return;
  }
  c.settle_min = std::min(c.settle_min, v);
  c.settle_max = std::max(c.settle_max, v);
  if (c.settle_max - c.settle_min > spec.settle_tolerance) {
    c.settle_window_start = time;
    c.settle_min = c.settle_max = v;
    c.settled_time = -1;
    return;
  }
  const double span = time - c.settle_window_start;
  if (c.settled_time < 0 && span >= spec.settle_window && !slowing_to_a_stop(spec, span, v, c))
    c.settled_time = c.settle_window_start;
}

void track_held(const ObservablesSpec& spec, double time, const CaseObservables& o, RunClock& c) {
  const bool resting_or_back = o.projectile && o.target && !o.perforated && o.residual_velocity <= spec.settle_tolerance;
  if (!resting_or_back || (c.held_window_start >= 0 && o.damage_fraction != c.held_failed_fraction)) {
    c.held_window_start = -1;
    c.held_time = -1;
  }
  if (!resting_or_back) return;
  if (c.held_window_start < 0) {
    c.held_window_start = time;
    c.held_failed_fraction = o.damage_fraction;
    return;
  }
  if (c.held_time < 0 && time - c.held_window_start >= spec.settle_window) c.held_time = c.held_window_start;
}

double verdict_time(const RunClock& c) {
  if (c.settled_time >= 0 && c.held_time >= 0) return std::min(c.settled_time, c.held_time);
  return c.settled_time >= 0 ? c.settled_time : c.held_time;
}

bool impact_is_over(const ObservablesSpec& spec, const CaseObservables& o) {
  return !o.target || o.perforated || o.residual_velocity <= spec.settle_tolerance;
}

std::vector<ObservableRow> observable_rows(const CaseObservables& o) {
  using K = ObservableRow::Kind;
  std::vector<ObservableRow> rows;
  if (o.taylor_bar) {
    rows.push_back({"final_length", o.final_length, "mm", 1e3, 4, K::Number, "m"});
    rows.push_back({"impact_face_diameter", o.impact_face_diameter, "mm", 1e3, 4, K::Number, "m"});
    rows.push_back({"impact_face_diameter_shifted", o.impact_face_diameter_shifted, "mm", 1e3, 4, K::Number, "m"});
    rows.push_back({"impact_face_diameter_area", o.impact_face_diameter_area, "mm", 1e3, 4, K::Number, "m"});
  }
  if (o.projectile) {
    rows.push_back({"residual_velocity", o.residual_velocity, "m/s", 1, 2, K::Number, "m/s"});
    rows.push_back({"residual_mass", o.residual_mass, "g", 1e3, 2, K::Number, "kg"});
    rows.push_back({"eroded_mass", o.eroded_mass, "g", 1e3, 2, K::Number, "kg"});
    rows.push_back({"settled_time", o.settled_time, "us", 1e6, 1, K::TimeOrNever, "s"});
  }
  if (o.target) {
    rows.push_back({"plug_velocity", o.plug_velocity, "m/s", 1, 2, K::Number, "m/s"});
    rows.push_back({"plug_mass", o.plug_mass, "g", 1e3, 2, K::Number, "kg"});
    rows.push_back({"perforated", o.perforated ? 1.0 : 0.0, "", 1, 0, K::Flag, ""});
    rows.push_back({"damage_fraction", o.damage_fraction, "", 1, 4, K::Number, ""});
  }
  return rows;
}

std::string format_observable(const ObservableRow& row) {
  std::string text = row.name + ": ";
  if (row.kind == ObservableRow::Kind::Flag) return text + (row.value != 0 ? "yes" : "no");
  if (row.kind == ObservableRow::Kind::TimeOrNever && row.value < 0) return text + "not settled by the end time";
  char number[64];
  std::snprintf(number, sizeof number, "%.*f", row.digits, row.value * row.scale);
  text += number;
  if (*row.unit) text += std::string(" ") + row.unit;
  return text;
}

}  // namespace impactsph
