// A case file's Taylor bar for the finite-element solver (fe2d.hpp): the checks that the case is one bar
// that the axisymmetric mesh can hold, each failing with the file, line and key, in the words of the case
// reader's errors (common/errors.hpp).
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "verification/fe2d/fe2d.hpp"

namespace impactsph::fe2d {
namespace {

const char* shape_word(Shape s) {
  switch (s) {
    case Shape::Box: return "box";
    case Shape::Cylinder: return "cylinder";
    case Shape::Sphere: return "sphere";
    case Shape::Mesh: return "mesh";
  }
  return "?";
}

const char* nose_word(Nose n) {
  switch (n) {
    case Nose::Flat: return "flat";
    case Nose::Hemispherical: return "hemispherical";
    case Nose::Conical: return "conical";
    case Nose::Ogival: return "ogival";
  }
  return "?";
}

std::string plane_key(const SymmetryPlaneSpec& p, std::size_t k) {
  return p.key.empty() ? "boundaries[" + std::to_string(k) + "]" : p.key;
}

std::string mm(double m) { return format_quantity(m, Dimension::Length); }

constexpr const char* kWhatIsValid =
    "the finite-element Taylor bar (impactsph taylor-fe) takes one body, a flat-ended cylinder moving along its "
    "axis, and a plane of symmetry or a wall normal to that axis at the bar's impact end";

}  // namespace

Bar bar_from_case(const CaseSpec& spec) {
  const std::string& file = spec.source_file;
  if (spec.bodies.size() != 1) {
    const int line = spec.bodies.size() > 1 ? spec.bodies[1].line : 0;
    throw CaseError(file, line, "bodies",
                    "the case has " + std::to_string(spec.bodies.size()) + " bodies; " + kWhatIsValid);
  }
  const BodySpec& b = spec.bodies[0];
  if (b.shape != Shape::Cylinder)
    throw CaseError(file, b.line, "bodies[0].shape",
                    std::string("is \"") + shape_word(b.shape) + "\"; " + kWhatIsValid + " (shape = \"cylinder\")");
  if (b.nose != Nose::Flat)
    throw CaseError(file, b.line, "bodies[0].nose",
                    std::string("is \"") + nose_word(b.nose) + "\"; the finite-element mesh holds a flat-ended cylinder only");
  if (b.material_index < 0 || b.material_index >= static_cast<int>(spec.materials.size()))
    throw CaseError(file, b.line, "bodies[0].material", "no material named \"" + b.material + "\"");
  const MaterialSpec& m = spec.materials[static_cast<std::size_t>(b.material_index)];
  if (m.params.damage.kind != DamageKind::None)
    throw CaseError(file, m.line, "materials." + m.name + ".damage",
                    std::string("is \"") + damage_key(m.params.damage.kind) +
                        "\"; the finite-element bar has no damage (valid: kind = \"none\", or no damage table)");
  if (!has_deviatoric_stress(m.params))
    throw CaseError(file, m.line, "materials." + m.name + ".strength",
                    std::string("is \"") + strength_key(m.params.strength.kind) +
                        "\", which has no shear modulus; the finite-element bar's hourglass control needs one "
                        "(a strength model with a shear modulus: elastic, perfectly-plastic, johnson-cook, ...)");
  if (!spec.fixed.empty())
    throw CaseError(file, spec.fixed[0].line, "boundaries.fixed[0]",
                    std::string("the finite-element bar has no fixed regions; ") + kWhatIsValid);

  // The velocity: along the axis, toward one end.
  const int axis = b.axis;
  const double v_axis = b.velocity[axis];
  const double v_norm = norm(b.velocity);
  if (!(v_norm > 0) || std::abs(std::abs(v_axis) - v_norm) > 1e-9 * v_norm)
    throw CaseError(file, b.line, "bodies[0].velocity",
                    std::string("must be along the bar's axis (") + static_cast<char>('x' + axis) +
                        ") and not zero; " + kWhatIsValid);
  const double impact_end = v_axis < 0 ? b.base[axis] : b.base[axis] + b.length;
  const double tol = 1e-6 * b.length;

  Bar bar;
  bar.case_name = spec.name;
  bar.case_file = file;
  bar.body = b.name;
  bar.material_name = m.name;
  bar.material = m.params;
  bar.radius = b.radius;
  bar.length = b.length;
  bar.speed = v_norm;
  bar.end_time = spec.time.end;
  bar.output_interval = spec.time.output_interval;

  bool found = false;
  for (std::size_t k = 0; k < spec.symmetry.size(); ++k) {
    const SymmetryPlaneSpec& p = spec.symmetry[k];
    if (p.axis == axis) {
      if (std::abs(p.position - impact_end) > tol)
        throw CaseError(file, p.line, plane_key(p, k) + ".position",
                        "is " + mm(p.position) + ", not at the bar's impact end (" + static_cast<char>('x' + axis) +
                            " = " + mm(impact_end) + "); " + kWhatIsValid);
      if (found)
        throw CaseError(file, p.line, plane_key(p, k), std::string("a second plane at the impact end; ") + kWhatIsValid);
      found = true;
      bar.plane_holds = !p.wall;
    } else if (std::abs(p.position - b.base[p.axis]) > tol) {
      throw CaseError(file, p.line, plane_key(p, k) + ".position",
                      "is " + mm(p.position) + ": a plane along the bar's axis must contain it (" +
                          static_cast<char>('x' + p.axis) + " = " + mm(b.base[p.axis]) +
                          "), or the bar is not axisymmetric");
    }
  }
  if (!found)
    throw CaseError(file, 0, "boundaries",
                    std::string("no plane of symmetry or wall normal to the bar's axis at its impact end (") +
                        static_cast<char>('x' + axis) + " = " + mm(impact_end) + "); " + kWhatIsValid);
  return bar;
}

}  // namespace impactsph::fe2d
