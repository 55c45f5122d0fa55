// Small fixed-size vector and 3x3 matrix types for the shared physics. They are plain aggregates
// (trivially copyable) so the gpu port can keep them in registers; Eigen stays on the host side.
#pragma once
#include "common/hd.hpp"

namespace impactsph {

template <class Real>
struct Vec3 {
  Real x, y, z;
  IMPACTSPH_HD Real& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  IMPACTSPH_HD Real operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

template <class Real> IMPACTSPH_HD Vec3<Real> operator+(Vec3<Real> a, Vec3<Real> b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class Real> IMPACTSPH_HD Vec3<Real> operator-(Vec3<Real> a, Vec3<Real> b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class Real> IMPACTSPH_HD Vec3<Real> operator-(Vec3<Real> a) { return {-a.x, -a.y, -a.z}; }
template <class Real> IMPACTSPH_HD Vec3<Real> operator*(Real s, Vec3<Real> a) { return {s * a.x, s * a.y, s * a.z}; }
template <class Real> IMPACTSPH_HD Vec3<Real> operator*(Vec3<Real> a, Real s) { return {s * a.x, s * a.y, s * a.z}; }
template <class Real> IMPACTSPH_HD Vec3<Real>& operator+=(Vec3<Real>& a, Vec3<Real> b) { a.x += b.x; a.y += b.y; a.z += b.z; return a; }
template <class Real> IMPACTSPH_HD Vec3<Real>& operator-=(Vec3<Real>& a, Vec3<Real> b) { a.x -= b.x; a.y -= b.y; a.z -= b.z; return a; }
template <class Real> IMPACTSPH_HD Real dot(Vec3<Real> a, Vec3<Real> b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class Real> IMPACTSPH_HD Real norm2(Vec3<Real> a) { return dot(a, a); }
template <class Real> IMPACTSPH_HD Real norm(Vec3<Real> a) { return std::sqrt(dot(a, a)); }

// Row-major 3x3 matrix, m[r][c].
template <class Real>
struct Mat3 {
  Real m[3][3];
  IMPACTSPH_HD static Mat3 zero() { return {{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}}; }
  IMPACTSPH_HD static Mat3 identity() { return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; }
  IMPACTSPH_HD Real trace() const { return m[0][0] + m[1][1] + m[2][2]; }
  IMPACTSPH_HD Mat3 transpose() const {
    Mat3 t;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) t.m[r][c] = m[c][r];
    return t;
  }
};

// Every entry equal (==; a NaN entry makes two matrices unequal).
template <class Real> IMPACTSPH_HD bool exactly_equal(const Mat3<Real>& a, const Mat3<Real>& b) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!(a.m[i][j] == b.m[i][j])) return false;
  return true;
}

template <class Real> IMPACTSPH_HD Mat3<Real> operator+(const Mat3<Real>& a, const Mat3<Real>& b) {
  Mat3<Real> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][j] + b.m[i][j];
  return r;
}
template <class Real> IMPACTSPH_HD Mat3<Real> operator-(const Mat3<Real>& a, const Mat3<Real>& b) {
  Mat3<Real> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][j] - b.m[i][j];
  return r;
}
template <class Real> IMPACTSPH_HD Mat3<Real> operator*(Real s, const Mat3<Real>& a) {
  Mat3<Real> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = s * a.m[i][j];
  return r;
}
template <class Real> IMPACTSPH_HD Mat3<Real> operator*(const Mat3<Real>& a, const Mat3<Real>& b) {
  Mat3<Real> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
  return r;
}
template <class Real> IMPACTSPH_HD Vec3<Real> operator*(const Mat3<Real>& a, Vec3<Real> v) {
  return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z, a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
          a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}
