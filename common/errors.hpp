// Errors a user can act on (host only). A CaseError names the file, the line (0 when unknown), the key
// and says what would be valid; the CLI prints it as `file:line: key: message` and exits with status 2.
#pragma once
#include <sstream>
#include <stdexcept>
#include <string>

namespace impactsph {

class CaseError : public std::runtime_error {
 public:
  CaseError(std::string file, int line, std::string key, const std::string& message)
      : std::runtime_error(format(file, line, key, message)), file_(std::move(file)), line_(line), key_(std::move(key)) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& key, const std::string& message) {
    std::string s = file.empty() ? std::string("<case>") : file;
    if (line > 0) s += ":" + std::to_string(line);
    s += ": ";
    if (!key.empty()) s += key + ": ";
    return s + message;
  }
  std::string file_;
  int line_;
  std::string key_;
};

// A run that cannot go on (NaN, time-step collapse, energy blow-up); the message names the particle and
// the offending fields. The last good state has been written before this is thrown.
class DivergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The error of a step that left particle `index` (its index in the scene, of body `body`) with a non-finite
// state or a non-positive density: its position (m), velocity (m/s), density (kg/m^3), specific energy
// (J/kg) and von Mises stress (Pa), and what to try. Both solvers throw it (state_is_finite, stages.hpp).
inline DivergenceError particle_diverged(double dt, long long index, const std::string& body, const double (&x)[3],
                                         const double (&v)[3], double rho, double energy, double von_mises) {
  std::ostringstream msg;
  msg.precision(6);
  msg << "the solution diverged in the step of dt = " << dt << " s at particle " << index << " of body '" << body
      << "': position (" << x[0] << ", " << x[1] << ", " << x[2] << ") m, velocity (" << v[0] << ", " << v[1] << ", "
      << v[2] << ") m/s, density " << rho << " kg/m^3, specific energy " << energy << " J/kg, von Mises " << von_mises
      << " Pa. Try a smaller numerics.cfl or larger viscosity coefficients.";
  return DivergenceError(msg.str());
}

}  // namespace impactsph
