// The AVX-512 form of the merge-partner search (partner_search.h): partner_search.inc on 16 lanes.
#include <cstdint>
#include <limits>
#include <span>

#include "sph/adaptive/partner_search.h"
#include "sph/simd/avx512_target.h"
#include "sph/simd/pair_lanes_avx512.h"

SPH_AVX512_BEGIN

namespace sph::avx512 {
using Lanes = Avx512Lanes;
#include "sph/adaptive/partner_search.inc"
}  // namespace sph::avx512

SPH_AVX512_END
