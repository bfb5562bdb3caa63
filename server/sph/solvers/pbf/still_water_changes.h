// A level change (a split, a merge) in still water, taken up slowly. Where the adaptive step puts
// a split's children or a merged particle is never where the water would hold them: pushed into
// place within a frame, the neighbourhood's change of volume and of forces moves the whole water
// above it, and every change stirs a resting tank (docs/level_changes.md, "Changes in still water").
// Orthmann & Kolb (2012) blend a new particle's contributions in over several steps; in pbf the
// same is done in the constraint and the velocity update, per particle, after the local
// placement (local_placement.h) has moved the fresh particles out of each other's way:
// - every placed particle in still water, and its neighbours, keeps the density the change and
//   the placement gave it as an offset of its constraint's rest density
//   (PbfAttributes::density_offset), which fades by 1 / kOffsetFadeFrames a frame: the water
//   takes the change up over a third of a second;
// - still particles within two neighbour hops of the change, while its particles are placed or
//   hold an offset beyond kTakingUp and kDampedFrames after, keep kStillDamping of the speed each
//   step gives them (PbfAttributes::still_damping): they settle without building the
//   momentum that would carry them past their new places.
// Water moving faster than kStillSpeed is untouched (the Martin & Moyce fronts move by tenths of a
// per cent with this).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sph/neighbor_grid.h"
#include "sph/particles.h"
#include "sph/solvers/pbf/pbf_passes.h"

namespace sph {

class StillWaterChanges {
 public:
  // Water slower than this (m/s) at a step's start is still. Below the speed a particle reaches
  // falling under the damping alone (kStillDamping / (1 - kStillDamping) g dt, 0.057 m/s at pbf's
  // 2.5 ms steps), so water that starts to fall is not held.
  static constexpr float kStillSpeed = 0.05f;
  // The offset falls by 1 / kOffsetFadeFrames a frame, and is dropped below kOffsetFloor (kg/m^3).
  static constexpr int kOffsetFadeFrames = 30;
  static constexpr float kOffsetFloor = 0.01f;
  // An offset holds at most this share of rest density either way.
  static constexpr float kOffsetLimit = 0.3f;
  static constexpr int kDampedFrames = 80;
  // An offset larger than this (kg/m^3, either way) is still being taken up: its particle and
  // its neighbours stay marked for damping.
  static constexpr float kTakingUp = 1.0f;
  static constexpr float kStillDamping = 0.7f;

  // In the frame's first step, after the prediction, the neighbour grid and the near-placement
  // marks, before the local placement: every placed particle (fresh, or not yet in place) or one
  // whose offset is still being taken up, and its neighbours, are marked for damping. Keeps the
  // densities the frame starts with for holdChanges. Returns whether any particle is placed.
  bool markDamped(ParticleSet& p, const NeighborGrid& grid);

  // After the local placement, where markDamped found any placed: every still particle that is
  // placed (fresh, or not yet in place) or near a fresh placement adds the change of its density
  // since the frame's start to its offset, so that the constraint leaves it as the change (and,
  // while it is not in place, each frame's step) left it; a constraint pass over them alone
  // measures it (`a` and `c` the solver's, positions at the particles'; the pass's multipliers
  // are the caller's to reset).
  void holdChanges(ParticleSet& p, const NeighborGrid& grid, std::span<const float> start_speed, PbfArrays& a,
                   const PbfConstants& c);

  // Whether a particle whose speed at the step's start is `start_speed` is still.
  static bool still(float start_speed) { return start_speed < kStillSpeed; }

  // Whether particle i keeps only kStillDamping of the velocity a step gives it: marked, and still.
  static bool damps(const ParticleSet& p, std::size_t i, float start_speed) {
    return p.still_damping[i] > 0 && still(start_speed);
  }

  // After the frame: the offsets fade, the damping marks count down.
  static void fade(ParticleSet& p);

 private:
  std::vector<float> start_density_;
  std::vector<std::uint32_t> held_;
};

}  // namespace sph
