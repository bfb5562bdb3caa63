// The AVX-512 form of the dfsph passes: dfsph_passes.inc on 16 lanes.
#include <span>

#include "sph/simd/avx512_target.h"
#include "sph/simd/pair_lanes_avx512.h"
#include "sph/solvers/dfsph/dfsph_passes.h"

SPH_AVX512_BEGIN

namespace sph::avx512 {
using Lanes = Avx512Lanes;
#include "sph/solvers/dfsph/dfsph_passes.inc"
}  // namespace sph::avx512

SPH_AVX512_END
