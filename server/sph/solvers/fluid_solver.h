// A fluid solver advances the particles by one frame of the simulation (SimParams::time_step), in
// as many solver steps as it takes, and builds the neighbour lists it needs (the adaptive step
// after it reads the last ones). Everything that differs from one solver to another is asked of
// this interface; which solver runs is the scene's SimParams::solver, looked up by name in
// fluid_solver_factory.h. The built-in ones, each in its folder:
//   thesis/  Mueller SPH of thesis 3.3-3.5, one step per frame
//   pbf/     position based fluids (Macklin & Mueller 2013)
//   dfsph/   divergence-free SPH (Bender & Koschier 2015, 2017)
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>

#include "sph/neighbor_grid.h"
#include "sph/particles.h"
#include "sph/scene.h"

namespace sph {

// Wall-clock milliseconds of one frame, grouped as the thesis measures them (4.1): neighbour
// search; density and pressure (for pbf and dfsph: the pressure solve); accelerations,
// integration and collision (for pbf and dfsph: velocities and positions); the adaptive step.
struct PhaseTimings {
  double neighbor_ms = 0.0;
  double density_pressure_ms = 0.0;
  double accel_integrate_collide_ms = 0.0;
  double adaptive_ms = 0.0;
  double total_ms = 0.0;
};

// What a solver did in one frame.
struct SolverStats {
  int substeps = 1;
  int iterations = 0;             // pressure iterations over the substeps (pbf, dfsph)
  int divergence_iterations = 0;  // dfsph
  int placement_iterations = 0;   // moving the adaptive step's fresh particles apart (local_placement.h)
  float density_error = 0.0f;     // mean max(rho / rho0 - 1, 0) after the last solve (pbf, dfsph)
};

struct FrameContext {
  const Scene& scene;
  ParticleSet& particles;
  NeighborGrid& grid;
  double time;  // at the start of the frame
  double dt;    // the frame
  bool track_surface_distance;
  PhaseTimings& timings;
  SolverStats& stats;
};

// Where the two children of a split go (adaptive/split_merge.cpp).
enum class SplitPlacement : std::uint8_t {
  kHashedDirection,  // along a direction hashed from the parent's id (thesis 3.6.1)
  kRoomiestAxis,     // along the roomiest axis, turned into the free surface (adaptive/split_axis.h)
};

// A solver keeps what it derives from the scene and its scratch, never a reference into the
// simulation that owns it (the scene comes with each frame), so a Simulation can move.
class FluidSolver {
 public:
  virtual ~FluidSolver() = default;
  virtual void advance(const FrameContext& frame) = 0;
  // Freshly filled water (a lattice at rest density): brings it to the state in which the solver
  // holds it at rest, so that the first steps add no kick. Nothing by default (the thesis's
  // preset starts from its lattice, as the thesis did).
  virtual void settleFreshWater(const FrameContext& /*frame*/) {}
  // After each frame: what becomes of the marks the adaptive step puts on the particles it placed
  // (ParticleSet::placed). By default they last one frame.
  virtual void releasePlaced(ParticleSet& particles) const {
    std::fill(particles.placed.begin(), particles.placed.end(), std::uint8_t{0});
  }
  virtual SplitPlacement splitPlacement() const { return SplitPlacement::kHashedDirection; }
  // How far inside the water region's faces the fill's first lattice point sits, for particles of
  // radius `radius` at lattice spacing `spacing`: by default half a spacing, so that the lattice
  // tiles the region with each particle's volume.
  virtual double fillInset(double spacing, double /*radius*/) const { return 0.5 * spacing; }
  // How many size levels (params.h) the solver's pair passes handle: every one by default (a
  // mixed pair's kernel from the two supports, pair_kernel.inc).
  virtual int sizeLevels() const { return kMaxLevels; }
};

}  // namespace sph
