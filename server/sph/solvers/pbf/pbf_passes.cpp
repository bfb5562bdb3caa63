// The scalar form of the pbf passes: pbf_passes.inc on one lane.
#include "sph/solvers/pbf/pbf_passes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "sph/collision.h"
#include "sph/simd/pair_lanes_scalar.h"
#include "sph/simd/simd_level.h"

namespace sph::scalar {
using Lanes = ScalarLanes;
#include "sph/solvers/pbf/pbf_passes.inc"
}  // namespace sph::scalar

sph::PbfPassForms sph::pbfPassForms() {
  return formsForThisCpu(scalar::pbfPassForms, avx2::pbfPassForms, avx512::pbfPassForms);
}
