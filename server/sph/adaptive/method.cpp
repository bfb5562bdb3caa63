#include "sph/adaptive/method.h"

#include <algorithm>

#include <stdexcept>

#include "sph/param_table.h"

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

// The ranges in the settings table, then what holds between settings.
void AdaptiveConfig::validate() const {
  checkRanges(*this);
  if (alpha + beta + gamma <= 0.0) {
    throw std::invalid_argument("parameters 'alpha' + 'beta' + 'gamma' must be > 0");
  }
  if (gaze_ring_radius < gaze_radius) {
    throw std::invalid_argument("parameter 'gaze_ring_radius' must be >= 'gaze_radius'");
  }
  if (gaze_hold_s < gaze_stale_s) {
    throw std::invalid_argument("parameter 'gaze_hold_s' must be >= 'gaze_stale_s'");
  }
}

}  // namespace sph
