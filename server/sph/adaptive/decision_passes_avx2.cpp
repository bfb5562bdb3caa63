// The AVX2 form of the adaptive decisions' passes: decision_passes.inc built for AVX2.
#include <cmath>
#include <limits>

#include "sph/adaptive/decision_passes.h"
#include "sph/simd/avx2_target.h"

SPH_AVX2_BEGIN

namespace sph::avx2 {
#include "sph/adaptive/decision_passes.inc"
}  // namespace sph::avx2

SPH_AVX2_END
