// dfsph's floor as a constraint of its constant-density solve.
//
// The one-sided walls (dfsph_passes.h) push a particle with its own pressure alone, so the solve
// holds water on the floor by compressing it, and it does not know the guard that keeps particles
// off a wall (collision.h, IncompressibleSetup::contact): it counts on moving the floor layer into
// the floor, the guard undoes that after the step, and the layer above stays compressed. The
// settled dam break stood 2.2 % below the depth its mass fills, its second layer 1-1.5 % over rho0,
// and the floor's guard had to sit at 0.4 spacings (at half a spacing the floor layer piled up to
// 1.07 rho0).
//
// Here the solve knows the floor. A particle whose velocity would carry it onto the floor's guard
// (or within kBand of it) in the step is held: its velocity into the floor is removed before the
// solve, as the guard would remove it after the step, and so is the vertical component of its
// pressure acceleration in every iteration, so that the pressure lifts the water above it instead
// of pressing it down. A held particle that also reaches a side wall's guard (the floor's edges
// and corners) is held along that wall's normal as well: otherwise the solve, pressing it into the
// side guard it does not know, slid it along the edge (a whole split pool's edge particles met at
// 0.3-0.4 m/s, 1.08 rho0). Only the floor and its edges: gravity keeps the floor layer on the
// floor, where a side wall's layer leaves it and comes back; held at every wall, the tests' tanks
// kept moving at 7-20 mm/s.
//
// The held particles' velocity along the floor relaxes to the floor's, a share each step: a
// no-slip floor, applied softly. Without it the floor layer, no longer pressed into the floor, slides:
// the validation tank moved at 12 mm/s after 8 s; stopped dead each step, the wall layers read
// 1.03 rho0. Measured (docs/fluids.md, "Walls that count").
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sph/boundary.h"
#include "sph/collision.h"
#include "sph/particles.h"

namespace sph {

class FloorContact {
 public:
  // Finds the particles held for a step of dt from their velocities as they stand, and removes
  // their velocity into the floor (and into an edge's side walls), relative to the walls'.
  // `reach` and `spacing` per class (IncompressibleSetup).
  void find(ParticleSet& p, const BoxState& box, const std::array<WallReach, kSizeClassCount>& reach,
            const std::array<float, kSizeClassCount>& spacing, float dt);

  // Removes the held components from an acceleration per particle.
  void hold(std::vector<Vec3>& acceleration) const;

  // Relaxes the held particles' velocity along the walls that hold them, one step's share.
  void relaxSlip(ParticleSet& p) const;

 private:
  // Scales each held particle's components along the axes that hold it and along the others.
  void scaleHeld(std::vector<Vec3>& v, float along_held, float along_free) const;

  // Per particle: bit a, held along axis a; 0 if free.
  std::vector<std::uint8_t> held_;
};

}  // namespace sph
