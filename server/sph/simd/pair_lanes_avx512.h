// 16 lanes of AVX-512 for the passes written once against a lane type: the pair passes, the
// partner search, the neighbour scan (pair_lanes_scalar.h lists the interface).
// For the AVX-512 forms only; built for AVX-512 like them.
#pragma once

#include <cstdint>

#include "sph/simd/avx512_lanes.h"
#include "sph/simd/avx512_target.h"

SPH_AVX512_BEGIN

namespace sph {

struct Avx512Lanes {
  static constexpr int kWidth = 16;
  using F = __m512;
  using I = __m512i;
  using M = __mmask16;
  using T = __m512;

  static F set(float x) { return _mm512_set1_ps(x); }
  static F zero() { return _mm512_setzero_ps(); }
  static M live(std::uint32_t left) { return lanes::liveLanes(left); }
  static I loadIndex(const std::uint32_t* p, M m) { return _mm512_maskz_loadu_epi32(m, p); }
  static F load(const float* p, M m) { return _mm512_maskz_loadu_ps(m, p); }
  static void store(float* p, M m, F v) { _mm512_mask_storeu_ps(p, m, v); }
  static F gather(M m, I j, const float* base) { return lanes::gather(m, j, base); }
  static I loadLevels(const std::uint8_t* p, M m) { return _mm512_maskz_cvtepu8_epi32(m, _mm_maskz_loadu_epi8(m, p)); }
  static T table(const float* p) { return _mm512_loadu_ps(p); }
  static F lookup(T t, I k) { return _mm512_permutexvar_ps(k, t); }
  static void gatherTriples(M m, const std::uint32_t* list, const float* base, F& x, F& y, F& z) {
    lanes::gatherTriples(m, list, base, x, y, z);
  }
  static M le(F a, F b) { return _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ); }
  static M lt(F a, F b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
  static M eq(F a, F b) { return _mm512_cmp_ps_mask(a, b, _CMP_EQ_OQ); }
  static M neq(F a, F b) { return _mm512_cmp_ps_mask(a, b, _CMP_NEQ_OQ); }
  static M andMask(M a, M b) { return static_cast<M>(a & b); }
  static bool any(M m) { return m != 0; }
  static F select(M m, F a, F b) { return _mm512_mask_blend_ps(m, b, a); }
  static F maskz(M m, F a) { return _mm512_maskz_mov_ps(m, a); }
  static F max(F a, F b) { return _mm512_max_ps(a, b); }
  static F min(F a, F b) { return _mm512_min_ps(a, b); }
  static F sqrt(F a) { return _mm512_sqrt_ps(a); }
  static float sum(F v) { return _mm512_reduce_add_ps(v); }
  static float minOf(F v) { return _mm512_reduce_min_ps(v); }

  // Index lanes as 32-bit integers, for the partner search and the neighbour scan.
  static I setIndex(std::int32_t x) { return _mm512_set1_epi32(x); }
  static I gatherIndex(M m, I j, const std::int32_t* base) { return lanes::gatherInt(m, j, base); }
  static I tripleIndex(I j) { return lanes::tripleIndex(j); }
  static M eqIndex(I a, I b) { return _mm512_cmpeq_epi32_mask(a, b); }
  static M ltIndex(I a, I b) { return _mm512_cmplt_epu32_mask(a, b); }
  static I selectIndex(M m, I a, I b) { return _mm512_mask_blend_epi32(m, b, a); }
  static std::uint32_t minOfIndex(I v) { return _mm512_reduce_min_epu32(v); }
  static std::int32_t laneOf(I v, int l) { return lanes::laneOf(v, l); }
  static M orMask(M a, M b) { return static_cast<M>(a | b); }
  static std::uint32_t bits(M m) { return m; }
  static M le(M m, F a, F b) { return _mm512_mask_cmp_ps_mask(m, a, b, _CMP_LE_OQ); }
  static M neqIndex(M m, I a, I b) { return static_cast<M>(m & _mm512_cmpneq_epi32_mask(a, b)); }
  static F fmadd(F a, F b, F c) { return _mm512_fmadd_ps(a, b, c); }
  static I compress(M m, I v) { return _mm512_maskz_compress_epi32(m, v); }
  static void storeIndex(std::uint32_t* p, I v) { _mm512_storeu_si512(p, v); }
  static void storeBytes(std::uint8_t* p, M m, I v) { _mm_mask_storeu_epi8(p, m, _mm512_cvtepi32_epi8(v)); }
  static constexpr bool kMaskedByteStore = true;

  // For the thesis stages.
  static M none() { return 0; }
  static M gt(F a, F b) { return _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ); }
  static M eq(M m, F a, F b) { return _mm512_mask_cmp_ps_mask(m, a, b, _CMP_EQ_OQ); }
  static M neq(M m, F a, F b) { return _mm512_mask_cmp_ps_mask(m, a, b, _CMP_NEQ_OQ); }
  static M andNotMask(M a, M b) { return static_cast<M>(b & ~a); }
  static F rsqrt(F a) { return _mm512_rsqrt14_ps(a); }  // 14 bits
  static F fmaddOn(M m, F a, F b, F c) { return _mm512_mask3_fmadd_ps(a, b, c, m); }
  static F addOn(M m, F a, F b) { return _mm512_mask_add_ps(a, m, a, b); }
};

}  // namespace sph

SPH_AVX512_END
