// One adaptive method: its levels, how it reads the gaze, and its rule for which particles split
// and merge each step. The controller (adaptive_controller.h) holds one and knows no method by
// name; adding a method is a rule of its own, a row of the method registry (method.cpp) and a case
// in makeAdaptiveRule (adaptive_rule.cpp).
// docs/design.md, "Adding an adaptive method", walks through one.
#pragma once

#include <memory>

#include "sph/adaptive/level_changes.h"
#include "sph/adaptive/method.h"
#include "sph/camera.h"
#include "sph/simulation.h"

namespace sph {

struct AdaptiveStats {
  int splits = 0;        // particles split this step
  int merges = 0;        // pairs merged this step
  int split_wanted = 0;  // particles whose decision was SPLIT (including ones with no room)
  int merge_wanted = 0;  // particles whose decision was MERGE (including unpaired ones)
  int split_passes = 1;  // decisions this step: foveated adds split passes after a saccade
  HeldFiner held;        // foveated (FoveatedView); zero for the thesis's methods
  GazeMode gaze_mode = GazeMode::None;
  // foveated: what the eye gets (perceptual_budget.h), measured after the step's splits; zero
  // (and -1) for the thesis's methods.
  int visible = 0;
  int over_budget = 0;
  int fovea_level = -1;             // the level of the particle under the gaze; -1: none
  double fovea_width_arcmin = 0.0;  // that particle's angular width; 0: the gaze falls on no water
  double fovea_mar_arcmin = 0.0;    // the eye's minimum angle of resolution there
  // The gaze point the step used (normalized, origin top left): the sample's, or where the rule
  // used another, that one (foveated: the screen's centre once the gaze is lost).
  double gaze_x = 0.5;
  double gaze_y = 0.5;
  double gaze_age_s = 0.0;
};

// What a rule reads each step besides the simulation.
struct RuleInput {
  const AdaptiveConfig& config;
  const ScreenCamera& camera;
  const GazeInput& gaze;
  GazeMode mode;  // the rule's gazeMode() of `gaze`
  int levels;     // the run's level count (SimParams::levels)
};

class AdaptiveRule {
 public:
  virtual ~AdaptiveRule() = default;
  virtual Method method() const = 0;
  // The coarsest level the rule makes, where its water starts (startLevel).
  virtual Level coarsest(int levels) const = 0;
  // How far a merging particle left without a partner of its level looks for one, in its support
  // radii (pairStragglers): far enough to reach a sibling left behind in coarser water, near
  // enough that the merged particle lands inside the water between them.
  virtual float stragglerReach() const { return 2.0f; }
  // Which gaze a step uses: tracking a fresh sample, holding a stale one, or a fallback once it
  // is lost (gaze_stale_s, gaze_hold_s).
  virtual GazeMode gazeMode(const GazeInput& gaze, const AdaptiveConfig& config) const;
  // Decides this step's splits and merges, applies them through `changes` (LevelChanges::apply with
  // coarsest() and stragglerReach()) and fills the stats it owns; the controller fills the gaze's.
  virtual void step(Simulation& sim, const RuleInput& in, LevelChanges& changes, AdaptiveStats& stats) = 0;
  // What the eye gets (perceptual_budget.h) from the particles as they are, into the stats'
  // visible, over_budget and fovea fields, for a rule that sizes particles by the eye; nothing
  // for the others. An instrument, not part of the method: the caller says when
  // (AdaptiveController::measureEye), around the gaze point the last step used.
  virtual void measure(const Simulation& /*sim*/, const RuleInput& /*in*/, AdaptiveStats& /*stats*/) {}
};

// The rule for `method`; nullptr for Method::Regular.
std::unique_ptr<AdaptiveRule> makeAdaptiveRule(Method method);

}  // namespace sph
