// The benchmark scene shared by the reference and gpu-port benchmarks: a steel cube at 1 mm spacing.
#pragma once
#include <benchmark/benchmark.h>

#include <cmath>
#include <sstream>

#include "common/case_file.hpp"
#include "common/scene.hpp"

namespace impactsph::bench {

// A cube of n^3 particles at 1 mm with a small smooth velocity field so every term is exercised; h =
// h_factor x spacing sets the neighbour count (about 49 at 1.2 in the 8000-particle block, 53 at 103823).
inline Scene block(int n, double h_factor = 1.2) {
  std::ostringstream toml;
  toml << "[case]\nname = \"block\"\n"
          "[materials.steel]\ndensity = \"7850 kg/m^3\"\n"
          "eos = { kind = \"linear\", bulk_modulus = \"196 GPa\" }\n"
          "strength = { kind = \"elastic\", shear_modulus = \"75 GPa\" }\n"
          "[[bodies]]\nname = \"block\"\nmaterial = \"steel\"\nshape = \"box\"\n"
          "min = [\"0 mm\", \"0 mm\", \"0 mm\"]\nmax = [\""
       << n << " mm\", \"" << n << " mm\", \"" << n
       << " mm\"]\n[numerics]\nspacing = \"1 mm\"\nh_factor = " << h_factor << "\n[time]\nend = \"1 us\"\noutput_interval = \"1 us\"\n";
  Scene scene = build_scene(parse_case_string(toml.str(), "benchmark-block.toml"));
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const Vec3d& x = scene.particles.pos[i];
    scene.particles.vel[i] = Vec3d{std::sin(300 * x.y), std::cos(200 * x.z), std::sin(250 * x.x)};
  }
  return scene;
}

inline int side(const benchmark::State& state) { return static_cast<int>(std::lround(std::cbrt(double(state.range(0))))); }

}  // namespace impactsph::bench
