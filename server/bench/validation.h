// Validation against experiment and theory (sph_validate): the surge front and the residual column
// height of a dam break against Martin & Moyce (1952, "An experimental study of the collapse of
// liquid columns on a rigid horizontal plane", Phil. Trans. R. Soc. A 244), and the density and
// pressure of water at rest against depth (rho0 everywhere for incompressible water, p = rho0 g
// depth).
#pragma once

#include <string>
#include <vector>

#include "bench/water_level.h"
#include "sph/particles.h"

namespace bench {

// One point of a dam-break curve against T = t sqrt(2 g / a): the surge front's Z = x_front / a,
// or the residual column's height over its initial height.
struct CurvePoint {
  double T = 0.0;
  double value = 0.0;
};

// Martin & Moyce's measured front for n^2 = 2 (their figure for the square-based column), T <= 3.33.
const std::vector<CurvePoint>& martinMoyceN2();

// Martin & Moyce's measured residual column height for n^2 = 2: h / (n^2 a) at the back wall
// against T (their table's time, tau = t sqrt(g / a), is T / sqrt(2)).
const std::vector<CurvePoint>& martinMoyceHeightN2();

// The initial column as the particles fill it: the width a (from the wall at x = wall_x to the
// edge of the particles' volumes, m / rho0 each), the height above y = 0, and how compressed the
// water is when released (a deep column held by too few solver iterations stands short and
// pushes off early: docs/fluids.md, "pbf: position based fluids", iterations to a tolerance).
struct Column {
  double width = 0.0;
  double height = 0.0;
  double mean_compression = 0.0;  // mean of max(rho / rho0 - 1, 0); NaN while no density is computed
  double max_density = 0.0;       // largest rho / rho0; NaN likewise
};
Column measureColumn(const sph::ParticleSet& particles, double rest_density, double wall_x);

// The front's x: the 99.9th percentile of the particles' x plus half their spacing (the edge of
// the leading particle's volume), so that a few spray particles ahead of the water do not count.
double surgeFrontX(const sph::ParticleSet& particles, double rest_density);

// The residual column's height above the floor (m): the level gauges read (water_level.h: the
// highest point where the kernel-interpolated density reaches rho0 / 2, the particles' sizes all
// alike) on three lines half an L0 spacing off the back wall, box.min.x(), at a quarter, half and
// three quarters of the tank's depth, averaged.
double residualHeight(const sph::ParticleSet& particles, const sph::Scene& scene, const sph::BoxState& box);

// `curve`'s value at T, linear between its points; its first value before it, NaN beyond its end.
double curveAt(const std::vector<CurvePoint>& curve, double T);

// The simulated curve compared with the experiment at the experiment's T <= t_max: the largest
// relative error |v_sim(T + shift) - v_exp| / v_exp over those points, with the simulated curve
// interpolated linearly. `shift` delays the experiment (its gate took time to clear).
double maxRelativeError(const std::vector<CurvePoint>& simulated, const std::vector<CurvePoint>& experiment,
                        double t_max, double shift);

// The shift in [0, max_shift] (steps of 0.001) with the smallest maximum error; `error` gets it.
double bestStartupShift(const std::vector<CurvePoint>& simulated, const std::vector<CurvePoint>& experiment,
                        double t_max, double max_shift, double& error);

// Water at rest, binned by depth below its free surface.
struct DepthBin {
  double depth = 0.0;  // bin centre, m below the surface
  int count = 0;
  double density_ratio = 0.0;  // mean rho / rho0
  double pressure = 0.0;       // mean p, Pa
};
struct RestProfile {
  double surface_y = 0.0;           // the free surface: the highest particle's volume edge
  std::vector<DepthBin> bins;       // top to bottom
  double mean_density_error = 0.0;  // mean |rho / rho0 - 1| over all particles
  double wall_density_error = 0.0;  // the largest |mean rho / rho0 - 1| of the wall and floor layers
  // The least and the largest rho / rho0 of a particle in those layers: a layer's mean hides its
  // densest particles (by the tank's edges).
  double wall_min = 1.0, wall_max = 1.0;
  double pressure_slope = 0.0;  // least squares dp / d(depth) over the interior, Pa/m (rho0 g)
  double rms_speed = 0.0;       // m/s
  WaterLevel level;             // the gauges' depth against sum m / rho0's (water_level.h)
};
// `box_min`/`box_max`: the tank; wall and floor layers are the particles within one spacing of a wall.
RestProfile measureRestProfile(const sph::ParticleSet& particles, double rest_density, const Eigen::Vector3f& box_min,
                               const Eigen::Vector3f& box_max, double bin_width);

}  // namespace bench
