// The solver a command runs: --backend reference|gpu and --precision double|float, shared by run and
// ballistic-limit. Host only.
#pragma once
#include <memory>
#include <string>

#include "common/scene.hpp"
#include "common/stepper.hpp"

namespace impactsph {

// Throws std::runtime_error for a backend or precision that does not exist, or a float reference.
void check_solver_choice(const std::string& backend, const std::string& precision);

// The reference (double only) or the gpu port (its CUDA build when a device is present, else its host
// build; `note` receives the line that says which, when not null). Throws std::runtime_error for a
// backend or precision that does not exist or a float reference.
std::unique_ptr<Stepper> make_stepper(const Scene& scene, const std::string& backend, const std::string& precision,
                                      std::string* note = nullptr);

// True when a run's summary.json `solver` (Stepper::name()) is what backend and precision make.
bool solver_is(const std::string& solver_name, const std::string& backend, const std::string& precision);

}  // namespace impactsph
