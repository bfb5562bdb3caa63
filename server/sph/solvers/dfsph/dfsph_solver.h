// Divergence-free SPH (Bender & Koschier 2015, 2017, in the form of SPlisHSPlasH's current DFSPH):
// each solver step finds the neighbours, computes densities, makes the velocity field
// divergence-free (the divergence solver), adds gravity and XSPH viscosity, solves for the
// pressure that brings the density after the step to rho0 (the constant-density solver), and
// moves the particles. Both solvers iterate for k = p / rho^2 >= 0 (water pushes, never pulls)
// to a tolerance, warm-started from the last step's k (attributes, so it follows its particle
// through reorders, splits and merges): relaxed Jacobi iterations, and for the constant density,
// past the first three, conjugate gradients (SimParams::dfsph_conjugate_gradients). Solver steps obey a
// CFL bound, and a frame takes at least SimParams::substeps of them.
#pragma once

#include <cstdint>
#include <vector>

#include "sph/solvers/dfsph/dfsph_passes.h"
#include "sph/solvers/floor_contact.h"
#include "sph/solvers/fluid_solver.h"
#include "sph/solvers/incompressible_setup.h"
#include "sph/solvers/local_placement.h"
#include "sph/solvers/pair_vectors.h"
// pbf's constraint constants, for the local placement (local_placement.h).
#include "sph/solvers/pbf/pbf_passes.h"
#include "sph/solvers/velocity_passes.h"

namespace sph {

class DfsphSolver : public FluidSolver {
 public:
  explicit DfsphSolver(const Scene& scene);
  void advance(const FrameContext& frame) override;
  void settleFreshWater(const FrameContext& frame) override { settleInGate<DfsphSolver>(frame); }
  SplitPlacement splitPlacement() const override { return SplitPlacement::kRoomiestAxis; }
  // Fresh water starts as sampled, with the pressure of water at rest as the warm start.
  void settle(const FrameContext& frame);

 private:
  // Moves the particles the adaptive step placed after the last frame apart (local_placement.h).
  void placeFresh(const FrameContext& frame);
  // `last`: the frame's last step.
  void substep(const FrameContext& frame, double t0, float dt, bool last);
  // One of the two solvers: the k >= 0 that makes the density after the step rho0
  // (density_target) or its rate 0, from `warm` (the last step's k, which receives this step's),
  // then the velocities it gives. Returns the iterations taken.
  int solve(const FrameContext& frame, std::vector<float>& warm, bool density_target, float dt);
  // acceleration_ from arrays_.stiffness (the acceleration pass), and in the constant-density
  // solve (held) less the components the floor holds (floor_contact.h): every pass of that solve,
  // so that its system stays the symmetric one of the held particles.
  void pressureAccelerations(const DfsphPassForms& forms, const NeighborGrid& grid, bool held);
  // solve's iterations for the constant density past the first Jacobi ones, from the k and the
  // change_ they left (dfsph_conjugate_gradients.cpp); returns the iteration count reached.
  int conjugateGradients(const FrameContext& frame, const DfsphPassForms& forms, float scale, float tolerance,
                         int least, int iteration);

  IncompressibleSetup setup_;
  DfsphConstants constants_;
  VelocityConstants velocity_constants_;
  DfsphArrays arrays_;
  // Scratch, sized once at the ceiling.
  std::vector<Vec3> boundary_grad_, next_velocity_, vorticity_, acceleration_;
  std::vector<float> inverse_diagonal_, wall_rate_, change_, target_, stiffness_;
  std::vector<float> residual_, search_, preconditioned_, anchor_;  // conjugateGradients'
  std::vector<std::uint8_t> active_;
  std::vector<double> sum_partials_;  // orderedSums' scratch
  PairVectorStore pair_grad_;         // DfsphArrays::pair_grad
  FloorContact floor_;                // the constant-density solve's
  PbfConstants placement_constants_;
  LocalPlacement placement_;
};

}  // namespace sph
