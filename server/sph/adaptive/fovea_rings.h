// Where the foveated method lets each coarser level begin around the gaze point, as circles on the
// screen, so a viewer can draw what the server used. Pure functions of the settings, the level
// widths and the display's field of view (displayTanHalf, adaptive/display_geometry.h), by the
// rule of decideFoveated (adaptive/foveated.h): a particle at the fovea's depth at eccentricity e
// may be q (1 + g (m / w0) e) finest widths wide.
#pragma once

#include <span>
#include <vector>

#include "sph/adaptive/method.h"

namespace sph {

// A ring this wide (viewport widths) or wider lies off any screen whatever the gaze point: what a
// level the display's field of view never reaches gets.
inline constexpr double kOffScreenRingRadius = 8.0;

// The eccentricity, degrees, at which a level `width` finest particles wide begins for a particle
// at the fovea's depth: (width / q - 1) / (g m / w0), 0 where q alone allows it.
double levelOnsetEccentricityDeg(const AdaptiveConfig& config, double width);

// The radius, in viewport widths, of the circle standing in for the screen points `e_deg` degrees
// from the gaze direction through (gaze_x, gaze_y) (normalized, origin top left). Those points
// form a conic on the screen plane, a circle only at the screen's centre; the circle's radius is
// the mean of the conic's distance from the gaze point over evenly spaced directions. Exact at
// the centre; off it the conic stretches away from the centre: with the gaze at the edge of a 40
// degree display its nearest and farthest points lie 8 % apart at 2 degrees, 15 % at 10. A
// direction in which the display never reaches e counts as kOffScreenRingRadius, and so does a
// mean beyond it.
double eccentricityRadiusOnScreen(double e_deg, double tan_half, double gaze_x, double gaze_y);

// One radius per level k = 1 .. widths.size() - 1 (widths[k]: level k's width in finest particles,
// SimParams::levelProps radius ratios), where it begins around the gaze: 0 where q allows it at the
// gaze point.
std::vector<float> foveaRingRadii(const AdaptiveConfig& config, std::span<const double> widths, double tan_half,
                                  double gaze_x, double gaze_y);

}  // namespace sph
