// The decision pass of the adaptive step: one SPLIT / MERGE / REMAIN flag per particle, computed in
// parallel, each particle writing only its own flag (so the result does not depend on the thread
// count).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sph/adaptive/method.h"
#include "sph/camera.h"
#include "sph/simulation.h"

namespace sph {

enum Decision : std::int8_t { kRemain = 0, kSplit = 1, kMerge = 2 };

// Whether a decision acts on a particle of level c: every level above L0 splits (into two of
// the level below), every level below `coarsest` merges (two into one of the level above); the
// thesis's methods have coarsest L1, so only L1 splits and only L0 merges. Branch-free
// (`&`), for the scans over every particle. (The vectorised decide loops count with their own
// arithmetic: with these, GCC 12 vectorised the gaze decision less fully.)
inline bool wantsSplit(std::int8_t decision, Level c) { return (decision == kSplit) & (c != Level{0}); }
inline bool wantsMerge(std::int8_t decision, Level c, Level coarsest) {
  return (decision == kMerge) & (levelIndex(c) < levelIndex(coarsest));
}

// What the decisions ask for: particles that can split flagged SPLIT, ones that can merge MERGE.
struct DecisionCounts {
  int split_wanted = 0;
  int merge_wanted = 0;
};

// foveated: the particles finer than the coarsest level that the rules keep from merging, by the
// first rule in this order that does (the others ask to merge).
struct HeldFiner {
  int eye = 0;      // acuity, or not hidden deep enough under the surface
  int grading = 0;  // a finer level within a merged particle's reach
  int thin = 0;     // thin or shallow water
  int waiting = 0;  // placed this frame or earlier, or within the merge hold
  int total() const { return eye + grading + thin + waiting; }
};

// Surface based, eqs. (3.44)-(3.46): the character field from the distance to the surface (or a
// boundary), the pressure and the neighbour count. Uses the neighbour lists and |n| of the step
// that just ran, and updates the particles' surface_distance: d_i = 0 on the surface, else the
// smaller of the boundary distance and this step's hop (the neighbours' previous d plus the pair
// distance, computed in the force loop). The field thus advances one hop per step, which keeps up
// with the fluid (it moves well under a support radius per step) at the cost of one min per pair,
// where recomputing it from scratch took a large share of the step (docs/performance.md).
DecisionCounts decideBySurface(Simulation& sim, const AdaptiveConfig& config, std::span<std::int8_t> out);

// Eye-tracking based, eqs. (3.47)-(3.48), with a hysteresis ring: SPLIT where the projected particle
// overlaps the gaze circle, MERGE where it lies wholly outside the ring (or behind the eye), REMAIN
// in the ring. With `hybrid`, `out` holds the surface decisions on entry and receives the hybrid
// rule: SPLIT only where both ask for it, MERGE where either does, else REMAIN (one pass, so the
// hybrid method costs no more than gaze and surface together). Both return the counts of the
// decisions they leave in `out`.
DecisionCounts decideByGaze(const ParticleSet& particles, const ScreenCamera& camera, double gaze_x, double gaze_y,
                            const AdaptiveConfig& config, bool hybrid, std::span<std::int8_t> out);

}  // namespace sph
