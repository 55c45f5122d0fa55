// Host-side particle storage shared by both solvers: structure of arrays, SI units, double precision.
// The scene builder fills it, a solver advances it, observers and writers read it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/tensor.hpp"

namespace impactsph {

using Vec3d = Vec3<double>;
using Sym3d = Sym3<double>;
using Mat3d = Mat3<double>;

struct ParticleSet {
  std::vector<Vec3d> pos;             // m
  std::vector<Vec3d> vel;             // m/s
  std::vector<double> mass;           // kg, constant
  std::vector<double> rho;            // kg/m^3
  std::vector<double> energy;         // specific internal energy e, J/kg
  std::vector<double> pressure;       // Pa, from the EOS (derived, kept for output)
  std::vector<double> h;              // smoothing length, m
  std::vector<Sym3d> dev_stress;      // deviatoric stress S, Pa
  std::vector<double> plastic_strain; // equivalent plastic strain
  std::vector<double> plastic_work;   // plastic work per unit mass, sum sigma_y d eps_p / rho, J/kg
  std::vector<double> damage;         // D in [0, 1]
  std::vector<double> temperature;    // K, raised by plastic work (F 3.14)
  std::vector<double> bulking_pressure; // Pa, JH-2 bulking increment dP (X eq 28); 0 for other materials
  std::vector<std::int32_t> body;     // index into Scene::bodies
  std::vector<std::int32_t> material; // index into Scene::materials
  std::vector<std::uint8_t> fixed;    // 1: clamped (velocity held at zero)

  std::size_t size() const { return pos.size(); }
  void resize(std::size_t n) {
    pos.resize(n); vel.resize(n); mass.resize(n); rho.resize(n); energy.resize(n); pressure.resize(n);
    h.resize(n); dev_stress.resize(n); plastic_strain.resize(n); plastic_work.resize(n); damage.resize(n);
    temperature.resize(n); bulking_pressure.resize(n); body.resize(n);
    material.resize(n); fixed.resize(n);
  }
};

}  // namespace impactsph
