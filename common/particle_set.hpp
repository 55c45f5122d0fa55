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

// Every per-particle array of a ParticleSet, once: X(member, vtu_name, kind) in the checkpoint's order.
// vtu_name is the array's name in the VTU frames ("" for one written otherwise: the positions are the
// points, the stress is written as its von Mises value); kind says how the gpu port keeps it:
//   Position: double in both precisions;  Evolving: the port's precision, copied back to the host;
//   Constant: never changed by a step (not copied back).
// A new field is one line here, its comment in ParticleSet, and the code that gives it a meaning: resize,
// the checkpoint, the VTU frames and the port's upload, download and permute take it from this list.
#define IMPACTSPH_PARTICLE_FIELDS(X)                        \
  X(pos, "", Position)                                      \
  X(vel, "velocity", Evolving)                              \
  X(mass, "mass", Constant)                                 \
  X(rho, "density", Evolving)                               \
  X(energy, "internal_energy", Evolving)                    \
  X(pressure, "pressure", Evolving)                         \
  X(h, "smoothing_length", Evolving)                        \
  X(dev_stress, "", Evolving)                               \
  X(plastic_strain, "plastic_strain", Evolving)             \
  X(plastic_work, "plastic_work", Evolving)                 \
  X(damage, "damage", Evolving)                             \
  X(temperature, "temperature", Evolving)                   \
  X(bulking_pressure, "bulking_pressure", Evolving)         \
  X(acceleration, "", Evolving)                             \
  X(energy_rate, "", Evolving)                              \
  X(density_diffusion, "", Evolving)                        \
  X(density_diffusion_before, "", Evolving)                 \
  X(contact_power, "", Evolving)                            \
  X(body, "body_id", Constant)                              \
  X(material, "material_id", Constant)                      \
  X(fixed, "fixed", Constant)

enum class FieldKind { Position, Evolving, Constant };

// What for_each_field tells of a field besides its array.
struct FieldInfo {
  const char* name;      // the member's name
  const char* vtu_name;  // "" when the VTU frames write it otherwise
  FieldKind kind;
};

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
  // The rates of the last evaluation, which the leapfrog carries into the first kick of the next step
  // (common/stages.hpp, "Leapfrog"); meaningful where rates_current.
  std::vector<Vec3d> acceleration;    // dv/dt, m/s^2
  std::vector<double> energy_rate;    // de/dt, J/kg/s
  std::vector<double> density_diffusion;  // the delta-SPH diffusion's share of drho/dt, kg/m^3/s
  std::vector<double> density_diffusion_before;  // the same of the evaluation before, kg/m^3/s
  std::vector<double> contact_power;  // power the particle's penalty pairs take from the motion, W
  std::vector<std::int32_t> body;     // index into Scene::bodies
  std::vector<std::int32_t> material; // index into Scene::materials
  std::vector<std::uint8_t> fixed;    // 1: clamped (velocity held at zero)
  // Whether acceleration .. contact_power are the rates of the current state's last evaluation
  // (a leapfrog step sets it; a scene as built, or a state changed by hand, has none and the next step
  // evaluates first).
  bool rates_current = false;

  std::size_t size() const { return pos.size(); }
  void resize(std::size_t n);
};

// f(info, array) for every field of a ParticleSet, or of any set with the same members (the gpu port's
// device arrays), in the order of IMPACTSPH_PARTICLE_FIELDS.
template <class Set, class F> void for_each_field(Set& p, F&& f) {
#define IMPACTSPH_VISIT_FIELD(member, vtu, kind) f(FieldInfo{#member, vtu, FieldKind::kind}, p.member);
  IMPACTSPH_PARTICLE_FIELDS(IMPACTSPH_VISIT_FIELD)
#undef IMPACTSPH_VISIT_FIELD
}

// f(info, a_array, b_array) for every field of two sets, in the same order.
template <class A, class B, class F> void for_each_field_pair(A& a, B& b, F&& f) {
#define IMPACTSPH_VISIT_FIELD_PAIR(member, vtu, kind) f(FieldInfo{#member, vtu, FieldKind::kind}, a.member, b.member);
  IMPACTSPH_PARTICLE_FIELDS(IMPACTSPH_VISIT_FIELD_PAIR)
#undef IMPACTSPH_VISIT_FIELD_PAIR
}

inline void ParticleSet::resize(std::size_t n) {
  for_each_field(*this, [n](const FieldInfo&, auto& a) { a.resize(n); });
}

}  // namespace impactsph
