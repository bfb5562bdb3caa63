#include "sph/solvers/thesis_solver.h"

#include <chrono>

#include "sph/solvers/dfsph_solver.h"
#include "sph/solvers/pbf_solver.h"

namespace sph {

namespace {
double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

ThesisSolver::ThesisSolver(const Scene& scene) : kernels_(makeKernelTable(scene.params)) {}

void ThesisSolver::advance(const FrameContext& f) {
  auto t = std::chrono::steady_clock::now();
  f.grid.build(f.particles);
  f.timings.neighbor_ms += msSince(t);

  t = std::chrono::steady_clock::now();
  computeDensityPressure(f.scene.params, kernels_, f.grid, f.particles);
  f.timings.density_pressure_ms += msSince(t);

  t = std::chrono::steady_clock::now();
  computeAccelerations(f.scene.params, kernels_, f.grid, f.particles, f.track_surface_distance);
  integrateAndCollide(f.scene.params, f.scene.boundary, f.scene.boundary.stateAt(f.time + f.dt), f.particles);
  f.timings.accel_integrate_collide_ms += msSince(t);
}

std::unique_ptr<FluidSolver> makeFluidSolver(const Scene& scene) {
  switch (scene.params.solver) {
    case Solver::kPbf:
      return std::make_unique<PbfSolver>(scene);
    case Solver::kDfsph:
      return std::make_unique<DfsphSolver>(scene);
    case Solver::kThesis:
      break;
  }
  return std::make_unique<ThesisSolver>(scene);
}

}  // namespace sph
