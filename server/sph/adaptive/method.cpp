#include "sph/adaptive/method.h"

#include <algorithm>

#include <cmath>
#include <stdexcept>

namespace sph {

namespace {

struct MethodEntry {
  Method method;
  const char* name;
};
constexpr MethodEntry kMethods[] = {
    {Method::Regular, "regular"}, {Method::Surface, "surface"},   {Method::Gaze, "gaze"},
    {Method::Hybrid, "hybrid"},   {Method::Foveated, "foveated"},
};

void requireRange(const char* key, double v, double lo, double hi) {
  if (!std::isfinite(v) || v < lo || v > hi) {
    throw std::invalid_argument(std::string("adaptive setting '") + key + "' must be in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "], got " + std::to_string(v));
  }
}

}  // namespace

const char* methodName(Method m) {
  for (const auto& e : kMethods) {
    if (e.method == m) return e.name;
  }
  return "unknown";
}

bool methodByName(const std::string& name, Method& out) {
  for (const auto& e : kMethods) {
    if (name == e.name) {
      out = e.method;
      return true;
    }
  }
  return false;
}

std::vector<std::string> methodNames() {
  std::vector<std::string> names;
  for (const auto& e : kMethods) names.emplace_back(e.name);
  return names;
}

Level startLevel(Method m, int levels) {
  if (m == Method::Regular) return Level{0};
  return coarsestLevel(m, levels);
}

Level coarsestLevel(Method m, int levels) {
  return m == Method::Foveated ? asLevel(std::clamp(levels, kMinLevels, kMaxLevels) - 1) : Level{1};
}

bool usesGaze(Method m) { return m == Method::Gaze || m == Method::Hybrid || m == Method::Foveated; }

const char* gazeModeName(GazeMode m) {
  switch (m) {
    case GazeMode::None:
      return "none";
    case GazeMode::Tracking:
      return "tracking";
    case GazeMode::Holding:
      return "holding";
    case GazeMode::Fallback:
      return "fallback";
  }
  return "unknown";
}

void AdaptiveConfig::validate() const {
  requireRange("alpha", alpha, 0.0, 1e6);
  requireRange("beta", beta, 0.0, 1e6);
  requireRange("gamma", gamma, 0.0, 1e6);
  if (alpha + beta + gamma <= 0.0) {
    throw std::invalid_argument("adaptive settings 'alpha' + 'beta' + 'gamma' must be > 0");
  }
  requireRange("threshold", threshold, 0.0, 1.0);
  requireRange("surface_normal_scale", surface_normal_scale, 0.0, 100.0);
  requireRange("gaze_radius", gaze_radius, 0.0, 2.0);
  requireRange("gaze_ring_radius", gaze_ring_radius, 0.0, 2.0);
  if (gaze_ring_radius < gaze_radius) {
    throw std::invalid_argument("adaptive setting 'gaze_ring_radius' must be >= 'gaze_radius'");
  }
  requireRange("gaze_stale_s", gaze_stale_s, 0.0, 3600.0);
  requireRange("gaze_hold_s", gaze_hold_s, 0.0, 3600.0);
  requireRange("foveated_quality", foveated_quality, 1.0, 1e3);
  requireRange("foveated_periphery_gain", foveated_periphery_gain, 1.0, 1e3);
  requireRange("foveated_mar_w0_deg", foveated_mar_w0_deg, 1e-4, 10.0);
  requireRange("foveated_mar_slope", foveated_mar_slope, 0.0, 10.0);
  requireRange("foveated_display_fov_deg", foveated_display_fov_deg, 0.0, 179.0);
  requireRange("foveated_hidden_depth", foveated_hidden_depth, 0.0, 1e6);
  requireRange("foveated_coarsen_margin", foveated_coarsen_margin, 1.0, 100.0);
  requireRange("foveated_thin_fill", foveated_thin_fill, 0.0, 1.0);
  requireRange("foveated_thin_level", foveated_thin_level, 0.0, kMaxLevels - 1);
  requireRange("foveated_shallow_spread", foveated_shallow_spread, 0.0, 1.0);
  requireRange("foveated_merge_hold_s", foveated_merge_hold_s, 0.0, 600.0);
  if (foveated_thin_level != std::floor(foveated_thin_level)) {
    throw std::invalid_argument("adaptive setting 'foveated_thin_level' must be a whole level");
  }
  if (gaze_hold_s < gaze_stale_s) {
    throw std::invalid_argument("adaptive setting 'gaze_hold_s' must be >= 'gaze_stale_s'");
  }
}

}  // namespace sph
