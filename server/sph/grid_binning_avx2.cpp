// The AVX2 form of the binning passes: grid_binning.inc built for AVX2.
#include <algorithm>
#include <cmath>

#include "sph/grid_binning.h"
#include "sph/simd/avx2_target.h"

SPH_AVX2_BEGIN

namespace sph::avx2 {
#include "sph/grid_binning.inc"
}  // namespace sph::avx2

SPH_AVX2_END
