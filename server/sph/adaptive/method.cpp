#include "sph/adaptive/method.h"

#include <stdexcept>

#include "sph/param_table.h"

namespace sph {

namespace {

// The method registry: a method's name and whether it needs a gaze source (its rule:
// makeAdaptiveRule, adaptive_rule.cpp).
struct MethodEntry {
  Method method;
  const char* name;
  bool uses_gaze;
};
constexpr MethodEntry kMethods[] = {
    {Method::Regular, "regular", false}, {Method::Surface, "surface", false},  {Method::Gaze, "gaze", true},
    {Method::Hybrid, "hybrid", true},    {Method::Foveated, "foveated", true},
};

const MethodEntry* entryOf(Method m) {
  for (const auto& e : kMethods) {
    if (e.method == m) return &e;
  }
  return nullptr;
}

}  // namespace

const char* methodName(Method m) {
  const MethodEntry* e = entryOf(m);
  return e != nullptr ? e->name : "unknown";
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

bool usesGaze(Method m) {
  const MethodEntry* e = entryOf(m);
  return e != nullptr && e->uses_gaze;
}

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
