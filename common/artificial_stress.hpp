// Artificial stress against the tensile instability of SPH (Monaghan 2000, J. Comput. Phys. 159:290-311;
// Gray, Monaghan and Swift 2001, Comput. Methods Appl. Mech. Engrg. 190:6641-6662, section 4). In tension
// a particle lattice is unstable: neighbours clump in pairs and open gaps that no constitutive law asked
// for (a Taylor bar's foot breaks into spokes, a plate's shear band separates before any failure). Each
// particle carries a repulsive stress R_i built from the tensile principal components of its own stress,
// and each pair adds (R_i + R_j) f_ij^n to the momentum and energy terms, with f_ij = W(r_ij)/W(dp) and dp
// the particle spacing: the term grows as two particles close in below the spacing and fades beyond it.
//   R_i = -epsilon sum_a max(s_a, 0) e_a (x) e_a,   s_a, e_a the eigenpairs of A_i = sigma_i / rho_i^2
// (units of A, m^5 kg^-1 s^-2). Gray et al. use epsilon = 0.3 and n = 4 for elastic solids. Compression is
// left alone: the pressure already keeps particles apart there.
// Gray et al. take A itself (deviatoric = false). In impact, where the Mie-Grueneisen pressure has no
// tensile limit, that form ran away on the Taylor bar (0.5 mm, epsilon 0.3, with and without the Monaghan
// term): a particle in hydrostatic tension repels its neighbours, its density and internal energy fall,
// the Grueneisen term Gamma rho e makes its pressure more tensile still (-45 GPa at 30 us), and the energy
// grew tenfold. The default therefore takes the deviator of A (Deviatoric): the shear that tears a band or a
// foot apart, bounded by the yield stress, and nothing of the mean stress. That gives a third of Gray et
// al.'s repulsion under equibiaxial tension T (the deviator's tensile values are T/3), where a plate's
// stretched face breaks into columns (cases/plate-8mm/README.md). TotalBounded keeps the whole stress but
// caps the mean tension that R sees at the von Mises stress of A (stress triaxiality at most 1):
//   A' = dev(A) + min(tr(A)/3, sqrt(3/2 dev(A):dev(A))) I.
// Shear (triaxiality 0), uniaxial (1/3) and equibiaxial tension (2/3) keep Gray et al.'s R; near-hydrostatic
// tension, where the Grueneisen loop runs away, gets no more than its shear bounds, i.e. the yield stress.
#pragma once
#include "common/kernels.hpp"
#include "common/tensor.hpp"

