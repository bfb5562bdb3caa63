// Where the adaptive step puts a particle (a split's children, a merged particle) is a choice of
// the method, not a motion of the water: the children of a split sit half a parent radius either
// side of it, closer than the water would hold them, and nearer still by a wall. LocalPlacement
// moves the fresh placements (dfsph: and their neighbours) compressed beyond a limit, and only as
// far as it takes, by local Jacobi iterations of pbf's density constraint (pbf_passes.h): only
// they and their neighbours update their multipliers, only the particles those reach move, and
// velocities are not touched.
// pbf runs it inside its first step after a placement (its constraint already moves positions);
// dfsph before its first step, since its solver moves particles only through velocities and would
// turn the overlap of a split into speed (docs/fluids.md).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sph/neighbor_grid.h"
#include "sph/params.h"
#include "sph/particles.h"
#include "sph/solvers/incompressible_setup.h"
#include "sph/solvers/pbf_passes.h"

namespace sph {

// `placed` (particle_attributes.h) of a particle the adaptive step placed after the last frame.
inline constexpr std::uint8_t kPlacedThisFrame = 1;

// pbf's constraint constants for the scene's parameters and setup (pbf_passes.h); the box and
// the obstacles are the caller's to set for the time it moves particles at.
PbfConstants pbfConstantsOf(const SimParams& params, const IncompressibleSetup& setup);

// The pbf passes' form this CPU runs (simd_level.h).
PbfPassForms dispatchedPbfPassForms();

// The pbf passes' view of `p` with the caller's multipliers and wall-gradient scratch (sized to
// p.size()); the positions are set per pass.
PbfArrays pbfArraysOf(ParticleSet& p, std::vector<float>& lambda, std::vector<float>& lambda_step,
                      std::vector<Vec3>& wall_grad);

class LocalPlacement {
 public:
  // The particles marked kPlacedThisFrame, in order.
  std::span<const std::uint32_t> fresh(const ParticleSet& p);
  // fresh(p) and their neighbours in `grid` (built on p), sorted.
  std::span<const std::uint32_t> watched(const ParticleSet& p, std::span<const std::uint32_t> fresh,
                                         const NeighborGrid& grid);

  // Moves the `candidates` (fresh() or watched(), whose densities the caller's last constraint
  // pass measured) whose density exceeds max(density_at_start, rho0) by more than `limit`
  // (kg/m^3), with their neighbourhoods, for at most `max_iterations` iterations or until none
  // exceeds it. `a` views p at its current positions (position, density, lambda, lambda_step,
  // wall_grad set and sized to p); lambda carries on from its values, lambda_step is zeroed first.
  // `next_position` is scratch of p.size(). Returns the iterations.
  int place(ParticleSet& p, const NeighborGrid& grid, std::span<const std::uint32_t> candidates, PbfArrays& a,
            const PbfConstants& c, const PbfPassForms& forms, std::span<const float> density_at_start,
            std::vector<Vec3>& next_position, float limit, int max_iterations);

 private:
  std::vector<std::uint32_t> fresh_, watched_, placed_, updated_, moved_;
  std::vector<std::uint8_t> mark_;
};

}  // namespace sph
