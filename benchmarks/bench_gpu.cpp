// Speed of the gpu port on the elastic steel block of bench_reference.cpp (cubic lattice, h = 1.2 dx,
// about 57 neighbours): whole steps of the host build (OpenMP, what this machine can run) in float and
// double, and the phases of a step of the CUDA build timed with CUDA events (skipped without a device).
// Counters: particle_steps_per_s (particles x steps / s; for a phase, particles x calls / s of that
// phase), neighbours (mean within the kernel support), threads.
// Run:  OMP_NUM_THREADS=2 ./build/bench_gpu --benchmark_counters_tabular=true
// BM_ReferenceStep is bench_reference's BM_Step, here so that one run gives the ratio. On a shared machine
// set OMP_WAIT_POLICY=passive and compare the cpu_s_per_step counters (CPU time of all threads) as well
// as the wall time.
#include <benchmark/benchmark.h>
#include <omp.h>
#include <time.h>

#include <cmath>
#include <sstream>

#include "common/case_file.hpp"
#include "common/scene.hpp"
#include "benchmarks/block_scene.hpp"
#include "gpu/solver.hpp"
#include "reference/solver.hpp"

namespace {

using namespace impactsph;

using bench::block;
using bench::side;

// CPU seconds of all threads of the process.
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

void set_counters(benchmark::State& state, std::size_t particles, double neighbours, double cpu_seconds) {
  state.counters["cpu_s_per_step"] = state.iterations() ? cpu_seconds / double(state.iterations()) : 0.0;
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(double(particles) * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["neighbours"] = neighbours;
  state.counters["threads"] = omp_get_max_threads();
  state.counters["particles"] = double(particles);
}

// Whole steps of the host build; the state stays in the solver (copies to the host deferred), as in a run.
template <gpu::Precision P>
void BM_GpuHostStep(benchmark::State& state) {
  Scene scene = block(side(state));
  std::unique_ptr<gpu::GpuStepper> solver = gpu::host::make_solver(scene, P);
  solver->defer_host_copies(true);
  solver->use_cluster_pairs(state.range(2) != 0);
  // The first step uploads, sorts and builds the lists; in a run the sort recurs only when particles have
  // moved half the skin (about every 5-10 steps in an impact, never in this nearly still block).
  solver->step(scene.particles, solver->stable_time_step(scene.particles));
  solver->profile_phases(state.range(1) != 0);
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) {
    const double dt = solver->stable_time_step(scene.particles);
    solver->step(scene.particles, dt);
  }
  for (const gpu::PhaseTime& t : solver->phase_times())
    if (t.calls > 0) state.counters[t.name + "_s_per_call"] = t.seconds / double(t.calls);
  set_counters(state, scene.particles.size(), solver->last_stats().mean_neighbours, process_cpu_seconds() - cpu0);
}

// The reference's whole step on the same block (as BM_Step of bench_reference), for the ratio in one run.
// Its first step (the work arrays' first allocation, the first list) is taken before the clock starts, as
// BM_GpuHostStep's is: a run pays it once, and timed with the others on the 103823 block it put 48 % of a
// profile in the kernel's page clearing and cut the reported rate by about a third (gpu/README.md).
void BM_ReferenceStep(benchmark::State& state) {
  Scene scene = block(side(state));
  reference::ReferenceSolver solver(scene);
  solver.step(scene.particles, solver.stable_time_step(scene.particles));
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) {
    const double dt = solver.stable_time_step(scene.particles);
    solver.step(scene.particles, dt);
  }
  set_counters(state, scene.particles.size(), solver.last_stats().mean_neighbours, process_cpu_seconds() - cpu0);
}

