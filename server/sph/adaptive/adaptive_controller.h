// The adaptive step (thesis 3.6): each step the method's rule (adaptive_rule.h) decides SPLIT /
// MERGE / REMAIN per particle and applies the changes (level_changes.h). Install it with
// Simulation::setAdaptiveStep; keep a raw pointer to feed it gaze and camera between steps.
#pragma once

#include <memory>

#include "sph/adaptive/adaptive_rule.h"
#include "sph/adaptive/level_changes.h"
#include "sph/adaptive/method.h"
#include "sph/camera.h"
#include "sph/simulation.h"

namespace sph {

class AdaptiveController : public AdaptiveStep {
 public:
  // `method` must not be Method::Regular (it has no adaptive step). Throws std::invalid_argument
  // for that, for an invalid config and for `levels` (the run's level count, SimParams::levels)
  // outside [kMinLevels, kMaxLevels]. setMethod keeps the method's levels (AdaptiveRule::coarsest):
  // changing them needs a new Simulation (its grid fits the coarsest level's support).
  AdaptiveController(Method method, int levels, const AdaptiveConfig& config, const ScreenCamera& camera);
  // A rule of the caller's own (a method outside the registry); the same checks.
  AdaptiveController(std::unique_ptr<AdaptiveRule> rule, int levels, const AdaptiveConfig& config,
                     const ScreenCamera& camera);

  void setGaze(const GazeInput& gaze) { gaze_ = gaze; }
  void setCamera(const ScreenCamera& camera);
  void setConfig(const AdaptiveConfig& config);
  void setMethod(Method method);

  Method method() const { return rule_->method(); }
  const AdaptiveConfig& config() const { return config_; }
  const ScreenCamera& camera() const { return camera_; }
  const GazeInput& gaze() const { return gaze_; }
  const AdaptiveStats& lastStats() const { return stats_; }

  void apply(Simulation& sim) override;
  // Measures what the eye gets (AdaptiveRule::measure) into lastStats(), from the particles as
  // they are now. With measureEachStep (the default) every apply() ends with it; a caller that
  // needs the figures less often (the server, once per published frame) or outside its timed step
  // (the bench) turns that off and calls this itself.
  void measureEye(const Simulation& sim);
  void setMeasureEachStep(bool each_step) { measure_each_step_ = each_step; }
  Level coarsest() const override { return rule_->coarsest(levels_); }

 private:
  std::unique_ptr<AdaptiveRule> rule_;
  int levels_;
  AdaptiveConfig config_;
  ScreenCamera camera_;
  GazeInput gaze_;
  AdaptiveStats stats_;
  LevelChanges changes_;
  bool measure_each_step_ = true;
};

// nullptr for Method::Regular.
std::unique_ptr<AdaptiveController> makeAdaptiveController(Method method, int levels, const AdaptiveConfig& config,
                                                           const ScreenCamera& camera);

}  // namespace sph
