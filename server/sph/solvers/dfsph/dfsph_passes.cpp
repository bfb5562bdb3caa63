// The scalar form of the dfsph passes: dfsph_passes.inc on one lane.
#include "sph/solvers/dfsph/dfsph_passes.h"

#include <span>

#include "sph/simd/pair_lanes_scalar.h"
#include "sph/simd/simd_level.h"

namespace sph::scalar {
using Lanes = ScalarLanes;
#include "sph/solvers/dfsph/dfsph_passes.inc"
}  // namespace sph::scalar

sph::DfsphPassForms sph::dfsphPassForms() {
  return formsForThisCpu(scalar::dfsphPassForms, avx2::dfsphPassForms, avx512::dfsphPassForms);
}
