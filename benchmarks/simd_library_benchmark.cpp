// Google Benchmark of one pass family, pbf's two pair passes (pbf_passes.inc), in the library's
// hand-written forms (scalar, AVX2 and AVX-512 lane types, through pbfPassForms()) against the
// same source on a lane type over Google Highway (simd_library/pbf_passes_hwy.h), at each
// Highway target this CPU runs: the measurement behind simd_level.h's choice of lane types
// (docs/performance.md, "Portable SIMD library"). 1 thread, on the dam break's pbf water after
// 600 frames: `regular` (20,000 L0 particles) and `foveated` (the mixed set that method holds
// then). Before timing, every form's results are checked against the scalar form's, to the
// tolerance the unit tier gives the forms (tests/sph/vector_stages_test.cpp): a form that
// computes something else is not timed.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_run.h"
#include "process/omp_wait.h"
#include "simd_library/pbf_passes_hwy.h"
#include "sph/simd/simd_level.h"
#include "sph/solvers/incompressible_setup.h"
#include "sph/solvers/local_placement.h"
#include "sph/solvers/pbf/pbf_passes.h"
#include "warm_run.h"

namespace {

constexpr int kWarmFrames = 600;

// A warmed state and the pbf passes' inputs over it, with its own outputs.
struct PbfState {
  std::unique_ptr<bench::SceneRun> run;
  sph::ParticleSet particles;
  sph::IncompressibleSetup setup;
  sph::PbfConstants constants;
  std::vector<float> lambda, lambda_step;
  std::vector<sph::Vec3> wall_grad, next;

  explicit PbfState(const std::string& method) {
    run = bench::warmRun("dambreak", "pbf", method, kWarmFrames);
    const sph::Simulation& sim = run->simulation();
    particles = sim.particles();
    setup = sph::makeIncompressibleSetup(sim.scene());
    constants = sph::pbfConstantsOf(sim.params(), setup);
    constants.box = sim.boxNow();
    constants.obstacles = &sim.scene().boundary;
  }
  const sph::NeighborGrid& grid() const { return run->simulation().grid(); }

  sph::PbfArrays arrays() {
    sph::PbfArrays a = sph::pbfArraysOf(particles, lambda, lambda_step, wall_grad);
    a.position = particles.position.data()->data();
    a.position_next = next.data()->data();
    return a;
  }
  // Fresh multipliers, then the lambda pass and the correction pass (with the artificial
  // pressure, as a step's first correction runs) of `forms`; the results stay here.
  void runBoth(const sph::PbfPassForms& forms) {
    const std::size_t n = particles.size();
    lambda.assign(n, 0.0f);
    lambda_step.assign(n, 0.0f);
    wall_grad.assign(n, sph::Vec3::Zero());
    next.assign(n, sph::Vec3::Zero());
    const sph::PbfArrays a = arrays();
    forms.lambda(a, constants, grid());
    forms.correct(a, constants, grid(), true);
  }
};

PbfState& stateOf(const std::string& method) {
  static std::map<std::string, std::unique_ptr<PbfState>> states;
  auto& s = states[method];
  if (!s) s = std::make_unique<PbfState>(method);
  return *s;
}

struct Form {
  std::string name;
  sph::PbfPassForms forms;
};

// The forms to time: the library's (those this CPU runs), then Highway's.
std::vector<Form> formsOnThisCpu() {
  std::vector<Form> out{{"scalar", sph::scalar::pbfPassForms()}};
  if (sph::simdAvailable(sph::SimdLevel::kAvx2)) out.push_back({"avx2", sph::avx2::pbfPassForms()});
  if (sph::simdAvailable(sph::SimdLevel::kAvx512)) out.push_back({"avx512", sph::avx512::pbfPassForms()});
  for (const auto& t : sph::hwy_form::targetsOnThisCpu()) out.push_back({std::string("hwy_") + t.name, t.forms});
  out.push_back({"hwy_dispatched", sph::hwy_form::dispatchedForms()});
  return out;
}

// Whether `form` gives the scalar form's density (relative 1e-5, the unit tier's tolerance for
// the forms' densities), lambda (1e-5 of l_c, the lambda of a full neighbourhood at C = 1: the
// same tolerance on the constraint C = rho / rho0 - 1) and moves (1e-5 of the particle spacing).
// Relative to lambda or the move themselves the forms differ by more: C is a difference of nearly
// equal numbers, so its rounding is all of a resting particle's lambda. Prints the worst.
bool matchesScalar(PbfState& s, const Form& form) {
  s.runBoth(sph::scalar::pbfPassForms());
  const std::vector<float> density(s.particles.density), lambda(s.lambda);
  const std::vector<sph::Vec3> next(s.next);
  s.runBoth(form.forms);
  const double lambda_scale = std::abs(s.constants.lambda_scale[0]);
  const double spacing = s.setup.spacing[0];
  double worst_density = 0.0, worst_lambda = 0.0, worst_move = 0.0;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    worst_density = std::max(worst_density, std::abs(s.particles.density[i] - density[i]) / double(density[i]));
    worst_lambda = std::max(worst_lambda, std::abs(s.lambda[i] - lambda[i]) / lambda_scale);
    worst_move = std::max(worst_move, (s.next[i] - next[i]).norm() / spacing);
  }
  std::printf("%-16s against scalar, worst particle: density %.1e, lambda %.1e l_c, move %.1e spacings\n",
              form.name.c_str(), worst_density, worst_lambda, worst_move);
  return worst_density <= 1e-5 && worst_lambda <= 1e-5 && worst_move <= 1e-5;
}

void BM_Lambda(benchmark::State& state, std::string method, sph::PbfPassForms forms) {
  PbfState& s = stateOf(method);
  omp_set_num_threads(1);
  s.runBoth(sph::scalar::pbfPassForms());
  const sph::PbfArrays a = s.arrays();
  for (auto _ : state) {
    forms.lambda(a, s.constants, s.grid());
    benchmark::ClobberMemory();
  }
  state.counters["particles"] = static_cast<double>(s.particles.size());
  state.counters["mean_neighbors"] = s.grid().meanNeighbors();
}

void BM_Correct(benchmark::State& state, std::string method, sph::PbfPassForms forms) {
  PbfState& s = stateOf(method);
  omp_set_num_threads(1);
  s.runBoth(sph::scalar::pbfPassForms());  // every form corrects by the same lambda_step
  const sph::PbfArrays a = s.arrays();
  for (auto _ : state) {
    forms.correct(a, s.constants, s.grid(), true);
    benchmark::ClobberMemory();
  }
}

}  // namespace

int main(int argc, char** argv) {
  process::applyDefaultOmpWaitPolicy(argv);  // first: it may re-execute the program
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  bool all_match = true;
  for (const std::string& method : std::vector<std::string>{"regular", "foveated"}) {
    for (const Form& form : formsOnThisCpu()) {
      if (!matchesScalar(stateOf(method), form)) {
        std::printf("%s: %s does not match the scalar form: not timed\n", method.c_str(), form.name.c_str());
        all_match = false;
        continue;
      }
      benchmark::RegisterBenchmark(("BM_Lambda/" + method + "/" + form.name).c_str(), BM_Lambda, method, form.forms)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("BM_Correct/" + method + "/" + form.name).c_str(), BM_Correct, method, form.forms)
          ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return all_match ? 0 : 1;
}
