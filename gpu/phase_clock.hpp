// The wall time of the gpu port's phases (in the backend's namespace: included by gpu/solver_impl.hpp).
#pragma once
#include <chrono>

#include "gpu/launch.hpp"

namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND {

// Wall time of the phases of a step: CUDA events on the device, the steady clock on the host.
class PhaseClock {
 public:
  enum Phase { Sort, TimeStep, Gather, Pass1, Pass2, Advance, Check, Finish, Count };
  static const char* name(int p) {
    static const char* names[Count] = {"sort", "time_step", "gather", "pass1", "pass2", "advance", "check", "finish"};
    return names[p];
  }
  bool on = false;
  // begin(p) ... end(p) around the launches of a phase (extended lambdas may not sit inside a lambda, so
  // the passes use these); time(p, f) around a call.
  void begin() {
    if (!on) return;
#if defined(__CUDACC__)
    if (!events_) {
      check_cuda(cudaEventCreate(&start_), "cudaEventCreate");
      check_cuda(cudaEventCreate(&stop_), "cudaEventCreate");
      events_ = true;
    }
    check_cuda(cudaEventRecord(start_), "cudaEventRecord");
#else
    t0_ = std::chrono::steady_clock::now();
#endif
  }
  void end(Phase p) {
    if (!on) return;
#if defined(__CUDACC__)
    check_cuda(cudaEventRecord(stop_), "cudaEventRecord");
    check_cuda(cudaEventSynchronize(stop_), "cudaEventSynchronize");
    float ms = 0;
    check_cuda(cudaEventElapsedTime(&ms, start_, stop_), "cudaEventElapsedTime");
    seconds[p] += 1e-3 * ms;
#else
    seconds[p] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
#endif
    ++calls[p];
  }
  template <class F> void time(Phase p, F&& f) {
    begin();
    f();
    end(p);
  }
  PhaseClock() = default;
  PhaseClock(const PhaseClock&) = delete;
  PhaseClock& operator=(const PhaseClock&) = delete;
  ~PhaseClock() {
#if defined(__CUDACC__)
    if (events_) {
      cudaEventDestroy(start_);
      cudaEventDestroy(stop_);
    }
#endif
  }
  double seconds[Count] = {};
  long calls[Count] = {};

 private:
#if defined(__CUDACC__)
  bool events_ = false;
  cudaEvent_t start_{}, stop_{};
#else
  std::chrono::steady_clock::time_point t0_{};
#endif
};

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND
