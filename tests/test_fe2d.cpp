// The axisymmetric finite-element Taylor bar (verification/fe2d): its element against closed forms, its
// material update against common/'s functions, the case checks with their messages, and a short run's
// mass and determinism. The elastic bar and the benchmarks are in verification/analytic_fe2d.cpp and
// validation_fe2d.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/case_file.hpp"
#include "common/errors.hpp"
#include "verification/fe2d/constitutive.hpp"
#include "verification/fe2d/element.hpp"
#include "verification/fe2d/fe2d.hpp"

namespace impactsph::fe2d {
namespace {

constexpr double kPi = Constants<double>::pi;

// A distorted quadrilateral away from the axis and one with an edge on it (m), counter-clockwise.
const double kR[4] = {1.0e-3, 2.1e-3, 2.3e-3, 0.9e-3}, kZ[4] = {0.5e-3, 0.4e-3, 1.6e-3, 1.3e-3};
const double kAxisR[4] = {0, 1.0e-3, 1.1e-3, 0}, kAxisZ[4] = {0, 0.1e-3, 1.0e-3, 0.9e-3};

TEST(Fe2dElement, RingVolumeAndLumpedMassesOfARectangle) {
  const double r[4] = {1e-3, 3e-3, 3e-3, 1e-3}, z[4] = {0, 0, 2e-3, 2e-3};
  const QuadGeometry g = quad_geometry(r, z);
  const double volume = kPi * (9e-6 - 1e-6) * 2e-3;  // pi (r1^2 - r0^2) h
  EXPECT_NEAR(g.volume / volume, 1.0, 1e-14);
  EXPECT_NEAR(g.area / 4e-6, 1.0, 1e-14);
  EXPECT_NEAR(g.length / (4e-6 / std::hypot(2e-3, 2e-3)), 1.0, 1e-14);
  double m[4];
  lumped_masses(r, z, 8000, m);
  EXPECT_NEAR((m[0] + m[1] + m[2] + m[3]) / (8000 * volume), 1.0, 1e-14);
  // rho 2 pi int N_I r dA: the outer nodes carry more, (2 r1 + r0) against (2 r0 + r1).
  EXPECT_NEAR(m[1] / m[0], 7.0 / 5.0, 1e-13);
  EXPECT_DOUBLE_EQ(m[0], m[3]);
}

// u = a r and w = c r + d z + e are in the element's space: its velocity gradient is exact, the hoop rate
// u/r = a included, on any quadrilateral.
TEST(Fe2dElement, LinearVelocityFieldsGiveTheExactGradient) {
  const double a = 310, c = -120, d = 870, e = -4;
  for (const auto* quad : {&kR, &kAxisR}) {
    const double* r = *quad;
    const double* z = quad == &kR ? kZ : kAxisZ;
    const QuadGeometry g = quad_geometry(r, z);
    double l_rr = 0, l_rz = 0, l_zr = 0, l_zz = 0, hoop = 0;
    for (int k = 0; k < 4; ++k) {
      const double u = a * r[k], w = c * r[k] + d * z[k] + e;
      l_rr += g.b_r[k] * u, l_rz += g.b_z[k] * u, l_zr += g.b_r[k] * w, l_zz += g.b_z[k] * w, hoop += g.hoop[k] * u;
    }
    EXPECT_NEAR(l_rr, a, 1e-10);
    EXPECT_NEAR(l_rz, 0, 1e-10);
    EXPECT_NEAR(l_zr, c, 1e-10);
    EXPECT_NEAR(l_zz, d, 1e-10);
    EXPECT_NEAR(hoop, a, 1e-10);
  }
}

// The trace of the volume-averaged gradient is the ring's volume rate over its volume, for any nodal
// velocities (the mean dilatation): against a central difference of the exact volume.
TEST(Fe2dElement, DivergenceIsTheVolumeRate) {
  const double u[4] = {13, -7, 22, 5}, w[4] = {-31, 4, 17, -9};
  const QuadGeometry g = quad_geometry(kR, kZ);
  double div = 0;
  for (int k = 0; k < 4; ++k) div += (g.b_r[k] + g.hoop[k]) * u[k] + g.b_z[k] * w[k];
  const double h = 1e-9;  // s
  double rp[4], zp[4], rm[4], zm[4];
  for (int k = 0; k < 4; ++k) rp[k] = kR[k] + h * u[k], zp[k] = kZ[k] + h * w[k], rm[k] = kR[k] - h * u[k], zm[k] = kZ[k] - h * w[k];
  const double rate = (quad_geometry(rp, zp).volume - quad_geometry(rm, zm).volume) / (2 * h) / g.volume;
  EXPECT_NEAR(div / rate, 1.0, 1e-8);
}

// The hourglass base vector sees no constant and no linear field and reads the hourglass pattern at 1.
TEST(Fe2dElement, HourglassVectorIsOrthogonalToLinearFields) {
  const QuadGeometry g = quad_geometry(kR, kZ);
  double one = 0, r = 0, z = 0, pattern = 0;
  for (int k = 0; k < 4; ++k) {
    one += g.gamma[k];
    r += g.gamma[k] * kR[k];
    z += g.gamma[k] * kZ[k];
    pattern += g.gamma[k] * kHourglass[k];
  }
  EXPECT_NEAR(one, 0, 1e-14);
  EXPECT_NEAR(r, 0, 1e-17);
  EXPECT_NEAR(z, 0, 1e-17);
  EXPECT_NEAR(pattern, 1, 1e-14);
}

TEST(Fe2dMaterial, VelocityGradientLayout) {
  const Mat3<double> l = axisymmetric_velocity_gradient(1.0, 2.0, 3.0, 4.0, 5.0);
  EXPECT_EQ(l.m[0][0], 1.0);  // d v_r / d r
  EXPECT_EQ(l.m[0][2], 2.0);  // d v_r / d z
  EXPECT_EQ(l.m[2][0], 3.0);  // d v_z / d r
  EXPECT_EQ(l.m[2][2], 4.0);  // d v_z / d z
  EXPECT_EQ(l.m[1][1], 5.0);  // v_r / r
  EXPECT_EQ(l.m[0][1] + l.m[1][0] + l.m[1][2] + l.m[2][1], 0.0);
  EXPECT_EQ(l.trace(), 10.0);
}

const std::string kBar = R"toml([case]
name = "bar"

[materials.cu]
density = "8930 kg/m^3"
eos = { kind = "linear" }
strength = { kind = "johnson-cook", youngs_modulus = "117 GPa", poisson_ratio = 0.35, a = "400 MPa", b = "100.09 MPa", n = 1.0, c = 0.0, m = 1.0 }

[[bodies]]
name = "bar"
material = "cu"
shape = "cylinder"
base = ["0 mm", "0 mm", "0 mm"]
axis = "z"
radius = "3.2 mm"
length = "32.4 mm"
velocity = "227 m/s"
direction = [0, 0, -1]

[[boundaries.symmetry]]
axis = "x"
position = "0 mm"

[[boundaries.symmetry]]
axis = "z"
position = "0 mm"

[numerics]
spacing = "0.4 mm"

[time]
end = "80 us"
output_interval = "1 us"
)toml";

std::string with(const std::string& from, const std::string& to, const std::string& text = kBar) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at == std::string::npos) return text;
  return text.substr(0, at) + to + text.substr(at + from.size());
}

