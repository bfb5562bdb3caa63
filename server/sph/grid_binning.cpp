// The scalar form of the binning passes: grid_binning.inc built for baseline x86-64.
#include "sph/grid_binning.h"

#include <algorithm>
#include <cmath>

#include "sph/simd/simd_level.h"

namespace sph::scalar {
#include "sph/grid_binning.inc"
}  // namespace sph::scalar

sph::GridBinningForms sph::gridBinningForms() {
  return formsForThisCpu(scalar::gridBinningForms, avx2::gridBinningForms, avx512::gridBinningForms);
}
