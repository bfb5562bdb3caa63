// The adaptive methods (thesis 3.6, docs/design.md section 3) by name, their settings and the gaze they
// are fed. The library knows no clock and no socket: the caller (bench or server) hands the current
// gaze and its age to the controller before each step.
#pragma once

#include <string>
#include <vector>

#include "sph/params.h"

namespace sph {

enum class Method { Regular, Surface, Gaze, Hybrid };

const char* methodName(Method m);
// False when `name` is not one of regular, surface, gaze, hybrid.
bool methodByName(const std::string& name, Method& out);
std::vector<std::string> methodNames();
// Regular runs all SMALL; the adaptive methods start LARGE and split where they need detail.
SizeClass startClass(Method m);
// Gaze and hybrid refine where the eye looks, so they need a gaze source.
bool usesGaze(Method m);

struct AdaptiveConfig {
  // Character field (3.45), table 3.2.
  double alpha = 0.8;        // geometric weight
  double beta = 0.01;        // dynamic (pressure) weight
  double gamma = 0.1;        // isolation weight
  double threshold = 0.225;  // T in (3.46): SPLIT if cf < T, MERGE if cf >= 2T
  // Box walls count as "boundary" for d in (3.45) when true (He et al.; the thesis's figure 3.2).
  bool surface_includes_walls = true;
  // A particle is a surface particle for (3.44) where |n| >= surface_normal_scale * l. The thesis
  // uses l itself (scale 1). With mixed sizes the colour field at the SMALL/LARGE interface inside
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

  // Throws std::invalid_argument naming the field when a value is not finite or out of range.
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
