#include "app/foveation_echo.h"

#include <algorithm>
#include <array>
#include <vector>

#include "sph/adaptive/display_geometry.h"
#include "sph/adaptive/fovea_rings.h"

namespace app {

net::FoveationEcho foveationEcho(const SimSession& session, double gain_ceiling) {
  net::FoveationEcho echo;
  const sph::AdaptiveController* controller = session.controller();
  if (!sph::sizesByAcuity(session.method()) || controller == nullptr) return echo;
  const sph::AdaptiveStats& stats = controller->lastStats();
  echo.periphery_gain_ceiling = static_cast<float>(gain_ceiling);
  echo.visible = static_cast<std::uint32_t>(std::max(stats.visible, 0));
  echo.over_budget = static_cast<std::uint32_t>(std::max(stats.over_budget, 0));
  echo.fovea_width_arcmin = static_cast<float>(stats.fovea_width_arcmin);
  echo.fovea_mar_arcmin = static_cast<float>(stats.fovea_mar_arcmin);
  // Each level's width in finest particles, as decideFoveated measures it.
  const sph::SimParams& params = session.sim().params();
  const auto levels = params.levelProps();
  std::vector<double> widths;
  for (int k = 0; k < params.levels && k < sph::kMaxLevels; ++k) {
    widths.push_back(levels[static_cast<std::size_t>(k)].radius / levels[0].radius);
  }
  // Around the gaze point the step used (AdaptiveStats::gaze_x).
  const sph::AdaptiveConfig& in_force = controller->config();
  echo.ring_radii = sph::foveaRingRadii(in_force, widths, sph::displayTanHalf(in_force, controller->camera()),
                                        stats.gaze_x, stats.gaze_y);
  return echo;
}

}  // namespace app
