#include "sph/adaptive/method.h"

#include <memory>
#include <stdexcept>

#include "sph/adaptive/adaptive_rule.h"
#include "sph/adaptive/foveated_rule.h"
#include "sph/adaptive/thesis_rules.h"
#include "sph/param_table.h"

namespace sph {

namespace {

// The method registry: a method's name, whether it needs a gaze source, and its rule.
struct MethodEntry {
  Method method;
  const char* name;
  bool uses_gaze;
  std::unique_ptr<AdaptiveRule> (*rule)();  // nullptr: no adaptive step
};
template <class Rule>
std::unique_ptr<AdaptiveRule> make() {
  return std::make_unique<Rule>();
}
constexpr MethodEntry kMethods[] = {
    {Method::Regular, "regular", false, nullptr},
    {Method::Surface, "surface", false, make<SurfaceRule>},
    {Method::Gaze, "gaze", true, make<GazeRule>},
    {Method::Hybrid, "hybrid", true, make<HybridRule>},
    {Method::Foveated, "foveated", true, make<FoveatedRule>},
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

std::unique_ptr<AdaptiveRule> makeAdaptiveRule(Method method) {
  const MethodEntry* e = entryOf(method);
  return e != nullptr && e->rule != nullptr ? e->rule() : nullptr;
}

Level startLevel(Method m, int levels) {
  const std::unique_ptr<AdaptiveRule> rule = makeAdaptiveRule(m);
  return rule != nullptr ? rule->coarsest(levels) : Level{0};
}

Level coarsestLevel(Method m, int levels) {
  const std::unique_ptr<AdaptiveRule> rule = makeAdaptiveRule(m);
  return rule != nullptr ? rule->coarsest(levels) : Level{1};
}

bool usesGaze(Method m) {
  const MethodEntry* e = entryOf(m);
  return e != nullptr && e->uses_gaze;
}

GazeMode AdaptiveRule::gazeMode(const GazeInput& gaze, const AdaptiveConfig& config) const {
  if (!gaze.present || !(gaze.age_s <= config.gaze_hold_s)) return GazeMode::Fallback;
  return gaze.age_s <= config.gaze_stale_s ? GazeMode::Tracking : GazeMode::Holding;
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
