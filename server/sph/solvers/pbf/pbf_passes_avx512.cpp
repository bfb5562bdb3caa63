// The AVX-512 form of the pbf passes: pbf_passes.inc on 16 lanes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "sph/collision.h"
#include "sph/simd/avx512_target.h"
#include "sph/simd/pair_lanes_avx512.h"
#include "sph/solvers/pbf/pbf_passes.h"

SPH_AVX512_BEGIN

namespace sph::avx512 {
using Lanes = Avx512Lanes;
#include "sph/solvers/pbf/pbf_passes.inc"
}  // namespace sph::avx512

SPH_AVX512_END
