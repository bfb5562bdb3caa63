// Where the adaptive step puts a particle (a split's children, a merged particle) is a choice of
// the method, not a motion of the water: the children of a split sit half a parent radius either
// side of it, closer than the water would hold them, and nearer still by a wall. LocalPlacement
// moves the fresh placements and their neighbours compressed beyond a limit, and only as far as it
// takes, by local Jacobi iterations of pbf's density constraint (pbf_passes.h): only they and
// their neighbours update their multipliers, only the particles those reach move, and velocities
// are not touched. Both solvers run it in the frame after a placement before they move the water:
// dfsph before its first step, since it moves particles only through velocities and would turn
// the overlap of a split into speed; pbf in its first step, after the prediction and before the
// constraint, carrying the step's start positions along, since it takes velocities from the
// step's displacements. Run after pbf's constraint, the placement's moves became velocity, which
// its speed rule for placed particles scaled down whole, the water's own motion with it: the
// Martin & Moyce front on the surface method, whose water is split and merged as its surface
// moves, fell behind the experiment (docs/level_changes.md, "Placement" and "Validation").
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sph/neighbor_grid.h"
#include "sph/params.h"
#include "sph/particles.h"
#include "sph/solvers/incompressible_setup.h"
// pbf's passes, though dfsph places with them too: the placement is pbf's density constraint, run
// locally.
#include "sph/solvers/pbf/pbf_passes.h"

namespace sph {

// pbf's constraint constants for the scene's parameters and setup (pbf_passes.h); the box and
// the obstacles are the caller's to set for the time it moves particles at.
PbfConstants pbfConstantsOf(const SimParams& params, const IncompressibleSetup& setup);

// The pbf passes' view of `p` with the caller's multipliers and wall-gradient scratch (sized to
// p.size()); the positions are set per pass.
PbfArrays pbfArraysOf(ParticleSet& p, std::vector<float>& lambda, std::vector<float>& lambda_step,
                      std::vector<Vec3>& wall_grad);

class LocalPlacement {
 public:
  // Whether placeFresh builds the neighbour grid on the particles or finds it built there.
  enum class Grid { kBuild, kCurrent };

  // In the frame after the adaptive step, before the solver moves the water: the particles marked
  // kPlacedThisFrame and their neighbours (a merged particle can press an unmerged neighbour it
  // lands beside while itself within the limit), where they now sit, each compressed more than
  // `limit` (kg/m^3) beyond max(its density at the frame's start, rho0) (a child carries its
  // parent's), are moved with their neighbourhoods for at most `max_iterations` iterations or
  // until none exceeds it. Their densities come from a constraint pass over them alone, whose
  // multipliers are discarded. `c` holds the box and obstacles for the particles' time; `grid`
  // is built on p first with Grid::kBuild, and only when anything is fresh. `carried` (empty, or
  // one per particle): positions moved by the same displacement as their particle, so that a
  // solver which takes velocities from displacements (pbf) sees none from the placement. Returns
  // the iterations (0 when nothing is fresh).
  int placeFresh(ParticleSet& p, NeighborGrid& grid, Grid state, const PbfConstants& c, float limit, int max_iterations,
                 std::span<Vec3> carried = {});

 private:
  // The iterations of placeFresh over the `candidates` (sorted), whose densities and multipliers
  // from zero the last constraint pass measured, every other particle's zero; `a` views p at its
  // current positions.
  int place(ParticleSet& p, const NeighborGrid& grid, std::span<const std::uint32_t> candidates, PbfArrays& a,
            const PbfConstants& c, const PbfPassForms& forms, float limit, int max_iterations, std::span<Vec3> carried);
  // The sets an iteration works on, from placed_ (the particles still compressed beyond the
  // limit): updated_, those and their neighbours, whose multipliers change; moved_, those and
  // theirs, whose corrections do (every other particle has a zero change of multiplier, so a zero
  // correction). Zeroes the last updated_'s changes.
  void surround(const NeighborGrid& grid, PbfArrays& a);

  // Scratch, sized to the particles.
  std::vector<float> lambda_, lambda_step_, density_at_start_;
  std::vector<Vec3> next_position_, wall_grad_;
  std::vector<std::uint32_t> fresh_, watched_, placed_, updated_, moved_, unmeasured_;
  std::vector<std::uint8_t> mark_;
};

}  // namespace sph
