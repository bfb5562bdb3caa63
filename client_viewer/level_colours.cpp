#include "level_colours.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace viewer {

namespace {

// matplotlib's viridis (van der Walt and Smith, 2015; CC0) at 0.25, 0.5, 0.75 and 1.0, its entries
// 64, 128, 192 and 255 of 256. Its darkest quarter is left out: on the viewer's dark background
// the finest level must stay visible. Linear interpolation between these keeps the lightness
// increasing from level to level, which is what the map is for.
constexpr std::array<LevelRgb, 4> kViridis{{
    {0.229739f, 0.322361f, 0.545706f},
    {0.127568f, 0.566949f, 0.550556f},
    {0.369214f, 0.788888f, 0.382914f},
    {0.993248f, 0.906157f, 0.143936f},
}};

}  // namespace

LevelRgb levelColour(std::size_t level, std::size_t level_count) {
  const std::size_t count = std::max<std::size_t>(level_count, 2);
  const float t = static_cast<float>(std::min(level, count - 1)) / static_cast<float>(count - 1);
  const float at = t * static_cast<float>(kViridis.size() - 1);
  const auto lower = std::min(static_cast<std::size_t>(std::floor(at)), kViridis.size() - 2);
  const float f = at - static_cast<float>(lower);
  const LevelRgb& a = kViridis[lower];
  const LevelRgb& b = kViridis[lower + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

}  // namespace viewer
