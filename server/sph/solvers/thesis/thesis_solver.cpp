#include "sph/solvers/thesis/thesis_solver.h"

#include "sph/phase_timer.h"

namespace sph {

ThesisSolver::ThesisSolver(const Scene& scene) : kernels_(makeKernelTable(scene.params)) {}

void ThesisSolver::advance(const FrameContext& f) {
  PhaseTimer timer(f.timings.neighbor_ms);
  f.grid.build(f.particles);

  timer.start(f.timings.density_pressure_ms);
  computeDensityPressure(f.scene.params, kernels_, f.grid, f.particles);

  timer.start(f.timings.accel_integrate_collide_ms);
  computeAccelerations(f.scene.params, kernels_, f.grid, f.particles, f.track_surface_distance);
  integrateAndCollide(f.scene.params, f.scene.boundary, f.scene.boundary.stateAt(f.time + f.dt), f.particles);
}

void ThesisSolver::settleFreshWater(const FrameContext& f) {
  f.grid.build(f.particles);
  computeDensityPressure(f.scene.params, kernels_, f.grid, f.particles);
}

double ThesisSolver::fillInset(double spacing, double radius) const {
  // The thesis's collision keeps a particle a radius off a wall (3.29): the first lattice point
  // sits a radius in where that is more than half a spacing, so no particle starts in contact.
  return std::max(0.5 * spacing, radius);
}

}  // namespace sph
