// The geometry of one 4-node axisymmetric quadrilateral (README.md beside this file, "The element"):
// the ring's volume, its volume-averaged gradient operators (the uniform-strain element of Flanagan and
// Belytschko 1981, written for axisymmetry), its hourglass base vector and its length for the time step
// and the bulk viscosity. Nodes 0-3 counter-clockwise in the (r, z) half-plane; r >= 0 is the distance from
// the axis and z the height above the wall, both in m.
#pragma once
#include <algorithm>
#include <cmath>

#include "common/hd.hpp"

namespace impactsph::fe2d {

struct QuadGeometry {
  double area;    // A, m^2, of the quadrilateral in the (r, z) half-plane
  double volume;  // V = 2 pi int r dA, m^3, of the ring it sweeps about the axis
  // Volume averages of the shape functions' derivatives (1/m): b_r[I] = (1/V) int dN_I/dr dV,
  // b_z[I] = (1/V) int dN_I/dz dV, hoop[I] = (1/V) int N_I / r dV. With them the element's velocity
  // gradient is the volume average of the exact one, so its trace is (dV/dt) / V exactly.
  double b_r[4], b_z[4], hoop[4];
  double area_b_r[4], area_b_z[4];  // (1/A) dA/dr_I, (1/A) dA/dz_I (1/m): the plane element's gradients
  double gamma[4];                  // hourglass base vector (dimensionless), orthogonal to every linear field
  double length;                    // m, A over the longer diagonal: the time-step length
};

// Node I's natural coordinates (xi_I, eta_I) on [-1, 1]^2.
constexpr double kNodeXi[4] = {-1, 1, 1, -1};
constexpr double kNodeEta[4] = {-1, -1, 1, 1};
// The hourglass pattern of a quadrilateral (Flanagan and Belytschko 1981): Gamma = (1, -1, 1, -1).
constexpr double kHourglass[4] = {1, -1, 1, -1};

// The bilinear shape functions N_I = (1 + xi_I xi)(1 + eta_I eta) / 4, their derivatives in xi and eta, and
// the map (xi, eta) -> (r, z) at Gauss point p (2 x 2 rule, weights 1).
struct GaussPoint {
  double n[4], n_xi[4], n_eta[4];
  double r_xi, r_eta, z_xi, z_eta;  // the map's derivatives, m
  double r;                         // radius of the point, m
  double jac;                       // dA = jac dxi deta, m^2
};
inline GaussPoint gauss_point(int p, const double r[4], const double z[4]) {
  const double a = 1 / std::sqrt(3.0);
  const double xi = kNodeXi[p] * a, eta = kNodeEta[p] * a;
  GaussPoint g{};
  for (int i = 0; i < 4; ++i) {
    g.n[i] = 0.25 * (1 + kNodeXi[i] * xi) * (1 + kNodeEta[i] * eta);
    g.n_xi[i] = 0.25 * kNodeXi[i] * (1 + kNodeEta[i] * eta);
    g.n_eta[i] = 0.25 * kNodeEta[i] * (1 + kNodeXi[i] * xi);
    g.r_xi += g.n_xi[i] * r[i];
    g.r_eta += g.n_eta[i] * r[i];
    g.z_xi += g.n_xi[i] * z[i];
    g.z_eta += g.n_eta[i] * z[i];
    g.r += g.n[i] * r[i];
  }
  g.jac = g.r_xi * g.z_eta - g.r_eta * g.z_xi;
  return g;
}

// The integrals above by 2 x 2 Gauss quadrature, which is exact for them: dN_I/dr r dA = (z_eta dN_I/dxi -
// z_xi dN_I/deta) r dxi deta and N_I dA = N_I jac dxi deta are polynomials of degree at most 2 in each of xi
// and eta on a bilinear quadrilateral.
inline QuadGeometry quad_geometry(const double r[4], const double z[4]) {
  QuadGeometry g{};
  double int_r_da = 0;  // int r dA, m^3
  double sum_r[4] = {0, 0, 0, 0}, sum_z[4] = {0, 0, 0, 0}, sum_h[4] = {0, 0, 0, 0};
  for (int p = 0; p < 4; ++p) {
    const GaussPoint q = gauss_point(p, r, z);
    int_r_da += q.r * q.jac;
    for (int i = 0; i < 4; ++i) {
      sum_r[i] += (q.z_eta * q.n_xi[i] - q.z_xi * q.n_eta[i]) * q.r;
      sum_z[i] += (q.r_xi * q.n_eta[i] - q.r_eta * q.n_xi[i]) * q.r;
      sum_h[i] += q.n[i] * q.jac;
    }
  }
  g.volume = 2 * Constants<double>::pi * int_r_da;
  for (int i = 0; i < 4; ++i) {
    g.b_r[i] = sum_r[i] / int_r_da;
    g.b_z[i] = sum_z[i] / int_r_da;
    g.hoop[i] = sum_h[i] / int_r_da;
  }
  // Shoelace area and its derivatives: dA/dr_I = (z_{I+1} - z_{I-1}) / 2, dA/dz_I = (r_{I-1} - r_{I+1}) / 2.
  g.area = 0.5 * ((r[2] - r[0]) * (z[3] - z[1]) - (r[3] - r[1]) * (z[2] - z[0]));
  double gamma_r = 0, gamma_z = 0;  // Gamma . r, Gamma . z (m)
  for (int i = 0; i < 4; ++i) {
    const int next = (i + 1) % 4, prev = (i + 3) % 4;
    g.area_b_r[i] = 0.5 * (z[next] - z[prev]) / g.area;
    g.area_b_z[i] = 0.5 * (r[prev] - r[next]) / g.area;
    gamma_r += kHourglass[i] * r[i];
    gamma_z += kHourglass[i] * z[i];
  }
  for (int i = 0; i < 4; ++i)
    g.gamma[i] = 0.25 * (kHourglass[i] - gamma_r * g.area_b_r[i] - gamma_z * g.area_b_z[i]);
  const double d02 = std::hypot(r[2] - r[0], z[2] - z[0]), d13 = std::hypot(r[3] - r[1], z[3] - z[1]);
  g.length = g.area / std::max(d02, d13);
  return g;
}

// Row-sum lumped masses of a ring of density rho (kg/m^3): m_I = rho 2 pi int N_I r dA (kg), exact by the
// same quadrature. They add up to rho V.
inline void lumped_masses(const double r[4], const double z[4], double rho, double mass[4]) {
  for (int i = 0; i < 4; ++i) mass[i] = 0;
  for (int p = 0; p < 4; ++p) {
    const GaussPoint q = gauss_point(p, r, z);
    for (int i = 0; i < 4; ++i) mass[i] += rho * 2 * Constants<double>::pi * q.n[i] * q.r * q.jac;
  }
}

}  // namespace impactsph::fe2d
