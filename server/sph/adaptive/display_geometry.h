// Where the user sees a point of the display: directions from the eye through normalized screen
// coordinates (origin top left) of a display whose size in the visual field is a setting
// (AdaptiveConfig::foveated_display_fov_deg), not the camera's rendering angle. The foveated rule,
// the perceptual budget and the rings the viewer draws all measure eccentricity this way.
#pragma once

#include <cmath>
#include <numbers>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sph/adaptive/method.h"
#include "sph/camera.h"

namespace sph {

inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// tan of half the display's horizontal angle as the user sees it: the configured display's, or
// the camera's own field of view when that is 0.
inline float displayTanHalf(const AdaptiveConfig& config, const ScreenCamera& camera) {
  return config.foveated_display_fov_deg > 0.0
             ? static_cast<float>(std::tan(0.5 * config.foveated_display_fov_deg / kDegreesPerRadian))
             : static_cast<float>(1.0 / camera.projection(0, 0));
}

// In front of the eye with its centre on the display: the water the foveated rule and the
// perceptual budget both weigh.
inline bool onDisplay(const FastScreenDisc& disc) {
  return disc.in_front != 0 && disc.x >= 0.0f && disc.x <= 1.0f && disc.y >= 0.0f && disc.y <= 1.0f;
}

// The direction of screen point (sx, sy) from the eye, the display `tan_half` wide (tan of half
// its horizontal angle) and `aspect` wide per high.
inline Eigen::Vector3f screenDirection(float sx, float sy, float tan_half, float aspect) {
  return {(2.0f * sx - 1.0f) * tan_half, (1.0f - 2.0f * sy) * tan_half / aspect, 1.0f};
}

// The angular radius of a disc `radius` viewport widths wide as the user sees it near the line of
// sight, degrees (small angles: the foveated rule's and the perceptual budget's test of whether a
// particle covers the gaze point).
inline float discRadiusDeg(float radius, float tan_half) {
  return static_cast<float>(kDegreesPerRadian) * 2.0f * tan_half * radius;
}

// The angle between two directions, degrees (atan2 of |a x b| and a . b: exact near 0 too).
inline float angleDeg(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  return static_cast<float>(kDegreesPerRadian) * std::atan2(a.cross(b).norm(), a.dot(b));
}

// A disc's diameter as the user sees it: the angle between the directions of its left and right
// edges, degrees. Off the display's centre a disc looks narrower than the same disc at the centre.
inline float discWidthDeg(float x, float y, float radius, float tan_half, float aspect) {
  return angleDeg(screenDirection(x - radius, y, tan_half, aspect), screenDirection(x + radius, y, tan_half, aspect));
}

}  // namespace sph
