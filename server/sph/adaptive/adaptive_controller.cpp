#include "sph/adaptive/adaptive_controller.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "sph/adaptive/decide.h"
#include "sph/adaptive/split_merge.h"

namespace sph {

namespace {

// In support radii (pairStragglers).
constexpr float kFoveatedStragglerReach = 4.0f;

void requireAdaptive(Method method) {
  if (method == Method::Regular) {
    throw std::invalid_argument("the regular method has no adaptive step");
  }
}

}  // namespace

AdaptiveController::AdaptiveController(Method method, int levels, const AdaptiveConfig& config,
                                       const ScreenCamera& camera)
    : method_(method), levels_(levels), config_(config), camera_(camera) {
  requireAdaptive(method);
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
  requireAdaptive(method);
  if (coarsestLevel(method, levels_) != coarsestLevel(method_, levels_)) {
    throw std::invalid_argument(std::string("the ") + methodName(method) +
                                " method needs a new simulation (other levels)");
  }
  method_ = method;
}

GazeMode AdaptiveController::gazeMode() const {
  if (method_ == Method::Surface) return GazeMode::None;
  if (!gaze_.present || !(gaze_.age_s <= config_.gaze_hold_s)) return GazeMode::Fallback;
  return gaze_.age_s <= config_.gaze_stale_s ? GazeMode::Tracking : GazeMode::Holding;
}

void AdaptiveController::apply(Simulation& sim) {
  const ParticleSet& p = sim.particles();
  const std::size_t n = p.size();
  decision_.resize(n);
  partner_.resize(n);

  const GazeMode mode = gazeMode();
  stats_ = AdaptiveStats{};
  if (method_ == Method::Foveated) {
    // The depth field (hidden water) advances every step; without a gaze the eye is taken to
    // rest at the screen's centre.
    sim.setSurfaceDistanceTracking(true);
    const bool tracked = mode == GazeMode::Tracking || mode == GazeMode::Holding;
    const double gx = tracked ? gaze_.x : 0.5;
    const double gy = tracked ? gaze_.y : 0.5;
    FoveatedView view;
    const DecisionCounts wanted = decideFoveated(sim, camera_, gx, gy, config_, false, decision_, foveated_, view);
    finish(sim, wanted, mode);
    // Where the eye sees a particle more than one level coarser than it allows (the new fovea
    // after a saccade), the step splits again, level by level, so the eye finds the finest level
    // at once rather than a level a frame later. Water the eye does not see (hidden, off the
    // display) and the rules that do not come from the eye (thin, shallow, graded) split a level
    // a step: a further pass costs a neighbour search and a decision over all the water.
    for (int pass = 2; pass < levels_ && view.still_coarse > 0; ++pass) {
      sim.rebuildNeighbors();
      decision_.resize(sim.particles().size());
      partner_.assign(sim.particles().size(), -1);
      const DecisionCounts more = decideFoveated(sim, camera_, gx, gy, config_, true, decision_, foveated_, view);
      stats_.split_wanted += more.split_wanted;
      stats_.splits += applySplitMerge(sim, decision_, partner_, keep_, split_list_).splits;
    }
    const PerceptualBudget eye = budget_meter_.measure(sim.particles(), sim.params(), camera_, gx, gy, config_);
    stats_.visible = eye.visible;
    stats_.over_budget = eye.over_budget;
    stats_.fovea_level = eye.gaze_level;
    stats_.fovea_width_arcmin = eye.gaze_width_arcmin;
    stats_.fovea_mar_arcmin = eye.gaze_mar_arcmin;
    return;
  }
  finish(sim, decideThesis(sim, mode), mode);
}

DecisionCounts AdaptiveController::decideThesis(Simulation& sim, GazeMode mode) {
  const ParticleSet& p = sim.particles();
  const bool use_gaze = mode == GazeMode::Tracking || mode == GazeMode::Holding;
  const bool use_surface = method_ == Method::Surface || method_ == Method::Hybrid || !use_gaze;
  // The surface distance field advances one hop per step (a min per pair in the force loop, then
  // decideBySurface). The gaze method needs it only once the gaze is lost: it keeps it moving
  // while it holds a stale gaze (gaze_hold_s, 1 s by default, far more steps than the field
  // needs to settle), so the fallback starts from a warm field, and spares the pair loop while
  // the gaze is tracked. For gaze, decideByGaze then overwrites the surface flags.
  const bool advance_field = use_surface || mode == GazeMode::Holding;
  sim.setSurfaceDistanceTracking(advance_field);
  DecisionCounts wanted;
  if (advance_field) {
    wanted = decideBySurface(sim, config_, decision_);
  }
  if (use_gaze) {
    wanted = decideByGaze(p, camera_, gaze_.x, gaze_.y, config_, method_ == Method::Hybrid, decision_);
  }
  return wanted;
}

void AdaptiveController::finish(Simulation& sim, const DecisionCounts& wanted, GazeMode mode) {
  const ParticleSet& p = sim.particles();
  const Level coarsest = coarsestLevel(method_, levels_);
  stats_.split_wanted = wanted.split_wanted;
  stats_.merge_wanted = wanted.merge_wanted;
  if (wanted.merge_wanted > 0) {
    choosePartners(p, sim.grid(), decision_, partner_, coarsest, partner_scratch_);
    // Stragglers pair within two of their support radii: far enough to reach a sibling left
    // behind in coarser water, near enough that the merged particle lands inside the water
    // between them. The foveated method's reach farther: a fine particle left over where the eye
    // allows a coarser one holds its neighbourhood fine (grading) until it pairs, and where it
    // may merge the eye does not resolve where its mass goes.
    const float reach = method_ == Method::Foveated ? kFoveatedStragglerReach : 2.0f;
    pairStragglers(p, decision_, partner_, reach, coarsest, stragglers_);
  } else {
    std::fill(partner_.begin(), partner_.end(), -1);
  }
  const SplitMergeCounts counts = applySplitMerge(sim, decision_, partner_, keep_, split_list_);
  stats_.splits = counts.splits;
  stats_.merges = counts.merges;
  stats_.gaze_mode = mode;
  stats_.gaze_x = gaze_.x;
  stats_.gaze_y = gaze_.y;
  stats_.gaze_age_s = gaze_.age_s;
}

std::unique_ptr<AdaptiveController> makeAdaptiveController(Method method, int levels, const AdaptiveConfig& config,
                                                           const ScreenCamera& camera) {
  if (method == Method::Regular) return nullptr;
  return std::make_unique<AdaptiveController>(method, levels, config, camera);
}

}  // namespace sph
