#include "sph/adaptive/adaptive_controller.h"

#include <stdexcept>
#include <string>

namespace sph {

namespace {

std::unique_ptr<AdaptiveRule> ruleOf(Method method) {
  std::unique_ptr<AdaptiveRule> rule = makeAdaptiveRule(method);
  if (rule == nullptr)
    throw std::invalid_argument(std::string("the ") + methodName(method) + " method has no adaptive step");
  return rule;
}

}  // namespace

AdaptiveController::AdaptiveController(Method method, int levels, const AdaptiveConfig& config,
                                       const ScreenCamera& camera)
    : AdaptiveController(ruleOf(method), levels, config, camera) {}

AdaptiveController::AdaptiveController(std::unique_ptr<AdaptiveRule> rule, int levels, const AdaptiveConfig& config,
                                       const ScreenCamera& camera)
    : rule_(std::move(rule)), levels_(levels), config_(config), camera_(camera) {
  if (rule_ == nullptr) throw std::invalid_argument("adaptive controller: no rule");
  if (levels < kMinLevels || levels > kMaxLevels) {
    throw std::invalid_argument("adaptive controller: " + std::to_string(levels) + " levels, not " +
                                std::to_string(kMinLevels) + " to " + std::to_string(kMaxLevels));
  }
  config_.validate();
  if (!isUsable(camera_)) throw std::invalid_argument("adaptive controller: unusable camera");
}

void AdaptiveController::setCamera(const ScreenCamera& camera) {
  if (!isUsable(camera)) throw std::invalid_argument("unusable camera (non-finite or empty viewport)");
  camera_ = camera;
}

void AdaptiveController::setConfig(const AdaptiveConfig& config) {
  config.validate();
  config_ = config;
}

void AdaptiveController::setMethod(Method method) {
  std::unique_ptr<AdaptiveRule> rule = ruleOf(method);
  if (rule->coarsest(levels_) != rule_->coarsest(levels_)) {
    throw std::invalid_argument(std::string("the ") + methodName(method) +
                                " method needs a new simulation (other levels)");
  }
  rule_ = std::move(rule);
}

void AdaptiveController::apply(Simulation& sim) {
  stats_ = AdaptiveStats{};
  const GazeMode mode = rule_->gazeMode(gaze_, config_);
  stats_.gaze_mode = mode;
  stats_.gaze_x = gaze_.x;  // the rule may put the point it used instead
  stats_.gaze_y = gaze_.y;
  stats_.gaze_age_s = gaze_.age_s;
  rule_->step(sim, RuleInput{config_, camera_, gaze_, mode, levels_}, changes_, stats_);
  if (measure_each_step_) measureEye(sim);
}

void AdaptiveController::measureEye(const Simulation& sim) {
  rule_->measure(sim, RuleInput{config_, camera_, gaze_, stats_.gaze_mode, levels_}, stats_);
}

std::unique_ptr<AdaptiveController> makeAdaptiveController(Method method, int levels, const AdaptiveConfig& config,
                                                           const ScreenCamera& camera) {
  if (makeAdaptiveRule(method) == nullptr) return nullptr;
  return std::make_unique<AdaptiveController>(method, levels, config, camera);
}

}  // namespace sph
