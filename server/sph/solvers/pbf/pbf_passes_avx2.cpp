// The AVX2 form of the pbf passes: pbf_passes.inc on 8 lanes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "sph/collision.h"
#include "sph/simd/avx2_target.h"
#include "sph/simd/pair_lanes_avx2.h"
#include "sph/solvers/pbf/pbf_passes.h"

SPH_AVX2_BEGIN

namespace sph::avx2 {
using Lanes = Avx2Lanes;
#include "sph/solvers/pbf/pbf_passes.inc"
}  // namespace sph::avx2

SPH_AVX2_END
