// Unit tests of common/kernels.hpp (Wendland C2, F eq 2.15; cubic B-spline, X eq 2), support 2h in 3D:
// normalisation, gradient = derivative of the value, compact support, and the first-moment lattice sum
// behind the gradient correction (L close to the identity on a full-support interior particle).
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <random>

#include "common/kernels.hpp"

namespace {

using namespace impactsph;

constexpr KernelKind kKernels[] = {KernelKind::WendlandC2, KernelKind::CubicSpline};
const char* kernel_name(KernelKind k) { return k == KernelKind::WendlandC2 ? "WendlandC2" : "CubicSpline"; }

template <class Real>
class KernelTyped : public ::testing::Test {};
using KernelReals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(KernelTyped, KernelReals);

// Integral of W over its support by a lattice sum: sum_j dx^3 W(|x_j|) with dx = h/20. For a kernel with
// compact support this converges much faster than the formal O(dx^2) (it is an N-dimensional trapezoid
// rule of a function that vanishes smoothly at its support): 1 - 3.6e-8 already at dx = h/10 in double.
// The kernel is evaluated in Real and summed in double (531441 terms: a float accumulator would lose
// ~1e-4 by itself, which is not what is tested). A float kernel value is good to ~10 eps = 1.2e-6 relative,
// so the 1e-4 tolerance holds for both types and still catches any wrong constant (e.g. 1/(4 pi h^3)).
TYPED_TEST(KernelTyped, NormalisationByLatticeSum) {
  using Real = TypeParam;
  const double h = 1.7e-3;  // m, a realistic smoothing length; the sum is scale free
  const int N = 20;
  const double dx = h / N;
  const int M = 2 * N;  // lattice points up to |i| = 2h/dx cover the support
  for (KernelKind k : kKernels) {
    double sum = 0;
    for (int i = -M; i <= M; ++i)
      for (int j = -M; j <= M; ++j)
        for (int l = -M; l <= M; ++l) {
          const double r = dx * std::sqrt(double(i * i + j * j + l * l));
          sum += double(kernel_w<Real>(k, Real(r), Real(h)));
        }
    EXPECT_NEAR(sum * dx * dx * dx, 1.0, 1e-4) << kernel_name(k);
  }
}

// The same integral in spherical shells, int_0^2h 4 pi r^2 W dr, by composite Simpson on panels that
// meet at r = h (the cubic spline is a piecewise polynomial of degree 3 with its break at q = 1, so the
// integrand is a degree-5 polynomial on each panel: Simpson's error ~ (dr/h)^4 / 180 ~ 1e-15). In double
// the result is exact to rounding: 1e-12 pins the normalisation constants 21/(16 pi) and 1/pi.
TEST(KernelQuadrature, NormalisationBySphericalShellsDouble) {
  const double h = 0.37;
  const int n = 2000;  // Simpson intervals per unit of q (even)
  for (KernelKind k : kKernels) {
    double total = 0;
    for (int panel = 0; panel < 2; ++panel) {  // [0, h] and [h, 2h]
      const double a = panel * h, dr = h / n;
      double s = 0;
      for (int m = 0; m <= n; ++m) {
        const double r = a + m * dr;
        // At r = 2h the value is the limit from inside (zero for both kernels).
        const double f = 4 * Constants<double>::pi * r * r * kernel_w(k, r, h);
        s += f * (m == 0 || m == n ? 1.0 : (m % 2 ? 4.0 : 2.0));
      }
      total += s * dr / 3;
    }
    EXPECT_NEAR(total, 1.0, 1e-12) << kernel_name(k);
  }
}

// Closed-form values: W(0) = 21/(16 pi h^3) (Wendland), 1/(pi h^3) (cubic spline); W(h) = 21/(16 pi h^3)
// * 3/16 and 1/(4 pi h^3). A few operations each: 8 eps relative.
TYPED_TEST(KernelTyped, ClosedFormValues) {
  using Real = TypeParam;
  const double eps = std::numeric_limits<Real>::epsilon();
  const double h = 2.5e-3, pi = Constants<double>::pi, h3 = h * h * h;
  EXPECT_NEAR(double(wendland_c2_w<Real>(Real(0), Real(h))), 21.0 / (16 * pi * h3), 8 * eps * 21.0 / (16 * pi * h3));
  EXPECT_NEAR(double(wendland_c2_w<Real>(Real(h), Real(h))), 21.0 / (16 * pi * h3) * 3.0 / 16.0,
              8 * eps * 21.0 / (16 * pi * h3));
  EXPECT_NEAR(double(cubic_spline_w<Real>(Real(0), Real(h))), 1.0 / (pi * h3), 8 * eps / (pi * h3));
  EXPECT_NEAR(double(cubic_spline_w<Real>(Real(h), Real(h))), 0.25 / (pi * h3), 8 * eps / (pi * h3));
  // The two branches of the cubic spline agree at q = 1 (value and gradient factor).
  const Real hr = Real(h), below = Real(h) * (Real(1) - Real(4) * std::numeric_limits<Real>::epsilon());
  EXPECT_NEAR(double(cubic_spline_w(below, hr)), double(cubic_spline_w(hr, hr)), 1e-5 / (pi * h3));
  EXPECT_NEAR(double(cubic_spline_grad_factor(below, hr)), double(cubic_spline_grad_factor(hr, hr)),
              1e-5 / (pi * h3 * h * h));
  // Both kernels decrease monotonically in r on (0, 2h).
  for (KernelKind k : kKernels) {
    double prev = double(kernel_w<Real>(k, Real(0), Real(h)));
    for (int m = 1; m < 100; ++m) {
      const double w = double(kernel_w<Real>(k, Real(m * 0.02 * h), Real(h)));
      EXPECT_LT(w, prev) << kernel_name(k) << " q = " << m * 0.02;
      prev = w;
    }
  }
}

// grad_i W = F (x_i - x_j) against the central finite difference of W(|x|) in each Cartesian direction,
// at many radii and random directions, in double. Step d = 1e-5 h: truncation ~ (d/h)^2 W''' ~ 1e-10
// relative, rounding ~ eps W / d ~ 1e-11 relative to |grad W| ~ W/h; the test asks for 1e-6 relative to
// the gradient's magnitude scale max|grad W| (the gradient itself goes to zero at r = 0 and r = 2h).
// Radii stay at least 2d away from r = 0 (the cubic spline's |x|^3 term) and from r = 2h.
TEST(KernelGradient, MatchesCentralFiniteDifferenceDouble) {
  const double h = 1.3e-3;
  const double d = 1e-5 * h;
  std::mt19937 gen(2024);
  std::normal_distribution<double> n01(0, 1);
  for (KernelKind k : kKernels) {
    // Scale of the gradient: |grad W| = |F| r, maximal near q ~ 0.7-1.
    double gmax = 0;
    for (int m = 1; m < 200; ++m) gmax = std::max(gmax, std::abs(kernel_grad_factor(k, m * 0.01 * h, h)) * m * 0.01 * h);
    int checked = 0;
    for (int m = 1; m < 400; ++m) {
      const double r = (0.005 * m) * h;  // q from 0.005 to 1.995
      for (int dir = 0; dir < 5; ++dir) {
        Vec3<double> u{n01(gen), n01(gen), n01(gen)};
        u = (1.0 / norm(u)) * u;
        const Vec3<double> x = r * u;
        const Vec3<double> g = kernel_grad(k, x, h);
        for (int c = 0; c < 3; ++c) {
          Vec3<double> xp = x, xm = x;
          xp[c] += d;
          xm[c] -= d;
          const double fd = (kernel_w(k, norm(xp), h) - kernel_w(k, norm(xm), h)) / (2 * d);
          ASSERT_NEAR(g[c], fd, 1e-6 * gmax) << kernel_name(k) << " q = " << r / h << " component " << c;
          ++checked;
        }
      }
    }
    EXPECT_EQ(checked, 399 * 5 * 3);
  }
}

// The float kernels agree with the double ones to float precision (relative to W(0) and max|grad W|,
// since near q = 2 the factor (1 - q/2) loses relative accuracy by cancellation): 1e-5 is ~100 eps_float.
TEST(KernelGradient, FloatAgreesWithDouble) {
  const double h = 1.3e-3;
  for (KernelKind k : kKernels) {
    const double w0 = kernel_w(k, 0.0, h), f0 = std::abs(kernel_grad_factor(k, 1e-3 * h, h));
    for (int m = 0; m < 400; ++m) {
      const double r = 0.005 * m * h;
      const float rf = float(r), hf = float(h);
      EXPECT_NEAR(double(kernel_w(k, rf, hf)), kernel_w(k, double(rf), h), 1e-5 * w0) << kernel_name(k) << " q " << r / h;
      EXPECT_NEAR(double(kernel_grad_factor(k, rf, hf)), kernel_grad_factor(k, double(rf), h), 1e-5 * f0)
          << kernel_name(k) << " q " << r / h;
    }
  }
}

// W and F are exactly zero at r = 2h and beyond, and continuous there (tiny just inside).
TYPED_TEST(KernelTyped, CompactSupport) {
  using Real = TypeParam;
  const Real h = Real(1.2e-3);
  EXPECT_EQ(kernel_support(h), Real(2) * h);
  for (KernelKind k : kKernels) {
    for (Real r : {Real(2) * h, Real(2) * h * (Real(1) + std::numeric_limits<Real>::epsilon() * 4), Real(2.5) * h,
                   Real(3) * h, Real(100) * h}) {
      EXPECT_EQ(kernel_w(k, r, h), Real(0)) << kernel_name(k) << " r/h = " << r / h;
      EXPECT_EQ(kernel_grad_factor(k, r, h), Real(0)) << kernel_name(k) << " r/h = " << r / h;
      const Vec3<Real> x{r, Real(0), Real(0)};
      const Vec3<Real> g = kernel_grad(k, x, h);
      EXPECT_EQ(g.x, Real(0));
    }
    // Just inside, q = 2 - 1e-3: W ~ alpha (5e-4)^4 * 5 and F ~ alpha (5e-4)^3 / h^2: both negligible
    // against W(0) and F(0) (continuity at the support edge).
    const Real r_in = h * Real(1.999);
    EXPECT_LT(std::abs(kernel_w(k, r_in, h)), Real(1e-8) * kernel_w(k, Real(0), h)) << kernel_name(k);
    EXPECT_LT(std::abs(kernel_grad_factor(k, r_in, h)), Real(1e-5) * std::abs(kernel_grad_factor(k, h * Real(0.1), h)))
        << kernel_name(k);
    EXPECT_GT(kernel_w(k, r_in, h), Real(0)) << kernel_name(k);
  }
}

// A coincident pair gives a zero gradient, not a NaN (F is finite at r = 0 for both kernels).
TYPED_TEST(KernelTyped, CoincidentPairHasZeroGradient) {
  using Real = TypeParam;
  const Real h = Real(1e-3);
  for (KernelKind k : kKernels) {
    const Vec3<Real> g = kernel_grad(k, Vec3<Real>{0, 0, 0}, h);
    EXPECT_EQ(g.x, Real(0));
    EXPECT_EQ(g.y, Real(0));
    EXPECT_EQ(g.z, Real(0));
    EXPECT_TRUE(std::isfinite(kernel_grad_factor(k, Real(0), h)));
  }
}

// First moment on a cubic lattice: sum_j V_j x_ij (x) grad_i W_ij for a full-support interior particle
// (i at the origin, neighbours at all lattice points, V = dx^3, h = 1.2 dx) approximates
// int (x_i - x') (x) grad W dV' = -I, i.e. L_i of correction.hpp is close to the identity. The continuous
// identity follows from the normalisation by integration by parts; the lattice sum with h/dx = 1.2 misses
// it by 1.5% for Wendland (L_xx = 0.98523) and by 1.8% for the cubic spline (0.98169): 3% bounds both
// and still fails for a wrong gradient constant or sign. Off-diagonals vanish by the lattice symmetry
// (pairs +x, -x cancel exactly term by term up to rounding).
TYPED_TEST(KernelTyped, FirstMomentLatticeSumIsMinusIdentity) {
  using Real = TypeParam;
  const double dx_d = 1e-3;
  const Real dx = Real(dx_d), h = Real(1.2) * dx, V = dx * dx * dx;
  for (KernelKind k : kKernels) {
    double M[3][3] = {};
    int neighbours = 0;
    for (int i = -3; i <= 3; ++i)
      for (int j = -3; j <= 3; ++j)
        for (int l = -3; l <= 3; ++l) {
          const Vec3<Real> xij{-Real(i) * dx, -Real(j) * dx, -Real(l) * dx};  // x_i - x_j, x_i = 0
          const Vec3<Real> g = kernel_grad(k, xij, h);
          if (g.x != Real(0) || g.y != Real(0) || g.z != Real(0)) ++neighbours;
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) M[a][b] += double(V) * double(xij[a]) * double(g[b]);
        }
    // 2h = 2.4 dx: all lattice points with i^2 + j^2 + l^2 <= 5 except the particle itself:
    // 6 + 12 + 8 + 6 + 24 = 56 (|x|^2 = 1, 2, 3, 4, 5).
    EXPECT_EQ(neighbours, 56) << kernel_name(k);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        if (a == b)
          EXPECT_NEAR(M[a][b], -1.0, 0.03) << kernel_name(k) << " " << a << b;
        else
          EXPECT_NEAR(M[a][b], 0.0, 1e-5) << kernel_name(k) << " " << a << b;
      }
    // The diagonal is isotropic (cubic symmetry): equal to rounding.
    EXPECT_NEAR(M[0][0], M[1][1], 1e-5);
    EXPECT_NEAR(M[0][0], M[2][2], 1e-5);
  }
}

}  // namespace

namespace {

// The compile-time kernel choice (used by the gpu port's pair loops) gives the same bits as the run-time
// one for both kernels, at radii inside and beyond the support.
template <KernelKind K>
void expect_same_as_runtime_choice() {
  const double h = 1.3e-3;
  for (int m = 0; m <= 250; ++m) {
    const double r = 0.01 * m * h;  // q from 0 to 2.5
    EXPECT_EQ(kernel_grad_factor_of<K>(r, h), kernel_grad_factor(K, r, h)) << "q = " << r / h;
    EXPECT_EQ(kernel_grad_factor_of<K>(static_cast<float>(r), static_cast<float>(h)),
              kernel_grad_factor(K, static_cast<float>(r), static_cast<float>(h)));
  }
}

TEST(KernelGradient, CompileTimeChoiceMatchesRunTimeChoice) {
  expect_same_as_runtime_choice<KernelKind::WendlandC2>();
  expect_same_as_runtime_choice<KernelKind::CubicSpline>();
}

}  // namespace
