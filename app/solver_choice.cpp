#include "app/solver_choice.hpp"

#include <stdexcept>

#include "gpu/solver.hpp"
#include "reference/solver.hpp"

namespace impactsph {

std::unique_ptr<Stepper> make_stepper(const Scene& scene, const std::string& backend, const std::string& precision,
                                      std::string* note) {
  if (precision != "double" && precision != "float")
    throw std::runtime_error("--precision " + precision + ": expected double or float");
  if (backend == "reference") {
    if (precision != "double")
      throw std::runtime_error("--precision " + precision + ": the reference solver runs in double only (use --backend gpu)");
    return std::make_unique<reference::ReferenceSolver>(scene);
  }
  if (backend != "gpu") throw std::runtime_error("--backend " + backend + ": expected reference or gpu");
  std::string which;
  std::unique_ptr<gpu::GpuStepper> s =
      gpu::make_solver(scene, precision == "float" ? gpu::Precision::Float : gpu::Precision::Double, &which);
  if (note) *note = which;
  s->defer_host_copies(true);  // the driver calls copy_to_host before it reads the particles
  return s;
}

bool solver_is(const std::string& solver_name, const std::string& backend, const std::string& precision) {
  const std::string prefix = backend == "reference" ? "reference (" + precision : "gpu port (" + precision;
  return solver_name.rfind(prefix, 0) == 0;
}

}  // namespace impactsph