namespace impactsph {

// Which stress R is built from (the case file's numerics.artificial_stress_of).
enum class ArtificialStressOf : int {
  Deviatoric,    // "deviatoric": the deviator of A (the default)
  Total,         // "total": A itself, Gray, Monaghan and Swift's form
  TotalBounded,  // "total-bounded": A with its mean tension capped at its von Mises stress
};

template <class Real>
struct ArtificialStressParams {
  Real epsilon = Real(0);         // Gray et al.'s epsilon, dimensionless; 0: off
  int exponent = 4;               // n, dimensionless
  Real inverse_w_spacing = Real(0);  // 1 / W(1 / h_factor, 1): the kernel at the spacing, for unit h
  ArtificialStressOf of = ArtificialStressOf::Deviatoric;  // which stress R is built from
  IMPACTSPH_HD bool on() const { return epsilon > Real(0); }
};

// Parameters for a kernel and a smoothing-length factor h / dp.
template <class Real>
ArtificialStressParams<Real> make_artificial_stress(Real epsilon, int exponent, KernelKind kernel, Real h_factor,
                                                    ArtificialStressOf of) {
  return {epsilon, exponent, Real(1) / kernel_w(kernel, Real(1) / h_factor, Real(1)), of};
}

// Eigen-decomposition of a symmetric 3x3 matrix by cyclic Jacobi rotations (Golub and Van Loan, Matrix
// Computations, section 8.5): a = V diag(values) V^T, the eigenvectors in the columns of V. A fixed order
// of rotations and at most eight sweeps, so that the result is the same bits on every run.
template <class Real>
IMPACTSPH_HD void symmetric_eigen(const Sym3<Real>& s, Real values[3], Mat3<Real>& V) {
  Mat3<Real> a = s.full();
  V = Mat3<Real>::identity();
  const Real scale = a.m[0][0] * a.m[0][0] + a.m[1][1] * a.m[1][1] + a.m[2][2] * a.m[2][2] +
                     Real(2) * (a.m[0][1] * a.m[0][1] + a.m[0][2] * a.m[0][2] + a.m[1][2] * a.m[1][2]);
  const Real tolerance = Real(sizeof(Real) == 4 ? 1e-14 : 1e-30) * scale;
  for (int sweep = 0; sweep < 8; ++sweep) {
    const Real off = a.m[0][1] * a.m[0][1] + a.m[0][2] * a.m[0][2] + a.m[1][2] * a.m[1][2];
    if (!(off > tolerance)) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        const Real apq = a.m[p][q];
        if (apq == Real(0)) continue;
        // The rotation that zeroes a_pq: t = tan(phi), the smaller root of t^2 + 2 theta t - 1 = 0.
        const Real theta = (a.m[q][q] - a.m[p][p]) / (Real(2) * apq);
        const Real abs_theta = theta < Real(0) ? -theta : theta;
        Real t = Real(1) / (abs_theta + std::sqrt(theta * theta + Real(1)));
        if (theta < Real(0)) t = -t;
        const Real c = Real(1) / std::sqrt(t * t + Real(1)), sn = t * c;
        Mat3<Real> J = Mat3<Real>::identity();
        J.m[p][p] = c; J.m[q][q] = c; J.m[p][q] = sn; J.m[q][p] = -sn;
        a = J.transpose() * a * J;
        a.m[p][q] = Real(0);
        a.m[q][p] = Real(0);
        V = V * J;
      }
  }
  values[0] = a.m[0][0];
  values[1] = a.m[1][1];
  values[2] = a.m[2][2];
}

// The stress R is built from, units of A: A, its deviator, or A with its mean tension capped at its von
// Mises stress sqrt(3/2 s:s), s = dev(A).
template <class Real>
IMPACTSPH_HD Sym3<Real> artificial_stress_source(ArtificialStressOf of, const Sym3<Real>& A) {
  if (of == ArtificialStressOf::Total) return A;
  const Sym3<Real> s = deviator(A);
  if (of == ArtificialStressOf::Deviatoric) return s;
  const Real mean = A.trace() / Real(3), cap = von_mises(s);
  const Real capped = mean < cap ? mean : cap;
  return Sym3<Real>{s.xx + capped, s.yy + capped, s.zz + capped, s.xy, s.yz, s.zx};
}

// R_i from A_i = sigma_i / rho_i^2 (the stress with the pressure, before any artificial viscosity), units of
// A. Zero where every principal value of the source stress is compressive.
template <class Real>
IMPACTSPH_HD Sym3<Real> artificial_stress(const ArtificialStressParams<Real>& p, const Sym3<Real>& A) {
  Real s[3];
  Mat3<Real> V;
  symmetric_eigen(artificial_stress_source(p.of, A), s, V);
  Mat3<Real> R = Mat3<Real>::zero();
  for (int a = 0; a < 3; ++a) {
    if (!(s[a] > Real(0))) continue;
    const Vec3<Real> e{V.m[0][a], V.m[1][a], V.m[2][a]};
    R = R + (-p.epsilon * s[a]) * outer(e, e);
  }
  return Sym3<Real>::from(R);
}

// f_ij^n = (W(r, h) / W(dp, h))^n for a pair at distance r (m) with pair smoothing length h (m),
// dimensionless: 1 at the spacing, 0 beyond the support, and 0 when the artificial stress is off.
template <class Real>
IMPACTSPH_HD Real artificial_stress_pair_factor(const ArtificialStressParams<ScalarOf<Real>>& p, KernelKind kernel, Real r,
                                               Real h) {
  if (!p.on()) return Real(0);
  const Real f = kernel_w(kernel, r / h, Real(1)) * p.inverse_w_spacing;
  Real fn = Real(1);
  for (int k = 0; k < p.exponent; ++k) fn *= f;
  return fn;
}

}  // namespace impactsph
