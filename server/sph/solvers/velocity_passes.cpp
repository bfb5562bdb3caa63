// The scalar form of the velocity passes: velocity_passes.inc on one lane.
#include "sph/solvers/velocity_passes.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <span>

#include "sph/simd/pair_lanes_scalar.h"
#include "sph/simd/simd_level.h"

namespace sph::scalar {
using Lanes = ScalarLanes;
#include "sph/solvers/velocity_passes.inc"
}  // namespace sph::scalar

sph::VelocityPassForms sph::velocityPassForms() {
  return formsForThisCpu(scalar::velocityPassForms, avx2::velocityPassForms, avx512::velocityPassForms);
}
