// The adaptive step of the surface, gaze and hybrid methods (thesis 3.6): a parallel pass decides
// SPLIT / MERGE / REMAIN per particle, then split (3.37)-(3.39) and merge (3.40)-(3.43) are applied
// and the arrays compacted. Install it with Simulation::setAdaptiveStep; keep a raw pointer to feed
// it gaze and camera between steps.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "sph/adaptive/foveated.h"
#include "sph/adaptive/method.h"
#include "sph/adaptive/perceptual_budget.h"
#include "sph/adaptive/split_merge.h"
#include "sph/camera.h"
#include "sph/simulation.h"

namespace sph {

struct AdaptiveStats {
  int splits = 0;        // L1 particles split this step
  int merges = 0;        // L0 pairs merged this step
  int split_wanted = 0;  // particles whose decision was SPLIT (including ones with no room)
  int merge_wanted = 0;  // particles whose decision was MERGE (including unpaired ones)
  GazeMode gaze_mode = GazeMode::None;
  // foveated: what the eye gets (perceptual_budget.h), measured after the step's splits; zero
  // (and -1) for the thesis's methods.
  int visible = 0;
  int over_budget = 0;
  int fovea_level = -1;             // the level of the particle under the gaze; -1: none
  double fovea_width_arcmin = 0.0;  // that particle's angular width; 0: the gaze falls on no water
  double fovea_mar_arcmin = 0.0;    // the eye's minimum angle of resolution there
  double gaze_x = 0.5;              // the gaze point the step used (normalized, origin top left)
  double gaze_y = 0.5;
  double gaze_age_s = 0.0;
};

class AdaptiveController : public AdaptiveStep {
 public:
  // `method` must not be Method::Regular (it has no adaptive step). Throws std::invalid_argument
  // for that, for an invalid config and for `levels` (the run's level count, SimParams::levels)
  // outside [kMinLevels, kMaxLevels]. setMethod keeps the method's levels (coarsestLevel):
  // changing them needs a new Simulation (its grid fits the coarsest level's support).
  AdaptiveController(Method method, int levels, const AdaptiveConfig& config, const ScreenCamera& camera);

  void setGaze(const GazeInput& gaze) { gaze_ = gaze; }
  void setCamera(const ScreenCamera& camera);
  void setConfig(const AdaptiveConfig& config);
  void setMethod(Method method);

  Method method() const { return method_; }
  const AdaptiveConfig& config() const { return config_; }
  const ScreenCamera& camera() const { return camera_; }
  const GazeInput& gaze() const { return gaze_; }
  const AdaptiveStats& lastStats() const { return stats_; }

  void apply(Simulation& sim) override;
  Level coarsest() const override { return coarsestLevel(method_, levels_); }

 private:
  Method method_;
  int levels_;
  AdaptiveConfig config_;
  ScreenCamera camera_;
  GazeInput gaze_;
  AdaptiveStats stats_;
  GazeMode gazeMode() const;
  // The thesis's decisions (surface, gaze, hybrid) into decision_.
  DecisionCounts decideThesis(Simulation& sim, GazeMode mode);
  // Partners, split and merge for decision_, and the step's stats.
  void finish(Simulation& sim, const DecisionCounts& wanted, GazeMode mode);

  // Scratch, sized once to the particle capacity (no allocation inside a step after the first).
  std::vector<std::int8_t> decision_;
  std::vector<std::int32_t> partner_;
  std::vector<std::uint8_t> keep_;
  std::vector<std::uint32_t> split_list_;
  PartnerScratch partner_scratch_;
  StragglerScratch stragglers_;
  FoveatedScratch foveated_;
  PerceptualBudgetMeter budget_meter_;
};

// nullptr for Method::Regular.
std::unique_ptr<AdaptiveController> makeAdaptiveController(Method method, int levels, const AdaptiveConfig& config,
                                                           const ScreenCamera& camera);

}  // namespace sph
