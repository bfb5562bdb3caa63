// Google Benchmark of the neighbour search and the two pair-sum stages on the dambreak water, 1
// and 2 threads, on two states after 600 steps (the column has fallen and the water sloshes, so
// neighbour counts and memory order are those of a real run): `regular` (20,000 L0 particles)
// and `gaze` (the mixed L0/L1 set the gaze method holds at that instant, replaying the
// scene's own recording). Both run in one process, so their ratio, the one the gaze method's
// speed-up depends on, is measured under the same machine load. The pair stages run in their
// scalar and their vector (AVX-512) form.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <map>
#include <memory>
#include <string>

#include "bench/bench_run.h"
#include "process/omp_wait.h"
#include "scene/scene_loader.h"
#include "sph/simulation.h"
#include "sph/solvers/thesis/thesis_stages.h"
#include "warm_run.h"

namespace {

constexpr int kWarmSteps = 600;

const sph::Simulation& warmState(const std::string& method) {
  static std::map<std::string, std::unique_ptr<bench::SceneRun>> runs;
  auto& run = runs[method];
  if (!run) run = bench::warmRun("dambreak", "", method, kWarmSteps);
  return run->simulation();
}

// Second argument: which state.
const sph::Simulation& stateOf(const benchmark::State& state) {
  return warmState(state.range(1) == 0 ? "regular" : "gaze");
}

void stateArgs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"threads", "gaze"});
  for (int threads : {1, 2}) {
    for (int gaze : {0, 1}) b->Args({threads, gaze});
  }
  b->Unit(benchmark::kMillisecond);
}

// A pass of the neighbour grid over the warmed state: the whole search (build) or its binning.
template <void (sph::NeighborGrid::*Pass)(const sph::ParticleSet&)>
void BM_GridPass(benchmark::State& state) {
  const sph::Simulation& sim = stateOf(state);  // first: warming sets its own thread count
  omp_set_num_threads(static_cast<int>(state.range(0)));
  sph::NeighborGrid grid = sim.grid();
  for (auto _ : state) {
    (grid.*Pass)(sim.particles());
    benchmark::ClobberMemory();
  }
  state.counters["particles"] = static_cast<double>(sim.particles().size());
  state.counters["mean_neighbors"] = grid.meanNeighbors();
  state.counters["cells"] = static_cast<double>(grid.cellCount());
}
BENCHMARK(BM_GridPass<&sph::NeighborGrid::build>)->Name("BM_NeighborSearch")->Apply(stateArgs);
BENCHMARK(BM_GridPass<&sph::NeighborGrid::bin>)->Name("BM_Bin")->Apply(stateArgs);

using DensityStage = void (*)(const sph::SimParams&, const sph::KernelTable&, const sph::NeighborGrid&,
                              sph::ParticleSet&);
using ForceStage = void (*)(const sph::SimParams&, const sph::KernelTable&, const sph::NeighborGrid&, sph::ParticleSet&,
                            bool);

// One of the thesis's pair stages over the warmed state's particles and lists.
template <DensityStage Stage>
void BM_PairStage(benchmark::State& state) {
  const sph::Simulation& sim = stateOf(state);  // first: warming sets its own thread count
  omp_set_num_threads(static_cast<int>(state.range(0)));
  sph::ParticleSet particles = sim.particles();
  const sph::KernelTable kernels = sph::makeKernelTable(sim.params());
  for (auto _ : state) {
    Stage(sim.params(), kernels, sim.grid(), particles);
    benchmark::ClobberMemory();
  }
  state.counters["pairs"] = static_cast<double>(sim.grid().meanNeighbors() * particles.size());
  state.counters["stride"] = static_cast<double>(sim.grid().stride());
}

// The force stage as a pair stage: without the surface distance's hop.
template <ForceStage Stage>
void forcesOnly(const sph::SimParams& params, const sph::KernelTable& kernels, const sph::NeighborGrid& grid,
                sph::ParticleSet& particles) {
  Stage(params, kernels, grid, particles, false);
}

BENCHMARK(BM_PairStage<sph::scalar::computeDensityPressure>)->Name("BM_Density/scalar")->Apply(stateArgs);
BENCHMARK(BM_PairStage<sph::computeDensityPressure>)->Name("BM_Density/dispatched")->Apply(stateArgs);
BENCHMARK(BM_PairStage<forcesOnly<sph::scalar::computeAccelerations>>)->Name("BM_Forces/scalar")->Apply(stateArgs);
BENCHMARK(BM_PairStage<forcesOnly<sph::computeAccelerations>>)->Name("BM_Forces/dispatched")->Apply(stateArgs);

void BM_FullStep(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  sph::Simulation sim(scene::loadScene("dambreak"), sph::Level{0});
  for (auto _ : state) sim.step();
  state.counters["particles"] = static_cast<double>(sim.particles().size());
}
BENCHMARK(BM_FullStep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  process::applyDefaultOmpWaitPolicy(argv);  // first: it may re-execute the program
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
