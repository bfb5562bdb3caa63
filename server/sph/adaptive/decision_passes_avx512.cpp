// The AVX-512 form of the adaptive decisions' passes: decision_passes.inc built for AVX-512.
#include <cmath>
#include <limits>

#include "sph/adaptive/decision_passes.h"
#include "sph/simd/avx512_target.h"

SPH_AVX512_BEGIN

namespace sph::avx512 {
#include "sph/adaptive/decision_passes.inc"
}  // namespace sph::avx512

SPH_AVX512_END