// Phases of a CUDA step (sort and lists, gather, pass 1, pass 2, advance, finish), timed with CUDA events.
template <gpu::Precision P>
void BM_CudaPhases(benchmark::State& state) {
  if (gpu::cuda::device_count() == 0) {
    state.SkipWithError("no CUDA device: the CUDA kernels are not measured on this machine");
    return;
  }
  Scene scene = block(side(state));
  std::unique_ptr<gpu::GpuStepper> solver = gpu::cuda::make_solver(scene, P);
  solver->defer_host_copies(true);
  solver->step(scene.particles, solver->stable_time_step(scene.particles));
  solver->profile_phases(true);
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) {
    const double dt = solver->stable_time_step(scene.particles);
    solver->step(scene.particles, dt);
  }
  for (const gpu::PhaseTime& t : solver->phase_times())
    state.counters[t.name + "_particle_steps_per_s"] =
        t.seconds > 0 ? double(scene.particles.size()) * double(t.calls) / t.seconds : 0.0;
  set_counters(state, scene.particles.size(), solver->last_stats().mean_neighbours, process_cpu_seconds() - cpu0);
}

// Whole steps against the neighbour count: the 8000-particle block at h = h_factor x spacing, the second
// argument h_factor x 100 (1.0 to 2.0, the range a case file allows). Run one thread (OMP_NUM_THREADS=1)
// for the speed per core; benchmarks/speed-vs-neighbours.sh runs them and writes docs/speed/.
template <class MakeSolver>
void step_against_neighbours(benchmark::State& state, MakeSolver make) {
  Scene scene = block(side(state), double(state.range(1)) / 100);
  std::unique_ptr<Stepper> solver = make(scene);
  solver->step(scene.particles, solver->stable_time_step(scene.particles));
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) {
    const double dt = solver->stable_time_step(scene.particles);
    solver->step(scene.particles, dt);
  }
  set_counters(state, scene.particles.size(), solver->last_stats().mean_neighbours, process_cpu_seconds() - cpu0);
}
void BM_NeighboursReference(benchmark::State& state) {
  step_against_neighbours(state, [](const Scene& s) { return std::make_unique<reference::ReferenceSolver>(s); });
}
template <gpu::Precision P>
void BM_NeighboursGpuHost(benchmark::State& state) {
  step_against_neighbours(state, [](const Scene& s) {
    std::unique_ptr<gpu::GpuStepper> g = gpu::host::make_solver(s, P);
    g->defer_host_copies(true);
    return g;
  });
}
void neighbour_args(benchmark::internal::Benchmark* b) {
  for (const int h : {100, 120, 150, 200}) b->Args({8000, h});
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}
BENCHMARK(BM_NeighboursReference)->Apply(neighbour_args);
BENCHMARK_TEMPLATE(BM_NeighboursGpuHost, gpu::Precision::Float)->Apply(neighbour_args);
BENCHMARK_TEMPLATE(BM_NeighboursGpuHost, gpu::Precision::Double)->Apply(neighbour_args);

BENCHMARK(BM_ReferenceStep)->Args({8000, 0})->Args({103823, 0})->Unit(benchmark::kMillisecond)->UseRealTime();
// Second argument 1: also time the phases (host clock), reported as <phase>_s_per_call. Third argument 1:
// both pair passes over cluster pairs in SIMD lanes (gpu/solver_clusters.hpp, the host build's default); 0:
// the rows, entry by entry, as the CUDA kernels take them.
void host_step_args(benchmark::internal::Benchmark* b) {
  for (const int n : {8000, 103823}) b->Args({n, 0, 0})->Args({n, 0, 1})->Args({n, 1, 0})->Args({n, 1, 1});
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}
BENCHMARK_TEMPLATE(BM_GpuHostStep, gpu::Precision::Float)->Apply(host_step_args);
BENCHMARK_TEMPLATE(BM_GpuHostStep, gpu::Precision::Double)->Apply(host_step_args);
BENCHMARK_TEMPLATE(BM_CudaPhases, gpu::Precision::Float)->Arg(103823)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_CudaPhases, gpu::Precision::Double)->Arg(103823)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
