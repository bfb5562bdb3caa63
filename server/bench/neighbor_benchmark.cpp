// Google Benchmark of the neighbour search and the two fluid passes on the dambreak water
// (20,000 SMALL particles at rest on their start lattice), 1 and 2 threads.
#include <benchmark/benchmark.h>
#include <omp.h>

#include "scene/scene_loader.h"
#include "sph/simulation.h"

namespace {

sph::Simulation& dambreakRegular() {
  static sph::Simulation sim(scene::loadScene("dambreak"), sph::SizeClass::Small);
  return sim;
}

void BM_NeighborSearch(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  sph::Simulation& sim = dambreakRegular();
  sph::NeighborGrid grid = sim.grid();
  for (auto _ : state) {
    grid.build(sim.particles());
    benchmark::ClobberMemory();
  }
  state.counters["particles"] = static_cast<double>(sim.particles().size());
  state.counters["mean_neighbors"] = grid.meanNeighbors();
}
BENCHMARK(BM_NeighborSearch)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_FullStep(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  sph::Simulation sim(scene::loadScene("dambreak"), sph::SizeClass::Small);
  for (auto _ : state) sim.step();
  state.counters["particles"] = static_cast<double>(sim.particles().size());
}
BENCHMARK(BM_FullStep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
