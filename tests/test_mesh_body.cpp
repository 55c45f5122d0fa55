// Bodies from surface meshes (shape = "mesh", common/mesh_solid.hpp): meshes written by the tests (a
// cube as ascii STL, a sphere as binary STL, a hemispherical-nosed projectile as OBJ), filled with the
// lattice, and every bad mesh named by its key and file.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "common/case_file.hpp"
#include "common/errors.hpp"
#include "common/mesh_solid.hpp"
#include "common/scene.hpp"
#include "tests/temp_dir_test.hpp"

using namespace impactsph;

namespace {

constexpr double kPi = 3.14159265358979323846;
using Triangle = std::array<Vec3d, 3>;

void write_stl_ascii(const std::filesystem::path& path, const std::vector<Triangle>& tris) {
  std::ofstream o(path);
  o.precision(17);
  o << "solid test\n";
  for (const Triangle& t : tris) {
    o << " facet normal 0 0 0\n  outer loop\n";
    for (const Vec3d& v : t) o << "   vertex " << v.x << " " << v.y << " " << v.z << "\n";
    o << "  endloop\n endfacet\n";
  }
  o << "endsolid test\n";
}

void write_stl_binary(const std::filesystem::path& path, const std::vector<Triangle>& tris) {
  std::ofstream o(path, std::ios::binary);
  const std::string header(80, ' ');
  o.write(header.data(), 80);
  const std::uint32_t n = static_cast<std::uint32_t>(tris.size());
  o.write(reinterpret_cast<const char*>(&n), 4);
  for (const Triangle& t : tris) {
    const float normal[3] = {0, 0, 0};
    o.write(reinterpret_cast<const char*>(normal), 12);
    for (const Vec3d& v : t) {
      const float xyz[3] = {float(v.x), float(v.y), float(v.z)};
      o.write(reinterpret_cast<const char*>(xyz), 12);
    }
    const std::uint16_t attributes = 0;
    o.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

// A box as 12 triangles, outward (or inward when `inward`).
std::vector<Triangle> box_triangles(Vec3d lo, Vec3d hi, bool inward = false) {
  const Vec3d v[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                      {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::vector<Triangle> out;
  for (const auto& t : f) out.push_back(inward ? Triangle{v[t[0]], v[t[2]], v[t[1]]} : Triangle{v[t[0]], v[t[1]], v[t[2]]});
  return out;
}

// An icosphere: the icosahedron subdivided `levels` times, its vertices on the sphere.
std::vector<Triangle> sphere_triangles(Vec3d c, double r, int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3d> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                          {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                       {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                                       {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (Vec3d& p : v) p = p * (1 / norm(p));
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      Vec3d m = (v[a] + v[b]) * 0.5;
      v.push_back(m * (1 / norm(m)));
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> g;
    for (const auto& tri : f) {
      const int a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), cc = midpoint(tri[2], tri[0]);
      g.push_back({tri[0], a, cc});
      g.push_back({tri[1], b, a});
      g.push_back({tri[2], cc, b});
      g.push_back({a, b, cc});
    }
    f = g;
  }
  std::vector<Triangle> out;
  for (const auto& tri : f) out.push_back({c + r * v[tri[0]], c + r * v[tri[1]], c + r * v[tri[2]]});
  return out;
}

// A projectile along z as OBJ: radius r, total length len, a hemispherical nose at z = 0 (its tip), the
// flat end at z = len; `segments` around, `rings` on the hemisphere.
void write_nosed_obj(const std::filesystem::path& path, double r, double len, int segments, int rings) {
  std::vector<std::pair<double, double>> profile;  // (z, radius) from the tip to the rear centre
  profile.emplace_back(0, 0);
  for (int i = 1; i <= rings; ++i) {
    const double a = 0.5 * kPi * i / rings;  // from the tip
    profile.emplace_back(r - r * std::cos(a), r * std::sin(a));
  }
  profile.emplace_back(len, r);
  profile.emplace_back(len, 0);
  std::ofstream o(path);
  o.precision(17);
  o << "# hemispherical-nosed projectile\n";
  // Vertex 1: the tip; then one ring per interior profile point; then the rear centre.
  o << "v 0 0 0\n";
  for (std::size_t p = 1; p + 1 < profile.size(); ++p)
    for (int s = 0; s < segments; ++s) {
      const double th = 2 * kPi * s / segments;
      o << "v " << profile[p].second * std::cos(th) << " " << profile[p].second * std::sin(th) << " " << profile[p].first << "\n";
    }
  o << "v 0 0 " << len << "\n";
  const int rings_n = static_cast<int>(profile.size()) - 2;
  auto ring = [&](int p, int s) { return 2 + (p - 1) * segments + (s % segments); };
  const int rear = 2 + rings_n * segments;
  for (int s = 0; s < segments; ++s) o << "f 1 " << ring(1, s + 1) << " " << ring(1, s) << "\n";
  for (int p = 1; p < rings_n; ++p)
    for (int s = 0; s < segments; ++s)
      o << "f " << ring(p, s) << " " << ring(p, s + 1) << " " << ring(p + 1, s + 1) << " " << ring(p + 1, s) << "\n";
  for (int s = 0; s < segments; ++s) o << "f " << rear << " " << ring(rings_n, s) << " " << ring(rings_n, s + 1) << "\n";
}

std::string mesh_case(const std::string& body_keys, const std::string& extra = "", const std::string& spacing = "1 mm") {
  return R"toml([case]
name = "mesh"
description = "a body from a mesh"

[materials.steel]
density = "7850 kg/m^3"
eos = { kind = "linear", bulk_modulus = "160 GPa" }
strength = { kind = "elastic", shear_modulus = "80 GPa" }

[[bodies]]
name = "solid"
material = "steel"
shape = "mesh"
)toml" + body_keys + "\n" + extra + R"toml(
[numerics]
spacing = ")toml" + spacing + R"toml("

[time]
end = "1 us"
output_interval = "1 us"
)toml";
}

class MeshBody : public TempDirTest {
 protected:
  MeshBody() : TempDirTest("impactsph_mesh") {}
  CaseSpec parse(const std::string& toml) { return parse_case_string(toml, (dir_ / "case.toml").string()); }
  CaseError error_of(const std::string& toml) {
    try {
      parse(toml);
      build_scene(parse(toml));
    } catch (const CaseError& e) {
      return e;
    }
    ADD_FAILURE() << "the case was accepted";
    return CaseError("", 0, "", "");
  }
};

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

struct Moments {
  double mass = 0;
  Vec3d centre{0, 0, 0};
};

Moments moments(const ParticleSet& p) {
  Moments m;
  for (std::size_t i = 0; i < p.size(); ++i) {
    m.mass += p.mass[i];
    m.centre += p.mass[i] * p.pos[i];
  }
  m.centre = m.centre * (1 / m.mass);
  return m;
}

}  // namespace

// A 10 x 8 x 6 mm cube in millimetres (ascii STL), moved by origin: exactly the box lattice of the same box.
TEST_F(MeshBody, CubeIsTheBoxItBounds) {
  write_stl_ascii(dir_ / "cube.stl", box_triangles({0, 0, 0}, {10, 8, 6}));
  const CaseSpec s = parse(mesh_case("file = \"cube.stl\"\nmesh_unit = \"mm\"\norigin = [\"1 mm\", \"2 mm\", \"3 mm\"]"));
  ASSERT_TRUE(s.bodies[0].mesh);
  EXPECT_NEAR(s.bodies[0].mesh->volume(), 480e-9, 1e-15);
  EXPECT_EQ(s.bodies[0].mesh->triangles(), 12u);
  for (const double dx : {1e-3, 0.7e-3}) {
    SCOPED_TRACE(dx);
    CaseSpec t = s;
    t.numerics.spacing = dx;
    const Scene scene = build_scene(t);
    CaseSpec as_box = t;
    as_box.bodies[0].shape = Shape::Box;
    as_box.bodies[0].box_min = {1e-3, 2e-3, 3e-3};
    as_box.bodies[0].box_max = {11e-3, 10e-3, 9e-3};
    const Scene box = build_scene(as_box);
    ASSERT_EQ(scene.particles.size(), box.particles.size());
    for (std::size_t i = 0; i < box.particles.size(); ++i) {
      EXPECT_LT(norm(scene.particles.pos[i] - box.particles.pos[i]), 1e-15);  // the mesh vertices round in mm
      EXPECT_NEAR(scene.particles.mass[i], box.particles.mass[i], 1e-12 * box.particles.mass[i]);
    }
    EXPECT_TRUE(scene.bodies[0].warnings.empty());
    EXPECT_EQ(scene.bodies[0].sizes.size(), 3u);
  }
}

// A sphere of radius 8 mm as binary STL (5120 triangles), 32 particles across: the mesh's volume is the
// ball's within 0.5 %, the lattice's cells inside it hold the mesh's volume within 1 % (the issue's
// figure), the masses give rho0 V_mesh and the centre is the sphere's. A quarter model (planes through the
// centre) mirrored back is the same body.
TEST_F(MeshBody, SphereHoldsItsVolume) {
  const double r = 8e-3;
  write_stl_binary(dir_ / "ball.stl", sphere_triangles({0, 0, 0}, r, 4));
  for (const bool quarter : {false, true}) {
    SCOPED_TRACE(quarter);
    const std::string planes = quarter ? "[[boundaries.symmetry]]\naxis = \"x\"\nposition = \"0 mm\"\n"
                                         "[[boundaries.symmetry]]\naxis = \"y\"\nposition = \"0 mm\"\n"
                                       : "";
    const CaseSpec s = parse(mesh_case("file = \"ball.stl\"\nmesh_unit = \"m\"", planes, "0.5 mm"));
    const double ball = 4.0 / 3.0 * kPi * r * r * r, v = s.bodies[0].mesh->volume();
    EXPECT_NEAR(v / ball, 1, 0.005);
    const Scene scene = build_scene(s);
    const BodyInfo& info = scene.bodies[0];
    EXPECT_NEAR(1 / info.mass_scale, 1, 0.01);
    EXPECT_NEAR(info.specified_mass, 7850 * v, 1e-9 * 7850 * v);
    EXPECT_NEAR(info.generated_mass, 7850 * v, 1e-6 * 7850 * v);
    if (!quarter) {
      const Moments m = moments(scene.particles);
      EXPECT_NEAR(norm(m.centre), 0, 1e-6 * r);
    }
    for (const Vec3d& q : scene.particles.pos) EXPECT_LT(norm(q), r);
    EXPECT_TRUE(info.warnings.empty()) << info.warnings.front();
  }
}

// The hemispherical-nosed projectile of the scene builder's own primitive (radius 10 mm, 80 mm long, nose
// at the base), as an OBJ of quads and triangles: mass and centre of mass agree with the primitive's
// within 0.5 % at 16 particles across.
TEST_F(MeshBody, NoseFromObjMatchesThePrimitive) {
  write_nosed_obj(dir_ / "nose.obj", 10, 80, 96, 24);
  const CaseSpec s = parse(mesh_case("file = \"nose.obj\"\nmesh_unit = \"mm\"", "", "1.25 mm"));
  const Scene mesh = build_scene(s);
  CaseSpec prim = s;
  BodySpec& b = prim.bodies[0];
  b.shape = Shape::Cylinder;
  b.mesh.reset();
  b.base = {0, 0, 0};
  b.axis = 2;
  b.radius = 10e-3;
  b.length = 80e-3;
  b.nose = Nose::Hemispherical;
  b.nose_at_base = true;
  b.nose_length = 10e-3;
  const Scene cyl = build_scene(prim);
  const Moments mm = moments(mesh.particles), mc = moments(cyl.particles);
  EXPECT_NEAR(mm.mass / mc.mass, 1, 0.005);
  EXPECT_NEAR(mm.centre.z / mc.centre.z, 1, 0.005);
  EXPECT_NEAR(mm.centre.x, 0, 1e-3 * 10e-3);
  EXPECT_NEAR(mm.centre.y, 0, 1e-3 * 10e-3);
}

// A cube written inside out is turned outwards; its volume is positive.
TEST_F(MeshBody, InwardSurfaceIsTurnedOutwards) {
  write_stl_ascii(dir_ / "inward.stl", box_triangles({0, 0, 0}, {4, 4, 4}, true));
  const CaseSpec s = parse(mesh_case("file = \"inward.stl\"\nmesh_unit = \"mm\""));
  EXPECT_NEAR(s.bodies[0].mesh->volume(), 64e-9, 1e-15);
  EXPECT_EQ(build_scene(s).particles.size(), 64u);
}

TEST_F(MeshBody, BadMeshesAreNamed) {
  write_stl_ascii(dir_ / "cube.stl", box_triangles({0, 0, 0}, {4, 4, 4}));
  std::vector<Triangle> open = box_triangles({0, 0, 0}, {4, 4, 4});
  open.pop_back();
  write_stl_ascii(dir_ / "open.stl", open);
  std::vector<Triangle> two = box_triangles({0, 0, 0}, {4, 4, 4});
  for (const Triangle& t : box_triangles({2, 2, 2}, {6, 6, 6})) two.push_back(t);
  write_stl_ascii(dir_ / "crossing.stl", two);
  std::ofstream(dir_ / "garbage.stl") << "this is not a mesh\n";
  std::ofstream(dir_ / "cube.step") << "ISO-10303-21;\n";

  struct Bad {
    std::string keys, key, hint;
  };
  const Bad bad[] = {
      {"file = \"missing.stl\"\nmesh_unit = \"mm\"", "bodies[0].file", "no such file"},
      {"file = \"cube.step\"\nmesh_unit = \"mm\"", "bodies[0].file", "give an .stl (ascii or binary), .obj, .off or .ply file"},
      {"file = \"garbage.stl\"\nmesh_unit = \"mm\"", "bodies[0].file", "cannot read a surface from"},
      {"file = \"open.stl\"\nmesh_unit = \"mm\"", "bodies[0].file", "is an open surface (it has border edges)"},
      {"file = \"crossing.stl\"\nmesh_unit = \"mm\"", "bodies[0].file", "intersects itself"},
      {"file = \"cube.stl\"", "bodies[0].mesh_unit", "a mesh file's coordinates carry no unit; give mesh_unit = one of \"m\", \"cm\", \"mm\", \"um\", \"in\""},
      {"file = \"cube.stl\"\nmesh_unit = \"furlong\"", "bodies[0].mesh_unit", "unknown mesh_unit \"furlong\""},
      {"mesh_unit = \"mm\"", "bodies[0].file", "missing"},
      {"file = \"cube.stl\"\nmesh_unit = \"mm\"\nradius = \"1 mm\"", "bodies[0].radius", "\"radius\" is a key of a cylinder or a sphere, not of a mesh"},
      {"file = \"cube.stl\"\nmesh_unit = \"mm\"\norigin = [\"1 mm\", \"2 m/s\", \"0 mm\"]", "bodies[0].origin[1]", "expected a length"},
      {"file = \"cube.stl\"\nmesh_unit = \"um\"", "bodies[0].file", "across along x at spacing 1 mm: a body needs at least two particles across"},
  };
  for (const Bad& b : bad) {
    SCOPED_TRACE(b.keys);
    const CaseError e = error_of(mesh_case(b.keys));
    EXPECT_EQ(e.key(), b.key) << e.what();
    EXPECT_TRUE(Contains(e.what(), b.hint));
    EXPECT_TRUE(Contains(e.what(), "case.toml"));
  }
  // A symmetry plane the mesh is not symmetric about: the cube spans x from 0 to 4 mm, the plane is x = 1 mm.
  const CaseError e = error_of(mesh_case("file = \"cube.stl\"\nmesh_unit = \"mm\"",
                                         "[[boundaries.symmetry]]\naxis = \"x\"\nposition = \"1 mm\"\n"));
  EXPECT_EQ(e.key(), "bodies[0].file") << e.what();
  EXPECT_TRUE(Contains(e.what(), "is not symmetric about the plane x = 1 mm (boundaries.symmetry[0])"));
  // Through its middle it is.
  EXPECT_NO_THROW(build_scene(parse(mesh_case("file = \"cube.stl\"\nmesh_unit = \"mm\"",
                                              "[[boundaries.symmetry]]\naxis = \"x\"\nposition = \"2 mm\"\n"))));
}
