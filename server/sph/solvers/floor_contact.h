// dfsph's floor as a constraint of its constant-density solve.
//
// The one-sided walls (dfsph_passes.h) push a particle with its own pressure alone, so the solve
// holds water on the floor by compressing it, and it does not know the guard that keeps particles
// off a wall (collision.h, IncompressibleSetup::contact): it counts on moving the floor layer into
// the floor, the guard undoes that after the step, and the layer above stays compressed. The
// settled dam break stood below the depth its mass fills, its second layer over rho0, and the
// floor's guard had to sit closer than half a spacing (at half a spacing the floor layer piled
// up).
//
// Here the solve knows the floor. A particle whose velocity would carry it onto the floor's guard
// (or within kBand of it) in the step is held: its velocity into the floor is removed before the
// solve, as the guard would remove it after the step, and so is the vertical component of its
// pressure acceleration in every iteration, so that the pressure lifts the water above it instead
// of pressing it down. A held particle that also reaches a side wall's guard (the floor's edges
// and corners) is held along that wall's normal as well: otherwise the solve, pressing it into the
// side guard it does not know, slid it along the edge (a whole split pool's edge particles met
// there fast and compressed). Only the floor and its edges: gravity keeps the floor layer on the
// floor, where a side wall's layer leaves it and comes back; held at every wall, the tests' tanks
// kept moving.
//
// The held particles' velocity along the floor relaxes to the floor's, a share each step: a
// no-slip floor, applied softly. Without it the floor layer, no longer pressed into the floor, slides
// and the validation tank keeps moving; stopped dead each step, the wall layers read compressed
// (floor_contact.cpp, kSlipLoss; docs/fluids.md, "dfsph: divergence-free SPH", the floor held by
// the solve).
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
  void find(ParticleSet& p, const BoxState& box, const std::array<WallReach, kMaxLevels>& reach,
            const std::array<float, kMaxLevels>& spacing, float dt);

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
