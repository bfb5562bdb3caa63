// The scalar form of the dfsph passes: dfsph_passes.inc on one lane.
#include "sph/solvers/dfsph/dfsph_passes.h"

#include <span>

#include "sph/simd/pair_lanes_scalar.h"

namespace sph::scalar {
using Lanes = ScalarLanes;
#include "sph/solvers/dfsph/dfsph_passes.inc"
}  // namespace sph::scalar
