// Reference solver speed on an elastic steel block on a cubic lattice, h = 1.2 dx (about 57 neighbours
// with the Wendland support 2h). Counters: particle_steps_per_s (particles x steps / wall s; for the
// search and the evaluation it counts one call as a step), neighbours (mean per particle), threads.
// Run:  ./build/bench_reference --benchmark_counters_tabular=true
// Threads come from OMP_NUM_THREADS (default: all cores).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <random>
#include <sstream>

#include "common/case_file.hpp"
#include "common/scene.hpp"
#include "benchmarks/block_scene.hpp"
#include "reference/neighbours.hpp"
#include "reference/solver.hpp"

namespace {

using namespace impactsph;

using bench::block;
using bench::side;

void set_counters(benchmark::State& state, std::size_t particles, double neighbours) {
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(double(particles) * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["neighbours"] = neighbours;
  state.counters["threads"] = omp_get_max_threads();
  state.counters["particles"] = double(particles);
}

void BM_NeighbourSearch(benchmark::State& state) {
  Scene scene = block(side(state));
  reference::NeighbourList list;
  const double radius = 2 * scene.particles.h[0];
  for (auto _ : state) {
    reference::build_neighbour_list(scene.particles.pos, scene.particles.size(), radius, list);
    benchmark::DoNotOptimize(list.indices.data());
  }
  set_counters(state, scene.particles.size(), list.mean_count());
}

// Neighbour search plus one evaluation of the rates (ghosts, EOS, pass 1, stress rate, pass 2).
void BM_Evaluation(benchmark::State& state) {
  Scene scene = block(side(state));
  reference::ReferenceSolver solver(scene);
  std::vector<Mat3d> grad;
  for (auto _ : state) {
    solver.velocity_gradients(scene.particles, grad);
    benchmark::DoNotOptimize(grad.data());
  }
  set_counters(state, scene.particles.size(), solver.last_stats().mean_neighbours);
}

// A whole step: time step, neighbour search and two evaluations of the midpoint scheme.
void BM_Step(benchmark::State& state) {
  Scene scene = block(side(state));
  reference::ReferenceSolver solver(scene);
  solver.step(scene.particles, solver.stable_time_step(scene.particles));  // first allocations and list, untimed
  for (auto _ : state) {
    const double dt = solver.stable_time_step(scene.particles);
    solver.step(scene.particles, dt);
  }
  set_counters(state, scene.particles.size(), solver.last_stats().mean_neighbours);
}

// 46^3 = 97336 and 47^3 = 103823: the 100k-particle block of the issue; 20^3 for a quick look.
BENCHMARK(BM_NeighbourSearch)->Arg(8000)->Arg(103823)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Evaluation)->Arg(8000)->Arg(103823)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Step)->Arg(8000)->Arg(103823)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
