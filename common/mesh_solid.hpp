// A solid body given by a closed triangle surface (STL ascii or binary, OBJ, OFF, PLY), read, checked and
// tested point by point with CGAL (Polygon_mesh_processing for reading, repair, orientation, volume and
// self-intersection; Side_of_triangle_mesh, on an AABB tree, for the inside test). Host only; CGAL stays
// inside mesh_solid.cpp.
#pragma once
#include <memory>
#include <stdexcept>
#include <string>

#include "common/particle_set.hpp"

namespace impactsph {

// What is wrong with a mesh file, said so that the case file's key can carry it.
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class MeshSolid {
 public:
  // Reads `path`, scales its coordinates by `unit` (m per file unit) and moves its origin to `origin` (m).
  // Throws MeshError when the file cannot be read or its surface is not that of a solid: not a closed
  // 2-manifold, self-intersecting, or of zero volume. A closed surface oriented inwards is turned outwards.
  static std::shared_ptr<const MeshSolid> read(const std::string& path, double unit, const Vec3d& origin);
  ~MeshSolid();

  double volume() const { return volume_; }     // m^3
  const Vec3d& lower() const { return lower_; } // m, bounding box
  const Vec3d& upper() const { return upper_; }
  std::size_t triangles() const { return triangles_; }
  // True when p lies strictly inside the surface (a point on it is outside).
  bool inside(const Vec3d& p) const;

 private:
  MeshSolid();
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double volume_ = 0;
  Vec3d lower_{0, 0, 0}, upper_{0, 0, 0};
  std::size_t triangles_ = 0;
};

}  // namespace impactsph
