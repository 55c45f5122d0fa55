// The parts of the scene builder (common/scene.cpp) shared by its files (internal; common/scene.hpp is the
// interface): body_lattice.cpp fits each body's lattice to its shape, scene_checks.cpp checks the geometry
// (overlaps, symmetry planes, fixed regions, contacts), scene.cpp builds the Scene and describes its bodies.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "common/case_spec.hpp"
#include "common/particle_set.hpp"

namespace impactsph::scene_detail {

// Keeps an absurd spacing from exhausting memory before it is reported; also the int32 index range.
constexpr double kMaxParticles = 1e9;

struct Box3 {
  Vec3d lo, hi;
  bool intersects(const Box3& o) const {
    for (int a = 0; a < 3; ++a)
      if (hi[a] < o.lo[a] || o.hi[a] < lo[a]) return false;
    return true;
  }
  bool contains(const Vec3d& p) const {
    for (int a = 0; a < 3; ++a)
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
    return true;
  }
  Box3 grown(double d) const { return {lo - Vec3d{d, d, d}, hi + Vec3d{d, d, d}}; }
};

// Cells of one lattice axis that fill [lo, hi] exactly: the interval is cut at the symmetry planes strictly
// inside it, and each piece of length L holds n = max(1, round(L / dx)) cells of width L / n, so that the
// outermost cells end on the body's faces and the layers next to a plane lie half a cell from it.
// With a block ratio r > 1 (two_resolution_lattice) each cell also names its block of r neighbouring cells,
// counted up along the axis; a piece's cells are grouped from its symmetry plane outwards, so no block
// straddles a plane, and where a piece's count does not divide by r the cells left over (the last block,
// short) lie at the end away from the plane.
struct AxisCells {
  std::vector<double> centre, width;
  std::vector<long long> block;
};

// The particles of one body before clipping, each with its cell (widths along x, y, z), and how the
// lattice was fitted.
struct BodyLattice {
  std::vector<Vec3d> pts;
  std::vector<Vec3d> cell;  // m, widths of each particle's lattice cell along x, y, z
  std::vector<double> spacing;  // m, each particle's nominal spacing: dx, or ratio dx in a coarse region
  bool round_fitted = true; // false: no round-lattice spacing within 10 % of dx fits; dx kept
  // With a block ratio r > 1: each point's block of r^3 neighbouring cells, its indices along the lattice's
  // axes from the outermost loop inwards, so that sorting by it gives the order of the lattice at r dx.
  std::vector<std::array<long long, 3>> block;
};

// body_lattice.cpp
std::string point(const Vec3d& p);
std::string body_key(std::size_t k);
std::string body_name(const CaseSpec& spec, std::size_t k);
std::string body_label(const CaseSpec& spec, std::size_t k);
char axis_name(int a);
void cross_axes(int axis, int& u, int& v);
double section_radius(const BodySpec& b, double t);
double nose_volume(const BodySpec& b);
Box3 shape_bounds(const BodySpec& b);
bool strictly_inside(const BodySpec& b, const Vec3d& p, double eps);
std::string plane_key(const CaseSpec& spec, std::size_t s);
std::vector<double> cuts_inside(const CaseSpec& spec, int axis, double lo, double hi, double dx);
AxisCells fill_axis(double lo, double hi, const std::vector<double>& cuts, double dx, int block_ratio = 1);
bool in_round(double q, long long i, long long j, long long k, int dim);
double round_q(double radius, double s);
long long fold(long long i);
long long round_count(double radius, double s, int dim);
double fit_round_spacing(double radius, double dx, int dim);
BodyLattice mesh_lattice(const CaseSpec& spec, std::size_t k, double dx, const std::string& thin_hint, int block_ratio = 1);
BodyLattice lattice(const CaseSpec& spec, std::size_t k, double dx, int block_ratio = 1);
BodyLattice two_resolution_lattice(const CaseSpec& spec, std::size_t k, double dx);

// scene_checks.cpp
void check_overlaps(const CaseSpec& spec, const ParticleSet& ps, const std::vector<std::size_t>& first,
                    const std::vector<Box3>& bounds, double dx);
std::vector<int> clip_to_symmetry(const CaseSpec& spec, std::vector<BodyLattice>& lattices, double dx);
bool in_fixed_region(const FixedRegionSpec& r, const Vec3d& p, double eps);
void mark_fixed(const CaseSpec& spec, ParticleSet& ps, const std::vector<std::size_t>& first, double dx);
void resolve_contacts(CaseSpec& spec);

}  // namespace impactsph::scene_detail
