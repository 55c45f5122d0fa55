// IMPACTSPH_HD marks a function that both solvers call: the reference on the host, the gpu port on the
// device. Under nvcc it expands to __host__ __device__; elsewhere to nothing, so the same header builds
// for the host-side CI without a CUDA toolkit. Headers that use it hold no I/O, exceptions or globals.
#pragma once

#if defined(__CUDACC__)
#define IMPACTSPH_HD __host__ __device__ __forceinline__
#else
#define IMPACTSPH_HD inline
#endif

#include <cmath>

namespace impactsph {

template <class Real>
IMPACTSPH_HD Real sqr(Real x) { return x * x; }

template <class Real>
IMPACTSPH_HD Real min_of(Real a, Real b) { return a < b ? a : b; }

template <class Real>
IMPACTSPH_HD Real max_of(Real a, Real b) { return a > b ? a : b; }

// `c ? a : b` with both taken: the form the pair functions use where a condition depends on the pair, so
// that they also run on SIMD lanes (common/lanes.hpp overloads it for a lane mask).
template <class Real>
IMPACTSPH_HD Real choose(bool c, Real a, Real b) { return c ? a : b; }

// Numbers that appear in several formulas.
template <class Real>
struct Constants {
  static constexpr Real pi = Real(3.14159265358979323846);
};

}  // namespace impactsph
