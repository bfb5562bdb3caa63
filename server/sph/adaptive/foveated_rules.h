// The foveated method's rules for one particle (foveated.h gives them in words, docs/fluids.md,
// "Foveated water", the reasons), each a small function of what the decision measured, so each
// can be changed and tested on its own. They narrow a LevelBounds in this order: acuity, hidden,
// graded, thin, shallow.
#pragma once

#include <algorithm>

#include <Eigen/Core>

namespace sph {

// What the rules allow one particle, as level indices (0 the finest).
struct LevelBounds {
  int target = 0;      // the coarsest level it may have: a coarser particle splits
  int merge_upto = 0;  // the coarsest level a merge may make: a particle finer than this may merge
  int eye_margin = 0;  // the coarsest level the eye allows with the margin (the merge hold counts while it is coarser)
};

// acuity: the coarsest level whose width (width[k], in finest widths) is within `allowed`, and the
// coarsest within it with `margin` to spare (a merge waits for that).
inline LevelBounds acuityBounds(float allowed, const float* width, int coarsest, float margin) {
  int acuity = 0;
  while (acuity < coarsest && width[acuity + 1] <= allowed) ++acuity;
  int with_margin = acuity;
  while (with_margin > 0 && width[with_margin] * margin > allowed) --with_margin;
  return {acuity, with_margin, with_margin};
}

// hidden: water at least `hidden_depth` under the free surface may take the coarsest level whose
// support (`support[k]`, in the depth's unit) its depth covers: that particle's kernel does not
// reach the surface, so it reads its density as deep water does and holds its volume, where a
// coarser one's would read the surface's missing half as a low density. Merging there needs
// `margin` times those depths. Not water whose neighbours spread as a layer (`spread` below
// `least_spread`, as the shallow rule reads it, and `margin` times it for a merge): a sheet
// thinner than the support has no particle the free-surface test finds (its faces' colour-field
// gradients cancel), so the surface distance reads it as deep as it is wide.
inline void hiddenRule(LevelBounds& b, float depth_below_surface, float hidden_depth, const float* support,
                       float spread, float least_spread, float margin, int coarsest) {
  const auto covered = [&](float depth) {
    int k = coarsest;
    while (k > 0 && support[k] > depth) --k;
    return k;
  };
  if (depth_below_surface >= hidden_depth && spread >= least_spread) {
    b.target = std::max(b.target, covered(depth_below_surface));
  }
  if (depth_below_surface >= hidden_depth * margin && spread >= least_spread * margin) {
    b.merge_upto = b.eye_margin = std::max(b.merge_upto, covered(depth_below_surface / margin));
  }
}

// graded: at most `step` levels coarser than the finest neighbour; a merged particle reaches
// farther than either of its pair, so no level more than `step` below its own may lie within its
// reach (`finest_in_merged_reach`: the finest level there, which the decision measures), or the
// merged particle would split again.
inline void gradedRule(LevelBounds& b, int finest_neighbour, int finest_in_merged_reach, int step) {
  b.target = std::min(b.target, finest_neighbour + step);
  b.merge_upto = std::min(b.merge_upto, finest_in_merged_reach + step);
}

// thin: a support filled below `thin_fill` of rho0 (a sheet, a jet, a drop) keeps the particle at
// most at `thin_level`; merging past it needs `margin` times the fill.
inline void thinRule(LevelBounds& b, float fill, float thin_fill, float margin, int thin_level) {
  if (fill < thin_fill) b.target = std::min(b.target, thin_level);
  if (fill < thin_fill * margin) b.merge_upto = std::min(b.merge_upto, thin_level);
}

// Whether the shallow rule can still narrow the bounds (the spread costs an eigenvalue solve
// only where it counts).
inline bool shallowCounts(const LevelBounds& b, int thin_level) {
  return b.target > thin_level || b.merge_upto > thin_level;
}

// shallow: neighbours spread across their thinnest direction less than `least_spread` of their
// mean (water spread on the floor thinner than the particle is wide) keep the particle at most at
// `thin_level`; merging past it needs `margin` times the spread.
inline void shallowRule(LevelBounds& b, float spread, float least_spread, float margin, int thin_level) {
  if (spread < least_spread) b.target = std::min(b.target, thin_level);
  if (spread < least_spread * margin) b.merge_upto = std::min(b.merge_upto, thin_level);
}

// How far a particle's neighbours spread across their thinnest direction, against their mean
// spread: sqrt(smallest eigenvalue / mean eigenvalue) of the second moment of their offsets about
// the particle. About the particle, not their centroid, so a ball and a half ball (a flat free
// surface, a wall) both read 1; one layer of neighbours reads 0, two about 0.5. A spread of at
// least `enough` may be returned as any value >= it.
float neighbourSpread(const Eigen::Matrix3f& moment, float enough);

}  // namespace sph
