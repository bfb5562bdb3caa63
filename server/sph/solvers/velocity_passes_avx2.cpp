// The AVX2 form of the velocity passes: velocity_passes.inc on 8 lanes.
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <span>

#include "sph/simd/avx2_target.h"
#include "sph/simd/pair_lanes_avx2.h"
#include "sph/solvers/velocity_passes.h"

SPH_AVX2_BEGIN

namespace sph::avx2 {
using Lanes = Avx2Lanes;
#include "sph/solvers/velocity_passes.inc"
}  // namespace sph::avx2

SPH_AVX2_END
