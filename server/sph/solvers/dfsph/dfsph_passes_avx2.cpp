// The AVX2 form of the dfsph passes: dfsph_passes.inc on 8 lanes.
#include <span>

#include "sph/simd/avx2_target.h"
#include "sph/simd/pair_lanes_avx2.h"
#include "sph/solvers/dfsph/dfsph_passes.h"

SPH_AVX2_BEGIN

namespace sph::avx2 {
using Lanes = Avx2Lanes;
#include "sph/solvers/dfsph/dfsph_passes.inc"
}  // namespace sph::avx2

SPH_AVX2_END
