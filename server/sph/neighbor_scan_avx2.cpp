// The AVX2 form of the neighbour scan (neighbor_scan.h): neighbor_scan.inc on 8 lanes.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "sph/neighbor_scan.h"
#include "sph/simd/avx2_target.h"
#include "sph/simd/pair_lanes_avx2.h"

SPH_AVX2_BEGIN

namespace sph::avx2 {
using Lanes = Avx2Lanes;
#include "sph/neighbor_scan.inc"
}  // namespace sph::avx2

SPH_AVX2_END