Bar bar_of(const std::string& text) { return bar_from_case(parse_case_string(text, "bar.toml")); }

// The case's error: its key and a piece of its message.
void expect_error(const std::string& text, const std::string& key, const std::string& words) {
  try {
    bar_of(text);
    ADD_FAILURE() << "no error; expected " << key;
  } catch (const CaseError& e) {
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("bar.toml", 0), 0u) << e.what();
  }
}

TEST(Fe2dCase, ABarOnAPlaneOfSymmetryOrAWall) {
  const Bar b = bar_of(kBar);
  EXPECT_EQ(b.radius, 3.2e-3);
  EXPECT_EQ(b.length, 32.4e-3);
  EXPECT_EQ(b.speed, 227.0);
  EXPECT_TRUE(b.plane_holds);
  EXPECT_DOUBLE_EQ(b.end_time, 80e-6);
  EXPECT_FALSE(bar_of(with("[[boundaries.symmetry]]\naxis = \"z\"", "[[boundaries.wall]]\naxis = \"z\"")).plane_holds);
  // Moving up onto a wall at its top end.
  const std::string up = with("direction = [0, 0, -1]", "direction = [0, 0, 1]",
                              with("axis = \"z\"\nposition = \"0 mm\"", "axis = \"z\"\nposition = \"32.4 mm\""));
  EXPECT_EQ(bar_of(up).speed, 227.0);
}

