// The AVX2 form of the merge-partner search (partner_search.h): partner_search.inc on 8 lanes.
#include <cstdint>
#include <limits>
#include <span>

#include "sph/adaptive/partner_search.h"
#include "sph/simd/avx2_target.h"
#include "sph/simd/pair_lanes_avx2.h"

SPH_AVX2_BEGIN

namespace sph::avx2 {
using Lanes = Avx2Lanes;
#include "sph/adaptive/partner_search.inc"
}  // namespace sph::avx2

SPH_AVX2_END
