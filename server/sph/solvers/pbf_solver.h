// Position based fluids (Macklin & Mueller 2013): each solver step predicts positions from
// gravity, finds the neighbours there, moves the particles by a few Jacobi iterations of the
// density constraint (pbf_passes.h), takes the velocity from the displacement, smooths it (XSPH)
// and restores vorticity (vorticity confinement). SimParams::substeps steps a frame.
//
// A few Jacobi iterations carry a correction only a few neighbours far, so a deep column cannot
// build the pressure that carries it within one step. Each step therefore starts from the last
// step's multipliers (pbf_lambda, an attribute; pbf_passes.h), applied before the iterations, as
// dfsph starts from the last pressure: the iterations correct what changed. Fresh water starts
// with the multipliers of water at rest (settle), so the first steps add no kick.
#pragma once

#include <vector>

#include "sph/solvers/fluid_solver.h"
#include "sph/solvers/incompressible_setup.h"
#include "sph/solvers/pbf_passes.h"
#include "sph/solvers/velocity_passes.h"

namespace sph {

class PbfSolver : public FluidSolver {
 public:
  explicit PbfSolver(const Scene& scene);
  void advance(const FrameContext& frame) override;
  void settle(const FrameContext& frame) override;

 private:
  // Returns the largest distance a particle moved.
  float substep(const FrameContext& frame, double t0, float dt);

  IncompressibleSetup setup_;
  PbfConstants constants_;
  VelocityConstants velocity_constants_;
  // Scratch, sized to the particles once at the ceiling (no allocation in a step after that).
  std::vector<Vec3> old_position_, next_position_, next_velocity_, vorticity_;
  std::vector<float> lambda_, lambda_step_;
};

}  // namespace sph
