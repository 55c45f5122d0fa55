// The host's parallel loops, one layer for the reference (reference/solver.cpp) and the gpu port's host
// build (gpu/launch.hpp): OpenMP with a static schedule, so that each index runs on the same thread for a
// given thread count and a run keeps its bits. Reductions are of minima, maxima and integer counts only,
// which are exact in any order.
#pragma once
#include <algorithm>
#include <cstdint>
#include <limits>

#if defined(_OPENMP)
#include <omp.h>
#endif

// IMPACTSPH_FLATTEN after a loop body's parameter list, [&](std::int64_t i) IMPACTSPH_FLATTEN { ... }: every
// call in the body is inlined. Without it GCC 12 inlined the pair functions less deeply into a lambda than
// into a plain OpenMP loop, and the reference's step ran 7 % slower. (Floating-point contraction is off,
// CMakeLists.txt, so inlining does not change the bits.)
#if defined(__GNUC__)
#define IMPACTSPH_FLATTEN __attribute__((flatten))
#else
#define IMPACTSPH_FLATTEN
#endif

namespace impactsph {

// The number of threads a parallel loop below runs on (1 without OpenMP).
inline std::int64_t parallel_thread_count() {
#if defined(_OPENMP)
  return omp_get_max_threads();
#else
  return 1;
#endif
}

// f(i) for every i in [0, n), spread over the host's threads.
template <class F> void parallel_for(std::int64_t n, F&& f) {
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) f(i);
}

// The same, where each thread first makes setup() (its floating-point mode, say), which lives while the
// thread runs its indices.
template <class Setup, class F> void parallel_for_with(std::int64_t n, Setup&& setup, F&& f) {
#pragma omp parallel
  {
    const auto guard = setup();
#pragma omp for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) f(i);
  }
}

// The smallest and the largest value(i) over [0, n) (+infinity and -infinity for none).
template <class F> double parallel_min(std::int64_t n, F&& value) {
  double m = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(min : m)
  for (std::int64_t i = 0; i < n; ++i) m = std::min(m, value(i));
  return m;
}
template <class F> double parallel_max(std::int64_t n, F&& value) {
  double m = -std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(max : m)
  for (std::int64_t i = 0; i < n; ++i) m = std::max(m, value(i));
  return m;
}

// The sum of the integers count(i) over [0, n).
template <class F> std::int64_t parallel_count(std::int64_t n, F&& count) {
  std::int64_t sum = 0;
#pragma omp parallel for schedule(static) reduction(+ : sum)
  for (std::int64_t i = 0; i < n; ++i) sum += count(i);
  return sum;
}

}  // namespace impactsph
