// What the eye gets from the foveated method, measured apart from the rule that sets the levels
// (foveated.h): which particles the user sees, how wide each looks, and whether that is within
// what the eye resolves at its eccentricity. docs/fluids.md, "What the eye gets", says what the
// figures promise and what they do not.
//
//   visible    nearest to the eye in at least one cell of a depth grid over the display
//              (kDepthGridWidth cells across), or under the gaze (below), its centre on the display
//              and in front of the eye; not the rule's own hidden-depth field.
//   width      the particle's diameter as the user sees it (the display foveated_display_fov_deg
//              wide, or the camera's own field of view when that is 0), in arcmin, from the
//              directions of the disc's two edges.
//   budget     a visible particle is over budget when it looks wider than q MAR(e) / MAR(0) times
//              the angular width of a finest-level particle at the depth of the water under the
//              gaze (Guenter et al. 2012: MAR(e) = w0 + m e), at periphery gain 1 whatever gain
//              the governor has in force: the grain may grow with eccentricity as fast as the
//              eye's acuity falls, and no faster, from what the gaze point gets.
//   gaze       of the particles whose disc covers the gaze point, the nearest the eye (what the
//              eye sees there, visible even where no cell samples it): its width and the eye's MAR
//              there, both in arcmin (0 where the gaze falls on no water). Their ratio says how
//              much coarser than the eye's resolution the finest water is.
#pragma once

#include <cstdint>
#include <vector>

#include "sph/adaptive/method.h"
#include "sph/camera.h"
#include "sph/params.h"
#include "sph/particles.h"

namespace sph {

struct PerceptualBudget {
  int visible = 0;
  int over_budget = 0;
  double gaze_width_arcmin = 0.0;  // 0: the gaze falls on no water
  double gaze_mar_arcmin = 0.0;
  int gaze_level = -1;  // the level of the particle under the gaze; -1: none
};

// The depth grid's cells across the display; its rows follow the viewport's aspect.
inline constexpr int kDepthGridWidth = 256;

class PerceptualBudgetMeter {
 public:
  // `gaze_x`, `gaze_y`: normalized screen coordinates (origin top left). Serial and in index
  // order: the result does not depend on the thread count.
  PerceptualBudget measure(const ParticleSet& p, const SimParams& params, const ScreenCamera& camera, double gaze_x,
                           double gaze_y, const AdaptiveConfig& config);

 private:
  // Per cell: the nearest particle's distance and index (scratch, kept between calls).
  std::vector<float> cell_depth_;
  std::vector<std::uint32_t> cell_owner_;
  std::vector<std::uint8_t> seen_;
};

}  // namespace sph
