// The water's level as SPH wave gauges measure it, against the level its mass would stand at with
// the rest density in the same container: the settled depth beside sum m / rho (the volume column),
// which errs high wherever most particles sit at the free surface (a thin sheet reads under-dense
// there, so its m / rho overstates the volume it fills).
//
// A gauge is a vertical line; its level is the highest point where the kernel-interpolated
// density sum_j m_j W(x - x_j, h_j) still reaches half of rho0, as the gauges of DualSPHysics
// (Crespo et al. 2015) find the free surface. Over a resting half-space of water at rho0 that is
// where the water ends, half a spacing above its top layer, whatever the (symmetric) kernel. The
// walls count as the solvers count them (boundary_volume.h): the floor's density adds to the
// water's, and the part of the kernel a side wall or an obstacle takes is divided out, so a gauge
// beside a wall, or over a sheet thinner than a support, reads like one in open deep water. The
// gauges stand one in each cell of a grid over the whole floor, less the cells whose centre is
// within half an L0 spacing of an obstacle. Where the surface is a single height over the floor
// (no overhang, no spray), the mean level over the gauges is the water's depth, moving or not; it
// is the settled depth once the water is at rest.
#pragma once

#include <utility>
#include <vector>

#include "sph/boundary.h"
#include "sph/particles.h"
#include "sph/scene.h"

namespace bench {

struct WaterLevel {
  int gauges = 0;      // gauges on the floor's grid clear of the walls and the obstacles
  int wet = 0;         // of them, those that found water
  double depth = 0.0;  // their mean level above the floor (m), a dry gauge counting 0
  // The depth sum m / rho0 fills at rest in this container, its obstacles displacing water (m).
  double incompressible_depth = 0.0;
};

// `box`: the container now (Boundary::stateAt); the obstacles are the scene boundary's spheres and
// cylinders; the rest density and the classes' kernels are the scene's parameters'.
WaterLevel measureWaterLevel(const sph::ParticleSet& particles, const sph::Scene& scene, const sph::BoxState& box);

// The mean level above the floor of `box` (m) of gauges on the vertical lines through `lines`
// ((x, z) pairs), each read as measureWaterLevel reads its own; a dry gauge counts 0. A line
// should stand at least half an L0 spacing off every side wall and obstacle.
double gaugeLevel(const sph::ParticleSet& particles, const sph::Scene& scene, const sph::BoxState& box,
                  const std::vector<std::pair<double, double>>& lines);

// The depth that `volume` (m^3) fills from the floor of `box`, less what the boundary's spheres and
// floor-to-roof cylinders standing over that floor take up to that height; the box's height if it
// holds less.
double incompressibleDepth(double volume, const sph::Boundary& boundary, const sph::BoxState& box);

}  // namespace bench
