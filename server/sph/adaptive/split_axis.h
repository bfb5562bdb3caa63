// Where a split puts its two children: their offset from the parent's centre (one child at
// centre + offset, the other at centre - offset), kept inside the box.
#pragma once

#include <cstddef>

#include "sph/boundary.h"
#include "sph/neighbor_grid.h"
#include "sph/particles.h"

namespace sph {

// `wanted` along `dir`, turned along the walls that would cut it short (the components towards a
// wall closer than `wanted`, less `margin`, dropped) and shortened so that both children stay
// `margin` (their radius) inside the box. The thesis's water splits along a direction drawn from
// the parent's id (splitDirection).
Vec3 childOffsetInBox(const Vec3& centre, const Vec3& dir, const BoxState& box, float margin, float wanted);

// Incompressible water (pbf, dfsph): the offset (childOffsetInBox) along the candidate axis whose
// children keep the farthest from particle i's neighbours and from each other, the nearest of
// them deciding. The candidates are the cubes' diagonals, the face diagonals and the axes; where
// the neighbours lie to one side (the free surface) they are first turned into the plane across
// that side (unturned, the most room there is out of the water). In a resting pool split whole
// the roomiest axis keeps the closest children farther from other particles than drawn directions
// do, and the split's compression and kick follow from how close they come (docs/level_changes.md, "Where
// the children go").
Vec3 roomiestChildOffset(const ParticleSet& p, const NeighborGrid& grid, std::size_t i, const BoxState& box,
                         float margin, float wanted);

// The unit diagonal from `centre` away from the nearest face on every axis: into the box from a
// corner, where walls on three sides leave two children no room about their parent's centre.
Vec3 awayFromNearestFaces(const Vec3& centre, const BoxState& box);

}  // namespace sph
