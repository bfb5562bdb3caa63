// Fresh water: the scene's water region filled with particles of one class at rest density.
#pragma once

#include "sph/particles.h"
#include "sph/scene.h"
#include "sph/solvers/fluid_solver.h"

namespace sph {

// Fills `out` with the scene's water on a cubic lattice of spacing cbrt(m / rho0), bottom layer
// first, the first point `solver`'s fill inset in from the region's faces.
// Throws std::invalid_argument when the region cannot hold the particles or lies outside the box.
void fillWater(const Scene& scene, Level start_class, const FluidSolver& solver, ParticleSet& out);

// The coarsest level, `wanted` or finer, whose lattice the scene's water region holds: a coarse
// level's spacing need not divide the region, so its lattice may hold fewer sites than the water
// needs where a finer one's holds enough (the adaptive methods then merge from there). `wanted`
// where no level's does, for fillWater's error.
Level fillingLevel(const Scene& scene, Level wanted, const FluidSolver& solver);

}  // namespace sph
