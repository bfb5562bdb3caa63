#include "sph/adaptive/adaptive_rule.h"

#include <memory>

#include "sph/adaptive/foveated_rule.h"
#include "sph/adaptive/thesis_rules.h"

namespace sph {

// Each adaptive method's rule; a new method adds its case here and its row in method.cpp's registry.
std::unique_ptr<AdaptiveRule> makeAdaptiveRule(Method method) {
  switch (method) {
    case Method::Regular:
      return nullptr;
    case Method::Surface:
      return std::make_unique<SurfaceRule>();
    case Method::Gaze:
      return std::make_unique<GazeRule>();
    case Method::Hybrid:
      return std::make_unique<HybridRule>();
    case Method::Foveated:
      return std::make_unique<FoveatedRule>();
  }
  return nullptr;
}

Level startLevel(Method m, int levels) {
  const std::unique_ptr<AdaptiveRule> rule = makeAdaptiveRule(m);
  return rule != nullptr ? rule->coarsest(levels) : Level{0};
}

Level coarsestLevel(Method m, int levels) {
  const std::unique_ptr<AdaptiveRule> rule = makeAdaptiveRule(m);
  return rule != nullptr ? rule->coarsest(levels) : Level{1};
}

GazeMode AdaptiveRule::gazeMode(const GazeInput& gaze, const AdaptiveConfig& config) const {
  if (!gaze.present || !(gaze.age_s <= config.gaze_hold_s)) return GazeMode::Fallback;
  return gaze.age_s <= config.gaze_stale_s ? GazeMode::Tracking : GazeMode::Holding;
}

}  // namespace sph
