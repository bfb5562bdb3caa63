// The adaptive methods (thesis 3.6, docs/design.md section 3) by name, their settings and the gaze they
// are fed. The library knows no clock and no socket: the caller (bench or server) hands the current
// gaze and its age to the controller before each step.
#pragma once

#include <string>
#include <vector>

#include "sph/params.h"

namespace sph {

// The thesis's four methods, and `foveated` (adaptive/foveated.h): several levels, each particle
// sized by the eye's acuity where it is seen.
enum class Method { Regular, Surface, Gaze, Hybrid, Foveated };

const char* methodName(Method m);
// False when `name` is not one of regular, surface, gaze, hybrid, foveated.
bool methodByName(const std::string& name, Method& out);
std::vector<std::string> methodNames();
// Regular runs all at L0; an adaptive method starts at its rule's coarsest level (the thesis's at
// L1, splitting where they need detail; foveated at L(levels - 1)). `levels`: the run's level
// count (SimParams::levels).
Level startLevel(Method m, int levels);
// The coarsest level the method makes (AdaptiveRule::coarsest); L1 for regular, whose runs still
// carry the thesis's two levels.
Level coarsestLevel(Method m, int levels);
// Every method but regular splits and merges particles: it has a rule (makeAdaptiveRule).
bool adapts(Method m);
// Gaze, hybrid and foveated refine where the eye looks, so they need a gaze source.
bool usesGaze(Method m);
// Gaze and hybrid refine a circle of fixed size around the gaze point (thesis 3.6.2): a server
// steps as soon as a fresh sample arrives, so the circle follows the eye with the least delay.
bool refinesGazeCircle(Method m);
// Foveated sizes each particle by the eye's acuity where it is seen: it has a quality q and a
// periphery gain (the real-time governor's knob), rings to draw, and measures what the eye gets
// (perceptual_budget.h).
bool sizesByAcuity(Method m);

// Each field is a row of the settings table (sph/param_table.h), which holds its key, range and
// unit: a new field needs its row there.
struct AdaptiveConfig {
  // Character field (3.45), table 3.2.
  double alpha = 0.8;        // geometric weight
  double beta = 0.01;        // dynamic (pressure) weight
  double gamma = 0.1;        // isolation weight
  double threshold = 0.225;  // T in (3.46): SPLIT if cf < T, MERGE if cf >= 2T
  // Box walls count as "boundary" for d in (3.45) when true (He et al.; the thesis's figure 3.2).
  bool surface_includes_walls = true;
  // A particle is a surface particle for (3.44) where |n| >= surface_normal_scale * l. The thesis
  // uses l itself (scale 1). With mixed sizes the colour field at the L0/L1 interface inside
  // the fluid exceeds l, and at scale 1 (or 1.5) the split band creeps inwards step by
  // step; 2 stops that on a resting pool (tests/adaptive) and still finds the free surface.
  double surface_normal_scale = 2.0;
  // Gaze circle radius as a fraction of the viewport width (docs/design.md section 3: 2.5 degrees at
  // 600 mm from a 531 mm wide screen, or the thesis's "5 % view"; both about 0.05).
  double gaze_radius = 0.05;
  // Outer radius of the hysteresis ring, same units, >= gaze_radius: between the two, particles
  // REMAIN, so a jittering gaze does not split and merge the same particles every step.
  double gaze_ring_radius = 0.08;
  // Lost-gaze policy: a sample older than gaze_stale_s is held (the last point stays in use) until
  // it is older than gaze_hold_s; after that the method falls back to surface-based refinement.
  double gaze_stale_s = 0.1;
  double gaze_hold_s = 1.0;

  // The foveated method (adaptive/foveated.h). A particle may look q MAR(e) / MAR(0) times as
  // wide as a finest particle at the gaze point, MAR(e) = w0 + m e the eye's minimum angle of
  // resolution at eccentricity e (Guenter et al. 2012: w0 about 1/48 degree, m 0.022-0.028).
  double foveated_quality = 1.0;  // q >= 1: coarser everywhere as it grows
  // g >= 1 multiplies the eccentricity term: q (1 + g m e / w0), except for the particle the gaze
  // falls on. The real-time governor's knob (server/app/realtime_governor.h): it coarsens the
  // periphery and leaves the gaze point as at g = 1. The perceptual budget is always measured at
  // g = 1.
  double foveated_periphery_gain = 1.0;
  double foveated_mar_w0_deg = 1.0 / 48.0;  // w0, degrees
  double foveated_mar_slope = 0.022;        // m, degrees of MAR per degree of eccentricity
  // How wide the display looks to the user, degrees: a desktop monitor at arm's length spans
  // 30-50 while the camera renders 72; in a headset the two agree (0: the camera's own).
  double foveated_display_fov_deg = 40.0;
  // Water deeper than this many finest lattice spacings under the free surface is hidden by the
  // water above it and may take, at any eccentricity, the coarsest level whose support its depth
  // covers.
  double foveated_hidden_depth = 4.0;
  // Coarsening waits until the eye would allow a particle this many times the next level's
  // width (hysteresis: a particle on a level's edge does not flicker between two levels).
  double foveated_coarsen_margin = 1.25;
  // A particle whose density is below this share of the rest density fills less of its support
  // than at a flat free surface (about half): it lies in a sheet, a jet, a drop or the surge
  // front's tip, and stays at most at `foveated_thin_level`, so thin water keeps particles across
  // it.
  double foveated_thin_fill = 0.4;
  int foveated_thin_level = 1;  // a level; the foveated rule clamps it to the run's coarsest
  // A particle whose neighbours spread across their thinnest direction less than this share of
  // their mean spread (1 in water of any depth, 0 in one layer: a sheet spread on the floor)
  // stays at most at the thin level: a layer under a coarse particle's width reads a low density
  // and loses its volume.
  double foveated_shallow_spread = 0.5;
  // A particle may be at most this many levels coarser than its finest neighbour (grading: each
  // level holds the next coarser ones within its reach, so the fine water around the eye spreads
  // in one shell per level). Every pair takes the kernel of its mean support whatever its levels
  // (pair_kernel.inc), so a wider step is a trade of the mixed pairs' accuracy for fewer shells.
  int foveated_grading_step = 2;
  // A merge waits until the eye has allowed the coarser level this many seconds without a break:
  // a gaze that comes back within it finds the water as it left it, so still water under a
  // moving gaze changes levels, and is stirred by the changes, far less; moving water keeps the
  // finer trail behind the gaze that long (docs/fluids.md, "Foveated water"). 0: at once.
  double foveated_merge_hold_s = 0.0;

  // Throws std::invalid_argument naming the setting when a value is outside its range in the
  // settings table (sph/param_table.h) or the settings disagree with each other.
  void validate() const;
};

// The caller's view of the gaze: whether any valid sample has arrived, the newest one (normalized
// screen coordinates, origin top left) and its age in seconds.
struct GazeInput {
  bool present = false;
  double x = 0.5;
  double y = 0.5;
  double age_s = 0.0;
};

// Which gaze the last adaptive step used.
enum class GazeMode { None, Tracking, Holding, Fallback };
const char* gazeModeName(GazeMode m);

}  // namespace sph
