// The bodies and specs the scene tests build (test_scene*.cpp).
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/scene.hpp"

namespace impactsph::scene_test {

inline constexpr double kRho = 7850;

inline CaseSpec spec_with_spacing(double dx) {
  CaseSpec s;
  s.source_file = "scene.toml";
  s.name = "scene-test";
  MaterialSpec steel;
  steel.name = "steel";
  steel.params.eos.rho0 = kRho;
  steel.params.eos.k1 = 160e9;
  s.materials.push_back(steel);
  s.numerics.spacing = dx;
  s.time.end = 1e-5;
  s.time.output_interval = 1e-6;
  return s;
}

// A steel body of the given shape; the callers below set its geometry.
inline BodySpec steel_body(const std::string& name, Shape shape) {
  BodySpec b;
  b.name = name;
  b.material = "steel";
  b.material_index = 0;
  b.shape = shape;
  return b;
}

inline BodySpec box(const std::string& name, Vec3d lo, Vec3d hi) {
  BodySpec b = steel_body(name, Shape::Box);
  b.box_min = lo;
  b.box_max = hi;
  return b;
}

inline BodySpec cylinder(const std::string& name, Vec3d base, int axis, double radius, double length) {
  BodySpec b = steel_body(name, Shape::Cylinder);
  b.base = base;
  b.axis = axis;
  b.radius = radius;
  b.length = length;
  return b;
}

inline BodySpec sphere(const std::string& name, Vec3d center, double radius) {
  BodySpec b = steel_body(name, Shape::Sphere);
  b.center = center;
  b.radius = radius;
  return b;
}

inline ::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

inline ::testing::AssertionResult AnyContains(const std::vector<std::string>& texts, const std::string& part) {
  for (const std::string& t : texts)
    if (t.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  ::testing::AssertionResult r = ::testing::AssertionFailure();
  r << "no text contains \"" << part << "\" among " << texts.size() << ":";
  for (const std::string& t : texts) r << "\n  " << t;
  return r;
}

inline CaseError scene_error(const CaseSpec& s) {
  try {
    build_scene(s);
  } catch (const CaseError& e) {
    EXPECT_EQ(e.file(), "scene.toml");
    return e;
  }
  ADD_FAILURE() << "the scene was accepted";
  return CaseError("", 0, "", "");
}

inline void expect_near_vec(Vec3d a, Vec3d b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace impactsph::scene_test