TEST(Fe2dCase, WhatIsNotABarIsAnErrorNamingTheKey) {
  expect_error(kBar + "\n[[bodies]]\nname = \"anvil\"\nmaterial = \"cu\"\nshape = \"box\"\nmin = [\"-5 mm\", \"-5 mm\", "
                      "\"-10 mm\"]\nmax = [\"5 mm\", \"5 mm\", \"-2 mm\"]\n",
               "bodies", "the case has 2 bodies");
  expect_error(with("shape = \"cylinder\"\nbase = [\"0 mm\", \"0 mm\", \"0 mm\"]\naxis = \"z\"\nradius = \"3.2 mm\"\n"
                    "length = \"32.4 mm\"",
                    "shape = \"box\"\nmin = [\"0 mm\", \"0 mm\", \"0 mm\"]\nmax = [\"3 mm\", \"3 mm\", \"30 mm\"]"),
               "bodies[0].shape", "is \"box\"");
  expect_error(with("length = \"32.4 mm\"", "length = \"32.4 mm\"\nnose = { kind = \"conical\", at = \"top\", length = \"5 mm\" }"),
               "bodies[0].nose", "flat-ended");
  expect_error(with("direction = [0, 0, -1]", "direction = [1, 0, -1]"), "bodies[0].velocity", "along the bar's axis");
  expect_error(with("[[boundaries.symmetry]]\naxis = \"z\"\nposition = \"0 mm\"\n", ""), "boundaries",
               "no plane of symmetry or wall");
  expect_error(with("axis = \"z\"\nposition = \"0 mm\"", "axis = \"z\"\nposition = \"5 mm\""),
               "boundaries.symmetry[1].position", "not at the bar's impact end");
  expect_error(with("axis = \"x\"\nposition = \"0 mm\"", "axis = \"x\"\nposition = \"1 mm\""),
               "boundaries.symmetry[0].position", "must contain it");
  expect_error(with("m = 1.0 }", "m = 1.0 }\ndamage = { kind = \"critical-plastic-strain\", critical_plastic_strain = 0.5 }"),
               "materials.cu.damage", "has no damage");
  expect_error(with("strength = { kind = \"johnson-cook\", youngs_modulus = \"117 GPa\", poisson_ratio = 0.35, a = "
                    "\"400 MPa\", b = \"100.09 MPa\", n = 1.0, c = 0.0, m = 1.0 }",
                    "strength = { kind = \"hydrodynamic\" }\neos = { kind = \"linear\", bulk_modulus = \"130 GPa\" }",
                    with("eos = { kind = \"linear\" }\n", "")),
               "materials.cu.strength", "no shear modulus");
}

// The strength model's rate and return through update_deviatoric_stress, in uniaxial compression along z at
// the equivalent rate 1e4 /s (v_r = -rate r / 2, v_z = rate z).
TEST(Fe2dMaterial, UniaxialCompressionThroughTheStrengthModel) {
  const MaterialParams<double> m = bar_of(kBar).material;
  const double rate = -1e4, g = m.strength.shear_modulus;
  const Mat3<double> l = axisymmetric_velocity_gradient(-0.5 * rate, 0.0, 0.0, rate, -0.5 * rate);
  // A small step stays elastic: S = 2 G dt d' (Hooke, common/strength.hpp), d' = rate diag(-1/2, -1/2, 1).
  Sym3<double> s = Sym3<double>::zero();
  DeviatoricStep<double> step = update_deviatoric_stress(m, s, l, 1e-8, 0.0, 293.0, 8930.0, 0.0);
  EXPECT_DOUBLE_EQ(step.strain_rate, 1e4);
  EXPECT_EQ(step.plastic.d_eps_p, 0.0);
  EXPECT_NEAR(s.zz / (2 * g * 1e-8 * rate), 1.0, 1e-12);
  EXPECT_EQ(s.xx, s.yy);
  // A large one yields at A = 400 MPa; the trial von Mises stress 3 G dt |rate| above it is the plastic
  // strain d_eps_p = dt |rate| - A / (3 G) (the radial return).
  s = Sym3<double>::zero();
  step = update_deviatoric_stress(m, s, l, 1e-6, 0.0, 293.0, 8930.0, 0.0);
  EXPECT_NEAR(von_mises(s) / 400e6, 1.0, 1e-12);
  EXPECT_NEAR(step.plastic.d_eps_p, 1e-6 * 1e4 - 400e6 / (3 * g), 1e-12);
  EXPECT_NEAR(step.plastic.plastic_work, 400e6 * step.plastic.d_eps_p / 8930.0, 1e-9);
}

// The mesh holds the bar's mass; the same input gives the same bits.
TEST(Fe2dRun, MassOfTheMeshAndTheSameBitsTwice) {
  const Bar bar = bar_of(kBar);
  Options opt;
  opt.elements_across = 4;
  opt.end_time = 5e-6;
  Simulation a(bar, opt), b(bar, opt);
  double mass = 0;
  for (const Node& n : a.nodes()) mass += n.mass;
  EXPECT_NEAR(mass / (8930 * kPi * 3.2e-3 * 3.2e-3 * 32.4e-3), 1.0, 1e-13);
  a.run();
  b.run();
  ASSERT_EQ(a.steps(), b.steps());
  EXPECT_EQ(a.time(), 5e-6);
  for (std::size_t k = 0; k < a.nodes().size(); ++k) {
    EXPECT_EQ(a.nodes()[k].r, b.nodes()[k].r);
    EXPECT_EQ(a.nodes()[k].z, b.nodes()[k].z);
  }
  EXPECT_GT(measure(a).impact_face_diameter, 2 * 3.2e-3);
}

}  // namespace
}  // namespace impactsph::fe2d
