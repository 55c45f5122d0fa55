// The gpu port of the solver (issue 5; design.md, gpu/). One set of sources, built twice:
//   * for CUDA devices with nvcc (namespace cuda), when the toolkit is found (IMPACTSPH_CUDA);
//   * for the host with the C++ compiler, kernels as OpenMP loops and Thrust's OMP system for sort, scan
//     and reductions (namespace host). This build is what CI runs and what cross-checks the reference.
// Both are templated on the precision: double for cross-checks, float for production (positions stay in
// double). See gpu/README.md for the data layout and the performance note.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "common/scene.hpp"
#include "common/stepper.hpp"

namespace impactsph::gpu {

enum class Precision { Double, Float };
inline const char* precision_name(Precision p) { return p == Precision::Double ? "double" : "float"; }

// Time spent in one phase of the step since profiling was switched on (CUDA events on the device, the
// steady clock in the host build).
struct PhaseTime {
  std::string name;
  long calls = 0;
  double seconds = 0;
};

// The interface of a gpu solver beyond Stepper.
class GpuStepper : public Stepper {
 public:
  // Particles stay in device memory between steps. By default every step copies the state back into the
  // ParticleSet it was given; with deferred copies it does so only in copy_to_host (the run driver calls
  // that before reading the particles, so the host only launches and copies back for output).
  virtual void defer_host_copies(bool defer) = 0;
  void copy_to_host(ParticleSet& p) override = 0;
  // How many times the particles were sorted by cell (and their neighbour lists rebuilt).
  virtual long sorts() const = 0;
  // Per-phase timing (sort, time_step, gather, pass1, pass2, advance, check, finish); off by default, since
  // on the device it synchronises after each phase.
  virtual void profile_phases(bool on) = 0;
  virtual std::vector<PhaseTime> phase_times() const = 0;
  // The host build sums the SPH pairs of both passes over cluster pairs in SIMD lanes (gpu/solver_clusters.hpp),
  // the default; with false it takes each row's list entries in turn, as the CUDA kernels do. The CUDA build
  // has the rows only.
  virtual void use_cluster_pairs(bool) {}
};

namespace host {
std::unique_ptr<GpuStepper> make_solver(const Scene& scene, Precision precision);
}
namespace cuda {
// Number of CUDA devices the runtime sees (0 with no driver or no device).
int device_count();
std::unique_ptr<GpuStepper> make_solver(const Scene& scene, Precision precision);
}  // namespace cuda

// True when this program was built with the CUDA port (nvcc found at configure time).
bool cuda_built();
// The CUDA build when it is built and a device is present, else the host build; `note` (if given) gets
// one line saying which when it falls back to the host build, and stays empty otherwise.
std::unique_ptr<GpuStepper> make_solver(const Scene& scene, Precision precision, std::string* note = nullptr);

}  // namespace impactsph::gpu
