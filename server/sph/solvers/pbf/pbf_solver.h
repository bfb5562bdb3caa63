// Position based fluids (Macklin & Mueller 2013): each solver step predicts positions from
// gravity, finds the neighbours there, moves the particles by a few Jacobi iterations of the
// density constraint (pbf_passes.h), takes the velocity from the displacement, smooths it (XSPH)
// and restores vorticity (vorticity confinement). SimParams::substeps steps a frame.
//
// Each step solves from zero multipliers (pbf_solver.cpp says why not from the last step's), so
// a few Jacobi iterations hold a deep column as a stiff equation of state would: the compression
// grows with the depth and with dt^2 and falls with the iterations, so the preset takes several
// steps a frame of at least pbf_iterations iterations each, more where the mean compression is over
// its tolerance (params.cpp). The mean of the steps' multipliers gives the pressure the frames show.
// Fresh water is relaxed at rest first (settleInGate, relaxAtRest: incompressible_setup.h).
#pragma once

#include <vector>

#include "sph/solvers/fluid_solver.h"
#include "sph/solvers/incompressible_setup.h"
#include "sph/solvers/local_placement.h"
#include "sph/solvers/pbf/pbf_passes.h"
#include "sph/solvers/pbf/still_water_changes.h"
#include "sph/solvers/velocity_passes.h"

namespace sph {

class PbfSolver : public FluidSolver {
 public:
  explicit PbfSolver(const Scene& scene);
  void advance(const FrameContext& frame) override;
  void settleFreshWater(const FrameContext& frame) override { settleInGate<PbfSolver>(frame); }
  // A placed particle keeps its mark until its density constraint holds it (pbf_solver.cpp).
  void releasePlaced(ParticleSet& /*particles*/) const override {}
  SplitPlacement splitPlacement() const override { return SplitPlacement::kRoomiestAxis; }
  // Relaxes fresh water at rest where it stands (relaxAtRest); settleFreshWater does it in a gate.
  void settle(const FrameContext& frame);

 private:
  // `first`, `last`: the frame's first and last step.
  void substep(const FrameContext& frame, double t0, float dt, bool first, bool last);

  IncompressibleSetup setup_;
  PbfConstants constants_;
  VelocityConstants velocity_constants_;
  // Scratch, sized to the particles once at the ceiling (no allocation in a step after that).
  std::vector<Vec3> old_position_, next_position_, next_velocity_, vorticity_, wall_grad_;
  std::vector<float> lambda_, lambda_step_;
  std::vector<float> pair_g_;  // PbfArrays::pair_g, at the grid's slots
  LocalPlacement placement_;
  StillWaterChanges still_changes_;
  std::vector<float> start_speed_;    // each particle's speed at the step's start
  std::vector<float> pressure_sum_;   // the frame's steps' pressures, summed
  std::vector<double> sum_partials_;  // orderedSum's scratch
};

}  // namespace sph
