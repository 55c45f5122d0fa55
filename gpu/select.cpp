// Which build of the gpu port runs: CUDA when it is built and a device is present, else the host build.
#include "gpu/solver.hpp"

#include <stdexcept>

namespace impactsph::gpu {

bool cuda_built() {
#ifdef IMPACTSPH_WITH_CUDA
  return true;
#else
  return false;
#endif
}

#ifndef IMPACTSPH_WITH_CUDA
namespace cuda {
int device_count() { return 0; }
std::unique_ptr<GpuStepper> make_solver(const Scene&, Precision) {
  throw std::runtime_error("this program was built without the CUDA port (nvcc was not found)");
}
}  // namespace cuda
#endif

std::unique_ptr<GpuStepper> make_solver(const Scene& scene, Precision precision, std::string* note) {
  if (note) note->clear();
  if (cuda::device_count() > 0) return cuda::make_solver(scene, precision);
  if (note)
    *note = cuda_built() ? "no CUDA device found: --backend gpu runs the host (OpenMP) build of the gpu port"
                         : "built without CUDA: --backend gpu runs the host (OpenMP) build of the gpu port";
  return host::make_solver(scene, precision);
}

}  // namespace impactsph::gpu
