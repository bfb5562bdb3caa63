// The AVX-512 form of the binning passes: grid_binning.inc built for AVX-512.
#include <algorithm>
#include <cmath>

#include "sph/grid_binning.h"
#include "sph/simd/avx512_target.h"

SPH_AVX512_BEGIN

namespace sph::avx512 {
#include "sph/grid_binning.inc"
}  // namespace sph::avx512

SPH_AVX512_END
