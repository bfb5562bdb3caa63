// One colour per size level, any number of levels (2 to kMaxSizeLevels), from one perceptually
// ordered colour map: particles mode paints the particles, the panel's legend and the foveated
// method's rings with the same colours. Plain data, no GL, so it is unit tested.
#pragma once

#include <cstddef>

namespace viewer {

struct LevelRgb {
  float r, g, b;
};

// Level `level` of `level_count`: L0 (the finest) at the map's blue end, the coarsest at its yellow
// end, the levels between evenly spaced along the map. A level_count below 2 counts as 2.
LevelRgb levelColour(std::size_t level, std::size_t level_count);

}  // namespace viewer
