#include "sph/adaptive/fovea_rings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace sph {

namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
// Directions the conic's distance is averaged over (adaptive/fovea_rings.h).
constexpr int kDirections = 32;

}  // namespace

double levelOnsetEccentricityDeg(const AdaptiveConfig& config, double width) {
  const double per_degree = config.foveated_periphery_gain * config.foveated_mar_slope / config.foveated_mar_w0_deg;
  const double excess = width / config.foveated_quality - 1.0;
  if (!(excess > 0.0)) return 0.0;
  return per_degree > 0.0 ? excess / per_degree : std::numeric_limits<double>::infinity();
}

double eccentricityRadiusOnScreen(double e_deg, double tan_half, double gaze_x, double gaze_y) {
  if (!(e_deg > 0.0)) return 0.0;
  if (!(e_deg < 180.0) || !(tan_half > 0.0)) return kOffScreenRingRadius;
  // The display as the plane z = 1 in front of the eye: the gaze direction p0 there, and one
  // viewport width along the screen is 2 tan_half along the plane in any direction (the aspect
  // ratio cancels, as in display_geometry.h's screenDirection).
  const double px = (2.0 * gaze_x - 1.0) * tan_half;
  const double py = (1.0 - 2.0 * gaze_y) * tan_half;  // sign only: the sum runs over all directions
  const double a = std::sqrt(px * px + py * py + 1.0);
  const double sin_e = std::sin(e_deg * kRadiansPerDegree);
  const double cos_e = std::cos(e_deg * kRadiansPerDegree);
  double sum = 0.0;
  for (int i = 0; i < kDirections; ++i) {
    const double theta = 2.0 * std::numbers::pi * (i + 0.5) / kDirections;
    const double ux = 2.0 * tan_half * std::cos(theta);
    const double uy = 2.0 * tan_half * std::sin(theta);
    // The point p0 + r u seen at angle atan2(r s, a + r c) from p0, c and s the parts of u along
    // p0 and across it: that angle is e at r = a sin e / (s cos e - c sin e).
    const double c = (px * ux + py * uy) / a;
    const double s = std::sqrt(std::max(ux * ux + uy * uy - c * c, 0.0));
    const double denominator = s * cos_e - c * sin_e;
    const double r = denominator > 0.0 ? a * sin_e / denominator : kOffScreenRingRadius;
    sum += std::min(r, kOffScreenRingRadius);
  }
  return std::min(sum / kDirections, kOffScreenRingRadius);
}

std::vector<float> foveaRingRadii(const AdaptiveConfig& config, std::span<const double> widths, double tan_half,
                                  double gaze_x, double gaze_y) {
  std::vector<float> radii;
  for (std::size_t k = 1; k < widths.size(); ++k) {
    const double e = levelOnsetEccentricityDeg(config, widths[k]);
    radii.push_back(static_cast<float>(eccentricityRadiusOnScreen(e, tan_half, gaze_x, gaze_y)));
  }
  return radii;
}

}  // namespace sph
