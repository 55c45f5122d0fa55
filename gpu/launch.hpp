// The launch layer of the gpu port: one thread per item. Under nvcc a launch is a CUDA kernel of 256-thread
// blocks, checked for errors at once; in the host build the same device lambda runs in the host's parallel
// loop (parallel_for_with, common/parallel.hpp: the reference's loops too; static schedule, so each item
// runs the same code in the same order whatever the thread count).
// Lambdas are written [=] IMPACTSPH_LAMBDA (std::int64_t i) { ... } and capture raw pointers by value.
// FlushDenormals (the float build): subnormal floats are read and written as zero, as the CUDA build
// does with -ftz=true. The precursor of a wave decays through the subnormal range ahead of the front,
// where x86 arithmetic is about a hundred times slower; values below 1.2e-38 carry no physics here.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>

#if defined(__CUDACC__)
#include <cuda_runtime.h>
#define IMPACTSPH_LAMBDA __host__ __device__
#else
#include "common/parallel.hpp"
#define IMPACTSPH_LAMBDA
#if defined(__SSE__)
#include <xmmintrin.h>
#endif
#endif

// IMPACTSPH_SIMD_SUMS(list): before a loop over one particle's neighbours whose only values carried from one
// entry to the next are the listed sums (an OpenMP simd reduction); empty under nvcc. On the host GCC 12 does
// not vectorise these loops across neighbours (the aggregate temporaries of the pair functions stop it), but
// with the sums held in one array it updates them with packed instructions: pass 1 in float 47.6 instead of
// 56 ms per evaluation on the 103823-particle block (gpu/README.md). How the sums are split is fixed by the
// code and the row, so a run keeps its bits for a given build and input.
#define IMPACTSPH_PRAGMA(x) _Pragma(#x)
#if defined(__CUDACC__)
#define IMPACTSPH_SIMD_SUMS(...)
#else
#define IMPACTSPH_SIMD_SUMS(...) IMPACTSPH_PRAGMA(omp simd reduction(+ : __VA_ARGS__))
#endif

namespace impactsph::gpu {

#if defined(__CUDACC__)
// Throws with the call's name when a CUDA runtime call failed.
inline void check_cuda(cudaError_t e, const char* what) {
  if (e != cudaSuccess) throw std::runtime_error(std::string("CUDA error in ") + what + ": " + cudaGetErrorString(e));
}

template <class F>
__global__ void for_each_kernel(std::int64_t n, F f) {
  const std::int64_t i = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}

constexpr int kBlock = 256;

template <bool FlushDenormals = false, class F>
void launch(const char* name, std::int64_t n, F f) {
  if (n <= 0) return;
  const std::int64_t blocks = (n + kBlock - 1) / kBlock;
  for_each_kernel<<<static_cast<unsigned>(blocks), kBlock>>>(n, f);
  check_cuda(cudaGetLastError(), name);
#ifndef NDEBUG
  check_cuda(cudaDeviceSynchronize(), name);
#endif
}
#else
// Sets the flush-to-zero and denormals-are-zero bits of this thread for its lifetime, then restores them.
class DenormalFlush {
 public:
  explicit DenormalFlush(bool on) {
#if defined(__SSE__)
    saved_ = _mm_getcsr();
    if (on) _mm_setcsr(saved_ | 0x8040u);  // FTZ (bit 15) and DAZ (bit 6)
#else
    (void)on;
#endif
  }
  ~DenormalFlush() {
#if defined(__SSE__)
    _mm_setcsr(saved_);
#endif
  }
  DenormalFlush(const DenormalFlush&) = delete;
  DenormalFlush& operator=(const DenormalFlush&) = delete;

 private:
  unsigned saved_ = 0;
};

template <bool FlushDenormals = false, class F>
void launch(const char*, std::int64_t n, F f) {
  if (n <= 0) return;
  parallel_for_with(n, [] { return DenormalFlush(FlushDenormals); }, f);
}
#endif

}  // namespace impactsph::gpu
