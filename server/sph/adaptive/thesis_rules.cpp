#include "sph/adaptive/thesis_rules.h"

#include "sph/adaptive/decide.h"

namespace sph {

namespace {

bool gazeInUse(GazeMode mode) { return mode == GazeMode::Tracking || mode == GazeMode::Holding; }

// The decisions of the surface rule, the gaze rule or both (hybrid), then the changes.
// The surface distance field advances one hop per step (a min per pair in the force loop, then
// decideBySurface). The gaze method needs it only once the gaze is lost: it keeps it moving while
// it holds a stale gaze (gaze_hold_s, 1 s by default, far more steps than the field needs to
// settle), so the fallback starts from a warm field, and spares the pair loop while the gaze is
// tracked. For gaze, decideByGaze then overwrites the surface flags.
void thesisStep(const AdaptiveRule& rule, Simulation& sim, const RuleInput& in, bool use_surface, bool use_gaze,
                bool hybrid, LevelChanges& changes, AdaptiveStats& stats) {
  const bool advance_field = use_surface || in.mode == GazeMode::Holding;
  sim.setSurfaceDistanceTracking(advance_field);
  const std::span<std::int8_t> decisions = changes.decisions(sim.particles().size());
  DecisionCounts wanted;
  if (advance_field) wanted = decideBySurface(sim, in.config, decisions);
  if (use_gaze) {
    wanted = decideByGaze(sim.particles(), in.camera, in.gaze.x, in.gaze.y, in.config, hybrid, decisions);
  }
  stats.split_wanted = wanted.split_wanted;
  stats.merge_wanted = wanted.merge_wanted;
  const SplitMergeCounts counts = changes.apply(sim, wanted, rule.coarsest(in.levels), rule.stragglerReach());
  stats.splits = counts.splits;
  stats.merges = counts.merges;
}

}  // namespace

void SurfaceRule::step(Simulation& sim, const RuleInput& in, LevelChanges& changes, AdaptiveStats& stats) {
  thesisStep(*this, sim, in, true, false, false, changes, stats);
}

void GazeRule::step(Simulation& sim, const RuleInput& in, LevelChanges& changes, AdaptiveStats& stats) {
  const bool use_gaze = gazeInUse(in.mode);
  thesisStep(*this, sim, in, !use_gaze, use_gaze, false, changes, stats);
}

void HybridRule::step(Simulation& sim, const RuleInput& in, LevelChanges& changes, AdaptiveStats& stats) {
  thesisStep(*this, sim, in, true, gazeInUse(in.mode), true, changes, stats);
}

}  // namespace sph
