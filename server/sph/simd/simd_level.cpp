#include "sph/simd/simd_level.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace sph {

namespace {

bool cpuHasAvx512() {
#if defined(SPH_FORCE_SCALAR)
  return false;
#elif defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
         __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512cd");
#else
  return false;
#endif
}

bool cpuHasAvx2() {
#if defined(SPH_FORCE_SCALAR)
  return false;
#elif defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("popcnt");
#else
  return false;
#endif
}

}  // namespace

const char* simdLevelName(SimdLevel level) {
  switch (level) {
    case SimdLevel::kAvx512:
      return "avx512";
    case SimdLevel::kAvx2:
      return "avx2";
    case SimdLevel::kScalar:
      break;
  }
  return "scalar";
}

SimdLevel chooseSimdLevel(SimdLevel best, const char* env) {
  if (env == nullptr || *env == '\0' || std::strcmp(env, "auto") == 0) return best;
  for (const SimdLevel level : {SimdLevel::kScalar, SimdLevel::kAvx2, SimdLevel::kAvx512}) {
    if (std::strcmp(env, simdLevelName(level)) == 0) return std::min(level, best);
  }
  throw std::invalid_argument(std::string("SPH_SIMD must be auto, avx512, avx2 or scalar, not '") + env + "'");
}

bool simdAvailable(SimdLevel level) {
  static const bool avx512 = cpuHasAvx512() && cpuHasAvx2();
  static const bool avx2 = cpuHasAvx2();
  switch (level) {
    case SimdLevel::kAvx512:
      return avx512;
    case SimdLevel::kAvx2:
      return avx2;
    case SimdLevel::kScalar:
      break;
  }
  return true;
}

SimdLevel simdLevel() {
  static const SimdLevel level = [] {
    SimdLevel best = SimdLevel::kScalar;
    if (simdAvailable(SimdLevel::kAvx2)) best = SimdLevel::kAvx2;
    if (simdAvailable(SimdLevel::kAvx512)) best = SimdLevel::kAvx512;
    return chooseSimdLevel(best, std::getenv("SPH_SIMD"));
  }();
  return level;
}

}  // namespace sph
