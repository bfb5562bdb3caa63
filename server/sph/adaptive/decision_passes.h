// The vectorisable passes of the adaptive decisions (decide.cpp), one form per instruction set
// (simd_level.h), the same source for both (decision_passes.inc).
#pragma once

#include <cstddef>
#include <cstdint>

#include "sph/adaptive/decide.h"
#include "sph/boundary.h"
#include "sph/camera.h"

namespace sph {

// What the second pass of decideBySurface needs from the first: the maxima of (3.45).
struct FieldMaxima {
  float pressure = 0.0f;
  float distance = 0.0f;
  std::uint32_t neighbors[kMaxLevels] = {0, 0};
};

// The arrays of the surface decision, restrict-qualified: the flags are bytes, which may otherwise
// alias anything, and GCC would not vectorise the passes.
struct SurfaceArrays {
  const float* __restrict xyz;  // packed x, y, z
  const float* __restrict hop;
  const float* __restrict normal_length;
  const float* __restrict pressure;
  const Level* __restrict level;
  const std::uint32_t* __restrict neighbors;
  float* __restrict distance;  // surface_distance, written by the first pass
  std::int8_t* __restrict out;
};

// The character field's weights and thresholds, eqs. (3.45)-(3.46), and this step's maxima
// (their inverses, 0 where the maximum is 0).
struct CharacterField {
  float alpha, beta, gamma, inv_weights;
  float split_below, merge_from;
  float max_distance, inv_dmax, inv_fmax;
  float inv_nmax[kMaxLevels];
};

// eq. (3.47)-(3.48) for one particle, with the hysteresis ring. Distances are in units of the
// viewport width (y is a fraction of the height).
struct GazeCircle {
  FastProjection projection;
  float x, y, inv_aspect, inner_radius, outer_radius;

  std::int8_t decide(float px, float py, float pz, float radius) const {
    const FastScreenDisc disc = projection.project(px, py, pz, radius);
    const float dx = disc.x - x;
    const float dy = (disc.y - y) * inv_aspect;
    const float dist2 = dx * dx + dy * dy;
    const float inner = inner_radius + disc.radius;
    const float outer = outer_radius + disc.radius;
    // f = sgn(|r_i - r_gaze|^2 - (r_i + r_gaze)^2); SPLIT where f < 0. Behind the eye: MERGE.
    const int split = disc.in_front & (dist2 < inner * inner);
    const int merge = !disc.in_front | (dist2 > outer * outer);
    // Arithmetic rather than a conditional: a split wins, and the ring (neither) is kRemain = 0.
    return static_cast<std::int8_t>(split * kSplit + (1 - split) * merge * kMerge);
  }
};

// The passes over particles [begin, end):
//   surfaceDistances        decideBySurface's first: d_i and the maxima (with obstacles or not)
//   characterDecisions      its second: cf (3.45) and the decision (3.46)
//   gazeDecisions           decideByGaze's (3.47)-(3.48), or the hybrid rule
struct DecisionPassForms {
  FieldMaxima (*surfaceDistances)(const SurfaceArrays& arrays, std::size_t begin, std::size_t end,
                                  float surface_threshold, bool include_walls, const BoxState& box,
                                  const Boundary& boundary);
  DecisionCounts (*characterDecisions)(const SurfaceArrays& arrays, std::size_t begin, std::size_t end,
                                       const CharacterField& field);
  DecisionCounts (*gazeDecisions)(const GazeCircle& gaze, const float* xyz, const float* radius,
                                  const Level* level, std::int8_t* out, std::size_t begin, std::size_t end,
                                  bool hybrid);
};

namespace scalar {
DecisionPassForms decisionPassForms();
}  // namespace scalar
namespace avx2 {
DecisionPassForms decisionPassForms();
}  // namespace avx2
namespace avx512 {
DecisionPassForms decisionPassForms();
}  // namespace avx512
// The forms this CPU runs (simd_level.h).
DecisionPassForms decisionPassForms();

}  // namespace sph
