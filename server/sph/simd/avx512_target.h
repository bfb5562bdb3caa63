// The AVX-512 forms of the library's vector loops are compiled, inside a baseline x86-64 build,
// between SPH_AVX512_BEGIN and SPH_AVX512_END: every function defined there may use AVX-512 (and
// FMA, BMI2, POPCNT, LZCNT, which every AVX-512 CPU has) and is only ever called after
// simdLevel() said the CPU has it (simd_level.h).
//
// Only code defined between the two macros is built for AVX-512: put every #include above
// SPH_AVX512_BEGIN, so that inline functions and templates from headers (Eigen, the standard
// library, our own) stay baseline code. Were a header's inline function compiled for AVX-512 in
// one file, the linker could keep that copy for the whole program, and CPUs without AVX-512
// would stop on it.
//
// The region also silences GCC 12's -Wmaybe-uninitialized / -Wuninitialized for the AVX-512
// intrinsics, which build _mm512_max_ps and the reductions on *_undefined_ps() and are reported
// once inlined (GCC bug 105593); both are pushed and popped with the region.
#pragma once

#include <immintrin.h>

// clang-format off
#define SPH_AVX512_BEGIN                                                                           \
  _Pragma("GCC push_options")                                                                      \
  _Pragma("GCC target(\"avx512f,avx512bw,avx512dq,avx512vl,avx512cd,fma,bmi,bmi2,popcnt,lzcnt\")") \
  _Pragma("GCC diagnostic push")                                                                   \
  _Pragma("GCC diagnostic ignored \"-Wmaybe-uninitialized\"")                                     \
  _Pragma("GCC diagnostic ignored \"-Wuninitialized\"")

#define SPH_AVX512_END    \
  _Pragma("GCC diagnostic pop") \
  _Pragma("GCC pop_options")
// clang-format on
