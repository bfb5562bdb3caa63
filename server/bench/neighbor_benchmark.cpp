// Google Benchmark of the neighbour search and the two pair-sum stages on the dambreak water
// (20,000 SMALL particles), 1 and 2 threads. The stages run on the state after 150 steps (the
// column has fallen and spread, so neighbour counts and memory order are those of a real run),
// each in its scalar and its vector (AVX-512) form in the same process, so their ratio is
// measured against the same machine load.
#include <benchmark/benchmark.h>
#include <omp.h>

#include "scene/scene_loader.h"
#include "sph/simulation.h"

namespace {

constexpr int kWarmSteps = 145;

sph::Simulation& dambreakRegular() {
  static sph::Simulation sim = [] {
    sph::Simulation s(scene::loadScene("dambreak"), sph::SizeClass::Small);
    for (int k = 0; k < kWarmSteps; ++k) s.step();
    return s;
  }();
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

using DensityStage = void (*)(const sph::SimParams&, const sph::KernelTable&, const sph::NeighborGrid&,
                              sph::ParticleSet&);
using ForceStage = void (*)(const sph::SimParams&, const sph::KernelTable&, const sph::NeighborGrid&,
                            sph::ParticleSet&, bool);

template <DensityStage Stage>
void BM_Density(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  sph::Simulation& sim = dambreakRegular();
  sph::ParticleSet particles = sim.particles();
  for (auto _ : state) {
    Stage(sim.params(), sim.kernels(), sim.grid(), particles);
    benchmark::ClobberMemory();
  }
  state.counters["pairs"] = static_cast<double>(sim.grid().meanNeighbors() * particles.size());
  state.counters["stride"] = static_cast<double>(sim.grid().stride());
}
BENCHMARK(BM_Density<sph::scalar::computeDensityPressure>)->Name("BM_Density/scalar")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Density<sph::computeDensityPressure>)->Name("BM_Density/dispatched")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

template <ForceStage Stage>
void BM_Forces(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  sph::Simulation& sim = dambreakRegular();
  sph::ParticleSet particles = sim.particles();
  for (auto _ : state) {
    Stage(sim.params(), sim.kernels(), sim.grid(), particles, false);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_Forces<sph::scalar::computeAccelerations>)->Name("BM_Forces/scalar")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Forces<sph::computeAccelerations>)->Name("BM_Forces/dispatched")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_FullStep(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  sph::Simulation sim(scene::loadScene("dambreak"), sph::SizeClass::Small);
  for (auto _ : state) sim.step();
  state.counters["particles"] = static_cast<double>(sim.particles().size());
}
BENCHMARK(BM_FullStep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
