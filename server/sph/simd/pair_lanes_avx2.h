// 8 lanes of AVX2 + FMA for the passes written once against a lane type: the pair passes, the
// partner search, the neighbour scan (pair_lanes_scalar.h lists the interface).
// A lane mask is a vector with all bits of its live lanes set, as AVX2's compares, blends and
// masked loads take it. For the AVX2 forms only; built for AVX2 like them.
#pragma once

#include <cstdint>

#include "sph/simd/avx2_lanes.h"
#include "sph/simd/avx2_target.h"

SPH_AVX2_BEGIN

namespace sph {

struct Avx2Lanes {
  static constexpr int kWidth = 8;
  using F = __m256;
  using I = __m256i;
  using M = __m256;
  using T = __m256;  // the table's first 8 entries: as many as there are levels

  static F set(float x) { return _mm256_set1_ps(x); }
  static F zero() { return _mm256_setzero_ps(); }
  static M live(std::uint32_t left) { return lanes2::liveLanes(left); }
  static I loadIndex(const std::uint32_t* p, M m) {
    return _mm256_maskload_epi32(reinterpret_cast<const int*>(p), _mm256_castps_si256(m));
  }
  static F load(const float* p, M m) { return _mm256_maskload_ps(p, _mm256_castps_si256(m)); }
  static void store(float* p, M m, F v) { _mm256_maskstore_ps(p, _mm256_castps_si256(m), v); }
  static F gather(M m, I j, const float* base) { return lanes2::gather(m, j, base); }
  // Reads 8 bytes whatever the mask (NeighborGrid::neighborLevels keeps them readable).
  static I loadLevels(const std::uint8_t* p, M m) {
    const __m256i k = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)));
    return _mm256_and_si256(k, _mm256_castps_si256(m));
  }
  static T table(const float* p) { return _mm256_loadu_ps(p); }
  static F lookup(T t, I k) { return _mm256_permutevar8x32_ps(t, k); }
  static void gatherTriples(M m, const std::uint32_t* list, const float* base, F& x, F& y, F& z) {
    lanes2::gatherTriples(m, list, base, x, y, z);
  }
  static M le(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_LE_OQ); }
  static M lt(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_LT_OQ); }
  static M eq(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_EQ_OQ); }
  static M neq(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_NEQ_OQ); }
  static M andMask(M a, M b) { return _mm256_and_ps(a, b); }
  static bool any(M m) { return _mm256_movemask_ps(m) != 0; }
  static F select(M m, F a, F b) { return _mm256_blendv_ps(b, a, m); }
  static F maskz(M m, F a) { return _mm256_and_ps(m, a); }
  static F max(F a, F b) { return _mm256_max_ps(a, b); }
  static F min(F a, F b) { return _mm256_min_ps(a, b); }
  static F sqrt(F a) { return _mm256_sqrt_ps(a); }
  static float sum(F v) { return lanes2::sum(v); }
  static float minOf(F v) { return lanes2::minOf(v); }

  // Index lanes as 32-bit integers, for the partner search and the neighbour scan.
  static I setIndex(std::int32_t x) { return _mm256_set1_epi32(x); }
  static I gatherIndex(M m, I j, const std::int32_t* base) { return lanes2::gatherInt(m, j, base); }
  static I tripleIndex(I j) { return lanes2::tripleIndex(j); }
  static M eqIndex(I a, I b) { return _mm256_castsi256_ps(_mm256_cmpeq_epi32(a, b)); }
  static M ltIndex(I a, I b) { return lanes2::lessUnsigned(a, b); }
  static I selectIndex(M m, I a, I b) {
    return _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(b), _mm256_castsi256_ps(a), m));
  }
  static std::uint32_t minOfIndex(I v) { return lanes2::minOfUnsigned(v); }
  static std::int32_t laneOf(I v, int l) { return lanes2::laneOf(v, l); }
  static M orMask(M a, M b) { return _mm256_or_ps(a, b); }
  static std::uint32_t bits(M m) { return lanes2::bitsOf(m); }
  static M le(M m, F a, F b) { return _mm256_and_ps(m, le(a, b)); }
  static M neqIndex(M m, I a, I b) { return _mm256_andnot_ps(eqIndex(a, b), m); }
  static F fmadd(F a, F b, F c) { return _mm256_fmadd_ps(a, b, c); }
  static I compress(M m, I v) { return lanes2::compress(lanes2::bitsOf(m), v); }
  static void storeIndex(std::uint32_t* p, I v) { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v); }
  static I loadIndex(const std::uint32_t* p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)); }
  static I gatherIndex(I j, const std::int32_t* base) { return _mm256_i32gather_epi32(base, j, 4); }
  static void storeBytes(std::uint8_t* p, I v) { lanes2::storeBytes(p, v); }
  static constexpr bool kMaskedByteStore = false;

  // For the thesis stages. The "on m" forms leave the other lanes of their first addend as they
  // are: AVX2 has no masked arithmetic, so they zero the other lanes' product or addend instead,
  // which adds +0 there.
  static M none() { return _mm256_setzero_ps(); }
  static M gt(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_GT_OQ); }
  static M eq(M m, F a, F b) { return _mm256_and_ps(m, eq(a, b)); }
  static M neq(M m, F a, F b) { return _mm256_and_ps(m, neq(a, b)); }
  static M andNotMask(M a, M b) { return _mm256_andnot_ps(a, b); }
  static F rsqrt(F a) { return _mm256_rsqrt_ps(a); }  // 12 bits
  static F fmaddOn(M m, F a, F b, F c) { return _mm256_fmadd_ps(_mm256_and_ps(m, a), b, c); }
  static F addOn(M m, F a, F b) { return a + _mm256_and_ps(m, b); }
};

}  // namespace sph

SPH_AVX2_END
