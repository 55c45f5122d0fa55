// The host build of the gpu port: kernels as OpenMP loops, Thrust's OMP system for sort, scan and
// reductions (THRUST_DEVICE_SYSTEM=OMP, set by gpu/CMakeLists.txt). This is what CI runs.
#define IMPACTSPH_GPU_BACKEND host
#include "gpu/solver_impl.hpp"

namespace impactsph::gpu::host {

std::unique_ptr<GpuStepper> make_solver(const Scene& scene, Precision precision) {
  return make_solver_for(scene, precision, "host OpenMP build");
}

}  // namespace impactsph::gpu::host
