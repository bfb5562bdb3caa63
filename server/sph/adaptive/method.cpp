#include "sph/adaptive/method.h"

#include <stdexcept>

#include "sph/param_table.h"

namespace sph {

namespace {

// The method registry: a method's name and what the programs around it need to know of it (its
// rule: makeAdaptiveRule, adaptive_rule.cpp).
struct MethodEntry {
  Method method;
  const char* name;
  bool adapts;
  bool uses_gaze;
  bool gaze_circle;
  bool acuity_sized;
};
constexpr MethodEntry kMethods[] = {
    {Method::Regular, "regular", false, false, false, false}, {Method::Surface, "surface", true, false, false, false},
    {Method::Gaze, "gaze", true, true, true, false},          {Method::Hybrid, "hybrid", true, true, true, false},
    {Method::Foveated, "foveated", true, true, false, true},
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

bool adapts(Method m) {
  const MethodEntry* e = entryOf(m);
  return e != nullptr && e->adapts;
}

bool usesGaze(Method m) {
  const MethodEntry* e = entryOf(m);
  return e != nullptr && e->uses_gaze;
}

bool refinesGazeCircle(Method m) {
  const MethodEntry* e = entryOf(m);
  return e != nullptr && e->gaze_circle;
}

bool sizesByAcuity(Method m) {
  const MethodEntry* e = entryOf(m);
  return e != nullptr && e->acuity_sized;
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
