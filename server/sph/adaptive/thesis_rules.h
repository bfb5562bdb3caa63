// The thesis's three adaptive methods (3.6), two levels (L0 and L1), water starting at L1:
//   surface  split near the free surface, merge inside, by the character field (3.44)-(3.46);
//   gaze     split under the gaze circle, merge outside its ring (3.47)-(3.48); once the gaze is
//            lost, the surface rule;
//   hybrid   split where both ask, merge where either does.
#pragma once

#include "sph/adaptive/adaptive_rule.h"

namespace sph {

class SurfaceRule : public AdaptiveRule {
 public:
  Method method() const override { return Method::Surface; }
  Level coarsest(int /*levels*/) const override { return Level{1}; }
  GazeMode gazeMode(const GazeInput& /*gaze*/, const AdaptiveConfig& /*config*/) const override {
    return GazeMode::None;
  }
  void step(Simulation& sim, const RuleInput& in, LevelChanges& changes, AdaptiveStats& stats) override;
};

class GazeRule : public AdaptiveRule {
 public:
  Method method() const override { return Method::Gaze; }
  Level coarsest(int /*levels*/) const override { return Level{1}; }
  void step(Simulation& sim, const RuleInput& in, LevelChanges& changes, AdaptiveStats& stats) override;
};

class HybridRule : public AdaptiveRule {
 public:
  Method method() const override { return Method::Hybrid; }
  Level coarsest(int /*levels*/) const override { return Level{1}; }
  void step(Simulation& sim, const RuleInput& in, LevelChanges& changes, AdaptiveStats& stats) override;
};

}  // namespace sph
