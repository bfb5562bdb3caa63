// The AVX2 form of the two pair-sum stages of thesis_stages.h: thesis_stages.inc on 8 lanes.
#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/simd/avx2_target.h"
#include "sph/simd/pair_lanes_avx2.h"
#include "sph/solvers/thesis/coincident_pairs.h"
#include "sph/solvers/thesis/thesis_stage_ends.h"
#include "sph/solvers/thesis/thesis_stages.h"

SPH_AVX2_BEGIN

namespace sph::avx2 {
using Lanes = Avx2Lanes;
#include "sph/solvers/thesis/thesis_stages.inc"
}  // namespace sph::avx2

SPH_AVX2_END
