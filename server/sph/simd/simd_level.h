// Which instruction set the library's vector loops run, chosen once at run time from the CPU.
//
// The pattern, the same for every loop that has a vector form: the scalar form lives in
// namespace sph::scalar in `foo.cpp`, the AVX-512 form in namespace sph::avx512 in
// `foo_avx512.cpp` (its code between SPH_AVX512_BEGIN and SPH_AVX512_END, avx512_target.h), both
// declared in `foo.h`, and the public sph::foo() calls the one simdLevel() names. The whole
// library is built for baseline x86-64, so one build runs on any x86-64 CPU and takes the
// AVX-512 forms where the CPU has them.
#pragma once

#include <string>

namespace sph {

enum class SimdLevel { kScalar, kAvx512 };

const char* simdLevelName(SimdLevel level);

// The level of this process: AVX-512 where the CPU has AVX-512 F, BW, DQ, VL and CD and the build
// has the AVX-512 forms (not with -DSPH_FORCE_SCALAR=ON), unless the environment says
// SPH_SIMD=scalar. Decided on the first call; the same for the rest of the process.
SimdLevel simdLevel();

// Whether this build on this CPU can run `level` (the tests run both forms side by side).
bool simdAvailable(SimdLevel level);

// simdLevel()'s rule on its inputs: `env` is SPH_SIMD's value or nullptr. Throws
// std::invalid_argument for a value other than "scalar", "avx512" or "auto"; "avx512" where it
// is not available falls back to scalar (a portable default, never a crash).
SimdLevel chooseSimdLevel(bool avx512_available, const char* env);

// Calls the form of `fn` that simdLevel() names: dispatch(scalar::fn, avx512::fn, args...).
template <typename ScalarFn, typename Avx512Fn, typename... Args>
decltype(auto) dispatch(ScalarFn scalar_form, Avx512Fn avx512_form, Args&&... args) {
  if (simdLevel() == SimdLevel::kAvx512) return avx512_form(static_cast<Args&&>(args)...);
  return scalar_form(static_cast<Args&&>(args)...);
}

}  // namespace sph
