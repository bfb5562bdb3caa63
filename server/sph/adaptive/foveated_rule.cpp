#include "sph/adaptive/foveated_rule.h"

#include <algorithm>
#include <cmath>

namespace sph {

Level FoveatedRule::coarsest(int levels) const { return asLevel(std::clamp(levels, kMinLevels, kMaxLevels) - 1); }

void FoveatedRule::step(Simulation& sim, const RuleInput& in, LevelChanges& changes, AdaptiveStats& stats) {
  // The depth field (hidden water) advances every step, from a settled start; without a gaze
  // the eye is taken to rest at the screen's centre.
  if (!sim.surfaceDistanceTracking()) settleSurfaceDistance(sim, in.config, scratch_);
  sim.setSurfaceDistanceTracking(true);
  const bool tracked = in.mode == GazeMode::Tracking || in.mode == GazeMode::Holding;
  const double gx = tracked ? in.gaze.x : 0.5;
  const double gy = tracked ? in.gaze.y : 0.5;
  stats.gaze_x = gx;
  stats.gaze_y = gy;
  FoveatedView view;
  const DecisionCounts wanted = decideFoveated(sim, in.camera, gx, gy, in.config, false,
                                               changes.decisions(sim.particles().size()), scratch_, view);
  stats.split_wanted = wanted.split_wanted;
  stats.merge_wanted = wanted.merge_wanted;
  stats.held = view.held;
  const SplitMergeCounts counts = changes.apply(sim, wanted, coarsest(in.levels), stragglerReach());
  stats.splits = counts.splits;
  stats.merges = counts.merges;
  // Where the eye sees a particle more than one level coarser than it allows (the new fovea after
  // a saccade), the step splits again, level by level, so the eye finds the finest level at once
  // rather than a level a frame later. Water the eye does not see (hidden, off the display) and
  // the rules that do not come from the eye (thin, shallow, graded) split a level a step: a
  // further pass costs a neighbour search and a decision.
  // The decision sized the step to the water at the gaze point as it found it; its own changes
  // can leave farther water there (the particle under the gaze split, its children off the gaze
  // point), from which the eye allows every particle less: a further pass then decides for all
  // the water. Otherwise only the particles the last changes placed and their neighbours can
  // decide otherwise than the step's first decision did (every other particle's level, neighbours
  // and allowance are as they were), and a further pass decides for them alone.
  int changed = counts.splits + counts.merges;
  for (int pass = 2; pass <= in.levels; ++pass) {
    const bool still_coarse = pass < in.levels && view.still_coarse > 0;
    const float fovea_now =
        changed == 0 ? view.fovea_depth : foveaWaterDepth(sim.particles(), in.camera, gx, gy, in.config);
    const bool moved_away = std::isfinite(fovea_now) && fovea_now > view.fovea_depth;
    if (!still_coarse && !moved_away) break;
    sim.rebuildNeighbors();
    const std::span<std::int8_t> decisions = changes.decisions(sim.particles().size());
    SplitPassScope scope;
    if (!moved_away) {
      sim.particles().freshPlacements(fresh_);
      collectNeighbourhoods(sim.grid(), fresh_, mark_, fresh_neighbourhoods_);
      scope = {fresh_neighbourhoods_, fovea_now};
    }
    const DecisionCounts more = decideFoveated(sim, in.camera, gx, gy, in.config, true, decisions, scratch_, view,
                                               moved_away ? nullptr : &scope);
    stats.split_wanted += more.split_wanted;
    ++stats.split_passes;
    changed = changes.applySplits(sim);
    stats.splits += changed;
  }
}

void FoveatedRule::measure(const Simulation& sim, const RuleInput& in, AdaptiveStats& stats) {
  const PerceptualBudget eye =
      meter_.measure(sim.particles(), sim.params(), in.camera, stats.gaze_x, stats.gaze_y, in.config);
  stats.visible = eye.visible;
  stats.over_budget = eye.over_budget;
  stats.fovea_level = eye.gaze_level;
  stats.fovea_width_arcmin = eye.gaze_width_arcmin;
  stats.fovea_mar_arcmin = eye.gaze_mar_arcmin;
}

}  // namespace sph
