#include "app/solver_choice.hpp"

#include <stdexcept>

#include "gpu/solver.hpp"
#include "reference/solver.hpp"

namespace impactsph {

void check_solver_choice(const std::string& backend, const std::string& precision) {
  if (backend != "reference" && backend != "gpu")
    throw std::runtime_error("--backend " + backend + ": expected reference or gpu");
  if (precision != "double" && precision != "float")
    throw std::runtime_error("--precision " + precision + ": expected double or float");
  if (backend == "reference" && precision != "double")
    throw std::runtime_error("--precision " + precision + ": the reference solver runs in double only (use --backend gpu)");
}

std::unique_ptr<Stepper> make_stepper(const Scene& scene, const std::string& backend, const std::string& precision,
                                      std::string* note) {
  check_solver_choice(backend, precision);
  if (backend == "reference") return std::make_unique<reference::ReferenceSolver>(scene);
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
