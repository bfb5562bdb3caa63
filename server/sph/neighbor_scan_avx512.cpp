// The AVX-512 form of the neighbour scan (neighbor_scan.h): neighbor_scan.inc on 16 lanes.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "sph/neighbor_scan.h"
#include "sph/simd/avx512_target.h"
#include "sph/simd/pair_lanes_avx512.h"

SPH_AVX512_BEGIN

namespace sph::avx512 {
using Lanes = Avx512Lanes;
#include "sph/neighbor_scan.inc"
}  // namespace sph::avx512

SPH_AVX512_END
