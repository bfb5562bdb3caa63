// One SPH simulation: owns the particles, the neighbour grid, the fluid solver of the scene's
// preset and the clock, and runs the step (a frame of SimParams::time_step) as a short list of
// named stages (thesis 3.8): the periodic re-sort, the fluid solver's frame (neighbour search,
// density and pressure, accelerations + integration + collision; solvers/fluid_solver.h), then
// the adaptive step when a method has one.
#pragma once

#include <cstdint>
#include <memory>

#include "sph/neighbor_grid.h"
#include "sph/particles.h"
#include "sph/scene.h"
#include "sph/solvers/fluid_solver.h"

namespace sph {

class Simulation;

// The adaptive step (thesis 3.6): decides, splits, merges and compacts. Runs last in the step.
class AdaptiveStep {
 public:
  virtual ~AdaptiveStep() = default;
  virtual void apply(Simulation& sim) = 0;
  // The coarsest level the step makes (the thesis's methods: L1); the neighbour grid's cells
  // fit its support.
  virtual Level coarsest() const { return Level{1}; }
};

class Simulation {
 public:
  // Fills the scene's water with particles of `start_class` (see fillWater).
  Simulation(const Scene& scene, Level start_class, std::size_t capacity = ParticleSet::kDefaultCapacity);

  // Without an adaptive step only the start class exists, and the neighbour grid's cells fit its
  // support; with one, the largest support of the levels it makes (AdaptiveStep::coarsest).
  void setAdaptiveStep(std::unique_ptr<AdaptiveStep> step);
  // The surface criterion's distance field advances one neighbour hop per step inside the force
  // loop (see computeAccelerations); adaptive steps that use it switch it on.
  void setSurfaceDistanceTracking(bool on) { track_surface_distance_ = on; }
  bool surfaceDistanceTracking() const { return track_surface_distance_; }

  void step();

  const Scene& scene() const { return scene_; }
  const SimParams& params() const { return scene_.params; }
  const FluidSolver& solver() const { return *solver_; }
  double time() const { return time_; }
  std::int64_t stepCount() const { return steps_; }
  const ParticleSet& particles() const { return particles_; }
  ParticleSet& particles() { return particles_; }
  const NeighborGrid& grid() const { return grid_; }
  const PhaseTimings& lastTimings() const { return timings_; }
  const SolverStats& lastSolverStats() const { return solver_stats_; }
  BoxState boxNow() const { return scene_.boundary.stateAt(time_); }
  // Continues from a checkpoint (checkpoint.h): the particles as they were after `steps` steps.
  // The next step rebuilds the neighbour grid from them, as every step does.
  void restore(ParticleSet&& particles, std::int64_t steps, bool surface_distance_tracking);
  // Rebuilds the neighbour lists for the current positions (after the adaptive step changed the set).
  void rebuildNeighbors() { grid_.build(particles_); }

 private:
  void configureGrid();

  Scene scene_;
  ParticleSet particles_;
  NeighborGrid grid_;
  Level start_class_;
  std::unique_ptr<FluidSolver> solver_;
  std::unique_ptr<AdaptiveStep> adaptive_;
  PhaseTimings timings_;
  SolverStats solver_stats_;
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  bool track_surface_distance_ = false;
};

}  // namespace sph
