// The scalar form of the adaptive decisions' passes: decision_passes.inc built for baseline x86-64.
#include "sph/adaptive/decision_passes.h"

#include <cmath>
#include <limits>

#include "sph/simd/simd_level.h"

namespace sph::scalar {
#include "sph/adaptive/decision_passes.inc"
}  // namespace sph::scalar

sph::DecisionPassForms sph::decisionPassForms() {
  return formsForThisCpu(scalar::decisionPassForms, avx2::decisionPassForms, avx512::decisionPassForms);
}
