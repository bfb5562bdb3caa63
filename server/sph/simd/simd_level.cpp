#include "sph/simd/simd_level.h"

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

}  // namespace

const char* simdLevelName(SimdLevel level) { return level == SimdLevel::kAvx512 ? "avx512" : "scalar"; }

SimdLevel chooseSimdLevel(bool avx512_available, const char* env) {
  if (env == nullptr || *env == '\0' || std::strcmp(env, "auto") == 0 || std::strcmp(env, "avx512") == 0) {
    return avx512_available ? SimdLevel::kAvx512 : SimdLevel::kScalar;
  }
  if (std::strcmp(env, "scalar") == 0) return SimdLevel::kScalar;
  throw std::invalid_argument(std::string("SPH_SIMD must be auto, avx512 or scalar, not '") + env + "'");
}

bool simdAvailable(SimdLevel level) {
  static const bool avx512 = cpuHasAvx512();
  return level == SimdLevel::kScalar || avx512;
}

SimdLevel simdLevel() {
  static const SimdLevel level = chooseSimdLevel(simdAvailable(SimdLevel::kAvx512), std::getenv("SPH_SIMD"));
  return level;
}

}  // namespace sph