// a (x) b: outer product, (a b^T)_rc = a_r b_c.
template <class Real> IMPACTSPH_HD Mat3<Real> outer(Vec3<Real> a, Vec3<Real> b) {
  return {{{a.x * b.x, a.x * b.y, a.x * b.z}, {a.y * b.x, a.y * b.y, a.y * b.z}, {a.z * b.x, a.z * b.y, a.z * b.z}}};
}
// A : B = sum_rc A_rc B_rc.
template <class Real> IMPACTSPH_HD Real ddot(const Mat3<Real>& a, const Mat3<Real>& b) {
  Real s = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s += a.m[i][j] * b.m[i][j];
  return s;
}
template <class Real> IMPACTSPH_HD Real determinant(const Mat3<Real>& a) {
  return a.m[0][0] * (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1]) -
         a.m[0][1] * (a.m[1][0] * a.m[2][2] - a.m[1][2] * a.m[2][0]) +
         a.m[0][2] * (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]);
}
// Frobenius norm.
template <class Real> IMPACTSPH_HD Real frobenius(const Mat3<Real>& a) { return std::sqrt(ddot(a, a)); }

// Inverse by cofactors. The caller checks conditioning first (see correction.hpp).
template <class Real> IMPACTSPH_HD Mat3<Real> inverse(const Mat3<Real>& a, Real det) {
  const Real s = Real(1) / det;
  Mat3<Real> r;
  r.m[0][0] = s * (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1]);
  r.m[0][1] = s * (a.m[0][2] * a.m[2][1] - a.m[0][1] * a.m[2][2]);
  r.m[0][2] = s * (a.m[0][1] * a.m[1][2] - a.m[0][2] * a.m[1][1]);
  r.m[1][0] = s * (a.m[1][2] * a.m[2][0] - a.m[1][0] * a.m[2][2]);
  r.m[1][1] = s * (a.m[0][0] * a.m[2][2] - a.m[0][2] * a.m[2][0]);
  r.m[1][2] = s * (a.m[0][2] * a.m[1][0] - a.m[0][0] * a.m[1][2]);
  r.m[2][0] = s * (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]);
  r.m[2][1] = s * (a.m[0][1] * a.m[2][0] - a.m[0][0] * a.m[2][1]);
  r.m[2][2] = s * (a.m[0][0] * a.m[1][1] - a.m[0][1] * a.m[1][0]);
  return r;
}

// Symmetric 3x3 tensor in six components (xx, yy, zz, xy, yz, zx): the deviatoric stress.
template <class Real>
struct Sym3 {
  Real xx, yy, zz, xy, yz, zx;
  IMPACTSPH_HD static Sym3 zero() { return {0, 0, 0, 0, 0, 0}; }
  IMPACTSPH_HD Real trace() const { return xx + yy + zz; }
  IMPACTSPH_HD Mat3<Real> full() const { return {{{xx, xy, zx}, {xy, yy, yz}, {zx, yz, zz}}}; }
  IMPACTSPH_HD static Sym3 from(const Mat3<Real>& a) {  // symmetric part of a
    return {a.m[0][0], a.m[1][1], a.m[2][2], Real(0.5) * (a.m[0][1] + a.m[1][0]), Real(0.5) * (a.m[1][2] + a.m[2][1]),
            Real(0.5) * (a.m[2][0] + a.m[0][2])};
  }
};
template <class Real> IMPACTSPH_HD Sym3<Real> operator+(Sym3<Real> a, Sym3<Real> b) {
  return {a.xx + b.xx, a.yy + b.yy, a.zz + b.zz, a.xy + b.xy, a.yz + b.yz, a.zx + b.zx};
}
template <class Real> IMPACTSPH_HD Sym3<Real> operator*(Real s, Sym3<Real> a) {
  return {s * a.xx, s * a.yy, s * a.zz, s * a.xy, s * a.yz, s * a.zx};
}
// S : S for a symmetric tensor.
template <class Real> IMPACTSPH_HD Real ddot(Sym3<Real> a, Sym3<Real> b) {
  return a.xx * b.xx + a.yy * b.yy + a.zz * b.zz + Real(2) * (a.xy * b.xy + a.yz * b.yz + a.zx * b.zx);
}
// Deviatoric part.
template <class Real> IMPACTSPH_HD Sym3<Real> deviator(Sym3<Real> a) {
  const Real m = a.trace() / Real(3);
  return {a.xx - m, a.yy - m, a.zz - m, a.xy, a.yz, a.zx};
}
// Von Mises equivalent stress of a deviator S: sqrt(3/2 S:S) = sqrt(3 J2).
template <class Real> IMPACTSPH_HD Real von_mises(Sym3<Real> s) { return std::sqrt(Real(1.5) * ddot(s, s)); }

}  // namespace impactsph
