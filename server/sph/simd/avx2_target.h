// The AVX2 forms of the library's vector loops are compiled, inside a baseline x86-64 build,
// between SPH_AVX2_BEGIN and SPH_AVX2_END: every function defined there may use AVX2, FMA and
// POPCNT (simdAvailable checks each of them) and is only ever called after simdLevel() said the
// CPU has them (simd_level.h). No BMI2: its pext and pdep are slow on AMD CPUs before Zen 3.
//
// The same rules as avx512_target.h: put every #include above SPH_AVX2_BEGIN, so that inline
// functions and templates from headers stay baseline code and the linker never keeps an AVX2 copy
// of them for CPUs without AVX2. The diagnostics are silenced for the same GCC bug (105593),
// which reports the *_undefined_ps() inside the 256-bit intrinsics once inlined.
#pragma once

#include <immintrin.h>

// clang-format off
#define SPH_AVX2_BEGIN                                            \
  _Pragma("GCC push_options")                                     \
  _Pragma("GCC target(\"avx2,fma,popcnt\")")                      \
  _Pragma("GCC diagnostic push")                                  \
  _Pragma("GCC diagnostic ignored \"-Wmaybe-uninitialized\"")    \
  _Pragma("GCC diagnostic ignored \"-Wuninitialized\"")

#define SPH_AVX2_END            \
  _Pragma("GCC diagnostic pop") \
  _Pragma("GCC pop_options")
// clang-format on
