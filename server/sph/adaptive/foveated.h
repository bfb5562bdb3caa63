// The foveated method's decision: each particle's target level from what the eye can resolve where
// it is seen, then SPLIT (one level finer) where a particle is coarser than its target and MERGE
// (one level coarser, with a partner of its level) where the eye allows the next level with a
// margin. docs/fluids.md, "Foveated water", gives the rules and why; each is a function of
// foveated_rules.h.
//
//   acuity   a particle may look q MAR(e) / MAR(0) times as wide, in visual angle, as a finest
//            particle at the gaze point (Guenter et al. 2012: MAR(e) = w0 + m e); its level is the
//            coarsest whose width, seen from its distance, stays within that. Eccentricity e is
//            the angle between the gaze and the particle as the user sees the display (its size
//            in the visual field is a setting), not as the camera renders it; 0 for the particle
//            whose disc covers the gaze point.
//   hidden   water deeper under the free surface than a few finest spacings may take the
//            coarsest level whose support its depth covers (its kernel then reads deep water's
//            density), unless its neighbours lie nearly in one layer (a sheet the surface test
//            misses).
//   thin     a particle with a thin neighbourhood (a sheet, a jet, a drop, the front's tip) stays
//            at most at the thin level, so thin water keeps particles across it.
//   shallow  a particle whose neighbours lie nearly in one layer (water spread on the floor
//            thinner than the particle is wide) stays at most at the thin level.
//   graded   no particle is more than foveated_grading_step levels coarser than its finest
//            neighbour (2: mass ratio 4 at most in a pair the solvers see); a merge needs no
//            level beyond the step within the merged particle's reach.
//
// Every particle writes only its own decision and target: the result does not depend on the
// thread count.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sph/adaptive/decide.h"
#include "sph/adaptive/method.h"
#include "sph/camera.h"
#include "sph/simulation.h"

namespace sph {

// What the last decision saw, for the controller's further split passes. What the eye gets is
// measured apart from the rule (perceptual_budget.h).
struct FoveatedView {
  // Seen particles (on the display, not hidden under water) coarser than the eye allows (at the
  // periphery gain in force) once this decision's splits are made: a further split pass in the
  // step is for them.
  int still_coarse = 0;
  float fovea_depth = 0.0f;  // distance of the water at the gaze point, metres
  HeldFiner held;            // counted by a step's first decision
};

// The water at the gaze point, the reference the perceptual budget measures against too: the
// nearest particle on the display whose disc covers the gaze point (what the eye sees there), or
// where none does (the gaze between particles, or off the water) the least eccentric particle on
// the display, the nearer of equals (the water nearest the gaze point). Gathered particle by
// particle and combined across threads: the same for any thread count.
struct FoveaWater {
  float under;          // distance of the nearest particle covering the gaze point, inf: none
  float least_e;        // the least eccentricity on the display, degrees
  float least_e_depth;  // that particle's distance
  FoveaWater();
  // An on-display particle seen `e_deg` from the gaze, its disc `disc_deg` in angular radius.
  void consider(float e_deg, float disc_deg, float depth);
  void combine(const FoveaWater& other);
  float depth() const;  // inf: no water on the display

 private:
  void takeIfLessEccentric(float e_deg, float depth);  // the nearer of equals
};

// The water at the gaze point as the particles stand (FoveaWater::depth).
float foveaWaterDepth(const ParticleSet& p, const ScreenCamera& camera, double gaze_x, double gaze_y,
                      const AdaptiveConfig& config);

// Per-particle scratch of the decision, kept between steps so the step does not allocate.
struct FoveatedScratch {
  std::vector<float> allowed;            // the width the eye allows, in finest particles at the gaze point
  std::vector<float> depth;              // view-space distance
  std::vector<std::int8_t> finest_near;  // the finest level among a particle and its neighbours
  std::vector<float> settled;            // settleSurfaceDistance's next sweep
  float fovea_depth = 0.0f;              // the last step's, 0 before the first
};

// Where no step has advanced the surface distance field (the method's first step, or its first
// after a method that does not track it), relaxes it to where the steps would settle it: d = 0 on
// the free surface (as decideFoveated finds it), else the least d_j + |r_ij| over the neighbours
// (Jacobi sweeps over the neighbour lists until none changes), and leaves each particle's
// surface_hop as the solver's last pass would. Without it the first decision reads every
// particle off the surface as deep (the field starts far) and keeps the water under a thin
// surface layer coarse where the eye sees it. Returns the sweeps taken.
int settleSurfaceDistance(Simulation& sim, const AdaptiveConfig& config, FoveatedScratch& scratch);

// A further split pass decided for part of the water: `particles` (ascending) and the distance of
// the water at the gaze point as the last changes left it (foveaWaterDepth; inf: none on the
// display). Every other particle remains.
struct SplitPassScope {
  std::span<const std::uint32_t> particles;
  float fovea_depth = 0.0f;
};

// Decides for every particle (out[i]) and returns the counts. `gaze_x`, `gaze_y`: normalized screen
// coordinates (origin top left). `splits_only`: no merges (a further split pass in the same step),
// for the particles of `scope` alone where one is given.
DecisionCounts decideFoveated(Simulation& sim, const ScreenCamera& camera, double gaze_x, double gaze_y,
                              const AdaptiveConfig& config, bool splits_only, std::span<std::int8_t> out,
                              FoveatedScratch& scratch, FoveatedView& view, const SplitPassScope* scope = nullptr);

// The eye's allowance at eccentricity `e_deg`: MAR(e) / MAR(0).
double acuityRatio(const AdaptiveConfig& config, double e_deg);

}  // namespace sph
