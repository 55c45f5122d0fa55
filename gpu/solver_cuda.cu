// The CUDA build of the gpu port: the same sources as solver_host.cpp, compiled by nvcc for the device.
#define IMPACTSPH_GPU_BACKEND cuda
#include "gpu/solver_impl.hpp"

namespace impactsph::gpu::cuda {

int device_count() {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess) {
    (void)cudaGetLastError();  // clear the error: no driver or no device means "none"
    return 0;
  }
  return count;
}

std::unique_ptr<GpuStepper> make_solver(const Scene& scene, Precision precision) {
  return make_solver_for(scene, precision, "CUDA");
}

}  // namespace impactsph::gpu::cuda
