#include "common/mesh_solid.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <filesystem>
#include <vector>

namespace impactsph {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;
}  // namespace

struct MeshSolid::Impl {
  Mesh mesh;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side;
};

MeshSolid::MeshSolid() : impl_(std::make_unique<Impl>()) {}
MeshSolid::~MeshSolid() = default;

std::shared_ptr<const MeshSolid> MeshSolid::read(const std::string& path, double unit, const Vec3d& origin) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw MeshError("no such file: " + path);
  const std::string ext = fs::path(path).extension().string();
  std::string lower_ext;
  for (const char c : ext) lower_ext += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower_ext != ".stl" && lower_ext != ".obj" && lower_ext != ".off" && lower_ext != ".ply")
    throw MeshError("\"" + path + "\" is not a mesh file this reads: give an .stl (ascii or binary), .obj, .off or .ply file");

  std::shared_ptr<MeshSolid> out(new MeshSolid());
  Mesh& m = out->impl_->mesh;
  // Reads the polygon soup, merges duplicate vertices, orients the faces consistently and builds the
  // mesh; false when the soup is not a 2-manifold surface (an edge shared by three faces, say).
  if (!PMP::IO::read_polygon_mesh(path, m) || m.number_of_faces() == 0)
    throw MeshError("cannot read a surface from " + path +
                    ": the file is not a valid " + lower_ext.substr(1) +
                    " mesh, or its faces do not form a 2-manifold surface (an edge shared by more than two faces)");
  if (!CGAL::is_triangle_mesh(m)) PMP::triangulate_faces(m);
  if (!CGAL::is_closed(m))
    throw MeshError(path + " is an open surface (it has border edges): a body needs a closed, watertight "
                           "surface; close the holes in the CAD tool or the mesher");
  if (PMP::does_self_intersect(m))
    throw MeshError(path + " intersects itself: a body needs a surface whose faces meet only at their edges");
  for (const auto v : m.vertices()) {
    const auto& p = m.point(v);
    m.point(v) = Kernel::Point_3(origin.x + unit * p.x(), origin.y + unit * p.y(), origin.z + unit * p.z());
  }
  if (!PMP::is_outward_oriented(m)) PMP::reverse_face_orientations(m);
  out->volume_ = PMP::volume(m);
  const CGAL::Bbox_3 box = PMP::bbox(m);
  out->lower_ = {box.xmin(), box.ymin(), box.zmin()};
  out->upper_ = {box.xmax(), box.ymax(), box.zmax()};
  out->triangles_ = m.number_of_faces();
  const double extent = std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  if (!(out->volume_ > 1e-9 * extent * extent * extent))
    throw MeshError(path + " encloses no volume (" + std::to_string(out->volume_) +
                    " m^3 after scaling): a body needs a solid, not a flat or degenerate surface");
  out->impl_->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(m);
  return out;
}

bool MeshSolid::inside(const Vec3d& p) const {
  return (*impl_->side)(Kernel::Point_3(p.x, p.y, p.z)) == CGAL::ON_BOUNDED_SIDE;
}

}  // namespace impactsph
