// IMPACTSPH_HD marks a function that both solvers call: the reference on the host, the gpu port on the
// device. Under nvcc it expands to __host__ __device__; elsewhere to nothing, so the same header builds
// for the host-side CI without a CUDA toolkit. Headers that use it hold no I/O, exceptions or globals.
#pragma once

#if defined(__CUDACC__)
#define IMPACTSPH_HD __host__ __device__ __forceinline__
#else
#define IMPACTSPH_HD inline
#endif
// IMPACTSPH_HD_INLINE: as IMPACTSPH_HD, and inlined on the host too: a pair function large enough that GCC
// would call it, which on SIMD lanes (common/lanes.hpp) passes every lane argument through memory.
#if defined(__CUDACC__)
#define IMPACTSPH_HD_INLINE IMPACTSPH_HD
#else
#define IMPACTSPH_HD_INLINE inline __attribute__((always_inline))
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
// Whether c holds for any pair (a lane mask: any lane): guards a term that few pairs take, so that the
// others skip it; the term itself is then taken under choose.
IMPACTSPH_HD bool any_true(bool c) { return c; }

// The scalar type of a Real (itself; common/lanes.hpp gives a lane type's element), for the parameters of
// a pair function that hold one value for every pair, and the type a comparison of two Reals gives (bool;
// a lane mask for lanes).
template <class Real> struct ScalarType { using type = Real; };
template <class Real> using ScalarOf = typename ScalarType<Real>::type;
template <class Real> using FlagOf = decltype(Real() < Real());

// Numbers that appear in several formulas.
template <class Real>
struct Constants {
  static constexpr Real pi = Real(3.14159265358979323846);
};

}  // namespace impactsph
