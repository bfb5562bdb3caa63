// The AVX-512 form of the two pair-sum stages of thesis_stages.h: thesis_stages.inc on 16 lanes.
#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/simd/avx512_target.h"
#include "sph/simd/pair_lanes_avx512.h"
#include "sph/solvers/thesis/coincident_pairs.h"
#include "sph/solvers/thesis/thesis_stage_ends.h"
#include "sph/solvers/thesis/thesis_stages.h"

SPH_AVX512_BEGIN

namespace sph::avx512 {
using Lanes = Avx512Lanes;
#include "sph/solvers/thesis/thesis_stages.inc"
}  // namespace sph::avx512

SPH_AVX512_END
