// ballistic-limit's reference: the points of CASE_DIR/reference.csv and the p = 2 Recht-Ipson form of the
// case's geometry (app/ballistic_search.hpp).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/ballistic_search.hpp"
#include "common/mesh_solid.hpp"
#include "common/scene.hpp"
#include "common/units.hpp"

namespace impactsph::ballistic {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

}  // namespace

Reference read_reference(const fs::path& file) {
  Reference ref;
  ref.file = file;
  std::ifstream in(file);
  if (!in) return ref;
  auto fail = [&](int line, const std::string& what) {
    throw std::runtime_error(file.string() + ":" + std::to_string(line) + ": " + what);
  };
  int line_no = 0, iv = -1, ir = -1, is = -1;
  bool header = false;
  std::string line;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> f = split_csv(t);
    if (!header) {
      for (int k = 0; k < static_cast<int>(f.size()); ++k) {
        if (f[k] == "v_impact_m_s") iv = k;
        if (f[k] == "v_residual_m_s") ir = k;
        if (f[k] == "source") is = k;
      }
      if (iv < 0 || ir < 0 || is < 0)
        fail(line_no, "the header must name the columns v_impact_m_s,v_residual_m_s,source (got '" + t + "')");
      header = true;
      continue;
    }
    if (static_cast<int>(f.size()) <= std::max({iv, ir, is}))
      fail(line_no, "expected 3 columns v_impact_m_s,v_residual_m_s,source, got '" + t + "'");
    auto number = [&](int k, const char* column) {
      char* end = nullptr;
      const double v = std::strtod(f[k].c_str(), &end);
      if (f[k].empty() || *end != '\0' || !std::isfinite(v) || v < 0)
        fail(line_no, std::string(column) + " '" + f[k] + "' is not a speed in m/s (a number >= 0)");
      return v;
    };
    ReferencePoint p;
    p.v_impact = number(iv, "v_impact_m_s");
    p.v_residual = number(ir, "v_residual_m_s");
    p.source = f[is].empty() ? "reference" : f[is];
    if (std::find(ref.sources.begin(), ref.sources.end(), p.source) == ref.sources.end()) ref.sources.push_back(p.source);
    ref.points.push_back(p);
  }
  return ref;
}

PlugForm plug_form(const CaseSpec& spec) {
  PlugForm f;
  const BodySpec& pb = spec.bodies[static_cast<std::size_t>(spec.observables.projectile_index)];
  const BodySpec& tb = spec.bodies[static_cast<std::size_t>(spec.observables.target_index)];
  const double speed = norm(pb.velocity);
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(pb.velocity[k]) > std::abs(pb.velocity[axis])) axis = k;
  if (!(speed > 0) || std::abs(pb.velocity[axis]) < 0.999 * speed) {
    f.why = "the impact is not along a coordinate axis";
    return f;
  }
  // Cross-section normal to the impact axis and extent along it; false when the body lies sideways.
  auto section = [&](const BodySpec& b, double& area, double& length) {
    if (b.shape == Shape::Sphere) {
      // The projectile's cross-section, and the length that gives its volume (4/3 r): the plug of a
      // sphere is the cylinder of its cross-section through the plate.
      area = kPi * b.radius * b.radius;
      length = 4.0 / 3.0 * b.radius;
      return true;
    }
    if (b.shape == Shape::Cylinder) {
      if (b.axis != axis) return false;
      area = kPi * b.radius * b.radius;
      length = shape_volume(b) / area;  // a nose counts by its volume
      return true;
    }
    if (b.shape == Shape::Mesh) {
      // The extent along the impact axis, and the mean cross-section that gives the mesh's volume.
      length = b.mesh->upper()[axis] - b.mesh->lower()[axis];
      area = shape_volume(b) / length;
      return true;
    }
    area = 1;
    for (int k = 0; k < 3; ++k)
      if (k != axis) area *= b.box_max[k] - b.box_min[k];
    length = b.box_max[axis] - b.box_min[axis];
    return true;
  };
  if (tb.shape == Shape::Sphere) {
    f.why = "the target is a sphere (no plate thickness)";
    return f;
  }
  double area_p, length_p, area_t, thickness;
  if (!section(pb, area_p, length_p) || !section(tb, area_t, thickness)) {
    f.why = "a cylinder's axis is not the impact direction";
    return f;
  }
  f.m_p = spec.materials[static_cast<std::size_t>(pb.material_index)].params.eos.rho0 * area_p * length_p;
  f.m_plug = spec.materials[static_cast<std::size_t>(tb.material_index)].params.eos.rho0 * area_p * thickness;
  f.ok = f.m_p > 0 && f.m_plug > 0;
  if (!f.ok) f.why = "a body has no mass";
  return f;
}

}  // namespace impactsph::ballistic
