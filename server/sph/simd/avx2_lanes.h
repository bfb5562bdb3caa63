// Small AVX2 helpers shared by the library's AVX2 vector loops (the pair stages, the neighbour
// scan, the merge-partner search): which of 8 lanes are live, gathers from per-particle arrays, and
// the lane masks AVX2 keeps in vector registers (all bits of a lane set) where AVX-512 has mask
// registers. For the AVX2 forms only (the *_avx2.cpp files); built for AVX2 like them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "sph/simd/avx2_target.h"

SPH_AVX2_BEGIN

namespace sph::lanes2 {

// Lane l's own bit, for turning a bit mask into a vector mask.
inline __m256i laneBits() { return _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128); }

// The first `left` lanes (all 8 when left >= 8): the live lanes of a batch near a range's end.
inline __m256 liveLanes(std::uint32_t left) {
  const int live = left >= 8 ? 8 : static_cast<int>(left);
  return _mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_set1_epi32(live), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7)));
}

// The lanes whose bits are set in `bits` (bit l: lane l), as a vector mask.
inline __m256 maskOfBits(std::uint32_t bits) {
  const __m256i b = laneBits();
  return _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(static_cast<int>(bits)), b), b));
}

// The lanes of a vector mask as bits (bit l: lane l).
inline std::uint32_t bitsOf(__m256 m) { return static_cast<std::uint32_t>(_mm256_movemask_ps(m)); }

// base[idx[l]] on live lanes, 0 on the others.
inline __m256 gather(__m256 live, __m256i idx, const float* base) {
  return _mm256_mask_i32gather_ps(_mm256_setzero_ps(), base, idx, live, 4);
}

// The same for 32-bit integers.
inline __m256i gatherInt(__m256 live, __m256i idx, const std::int32_t* base) {
  return _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), reinterpret_cast<const int*>(base), idx,
                                     _mm256_castps_si256(live), 4);
}

// Lanes a < b, as unsigned 32-bit integers (ids, indices): AVX2 compares signed only, so both
// sides are offset by 2^31 first.
inline __m256 lessUnsigned(__m256i a, __m256i b) {
  const __m256i sign = _mm256_set1_epi32(INT32_MIN);
  return _mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_xor_si256(b, sign), _mm256_xor_si256(a, sign)));
}

// The least of the 8 lanes, as unsigned 32-bit integers.
inline std::uint32_t minOfUnsigned(__m256i v) {
  __m128i s = _mm_min_epu32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
  s = _mm_min_epu32(s, _mm_shuffle_epi32(s, _MM_SHUFFLE(1, 0, 3, 2)));
  s = _mm_min_epu32(s, _mm_shuffle_epi32(s, _MM_SHUFFLE(2, 3, 0, 1)));
  return static_cast<std::uint32_t>(_mm_cvtsi128_si32(s));
}

// Lane l of v.
inline std::int32_t laneOf(__m256i v, int l) {
  alignas(32) std::int32_t lanes[8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), v);
  return lanes[l];
}

// For each 8-lane mask, the lanes it sets in order, one byte each (the rest 0): the permutation
// that packs those lanes to the front. A table, not BMI2's pext, which is slow on AMD CPUs before
// Zen 3, the very ones the AVX2 form is for.
inline constexpr std::array<std::uint64_t, 256> kCompress = [] {
  std::array<std::uint64_t, 256> table{};
  for (std::uint32_t m = 0; m < 256; ++m) {
    std::uint64_t packed = 0;
    int at = 0;
    for (std::uint64_t l = 0; l < 8; ++l) {
      if ((m >> l) & 1u) packed |= l << (8 * at++);
    }
    table[m] = packed;
  }
  return table;
}();

// The lanes of v whose bits are set in `bits`, packed to the front in order (AVX2 has no
// compress); the lanes after them are v's lane 0.
inline __m256i compress(std::uint32_t bits, __m256i v) {
  const __m256i order = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(kCompress[bits])));
  return _mm256_permutevar8x32_epi32(v, order);
}

// v[l] (each below 256) as the bytes p[0 .. 8).
inline void storeBytes(std::uint8_t* p, __m256i v) {
  const __m128i words = _mm_packus_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
  _mm_storel_epi64(reinterpret_cast<__m128i*>(p), _mm_packus_epi16(words, words));
}

// Positions and velocities are packed x, y, z triples: the gather index of particle j is 3 j.
inline __m256i tripleIndex(__m256i idx) { return _mm256_add_epi32(idx, _mm256_add_epi32(idx, idx)); }

// The sum and the least of the 8 lanes.
inline float sum(__m256 v) {
  __m128 s = _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  s = _mm_add_ps(s, _mm_movehl_ps(s, s));
  s = _mm_add_ss(s, _mm_movehdup_ps(s));
  return _mm_cvtss_f32(s);
}
inline float minOf(__m256 v) {
  __m128 s = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  s = _mm_min_ps(s, _mm_movehl_ps(s, s));
  s = _mm_min_ss(s, _mm_movehdup_ps(s));
  return _mm_cvtss_f32(s);
}

// The triples base[3 j .. 3 j + 2] of the particles j = list[l] on the live lanes, as x, y and z
// lanes (0 on dead lanes): one three-float load per particle (two loads that stay inside the
// triple, so the array's last one is safe), then a 4 x 4 transpose within each 128-bit half, as
// avx512_lanes.h does in quarters. Lane l's triple goes to half l / 4 of register l % 4.
inline void gatherTriples(__m256 live, const std::uint32_t* list, const float* base, __m256& x, __m256& y, __m256& z) {
  const std::uint32_t bits = bitsOf(live);
  __m128 row[8];
  for (int l = 0; l < 8; ++l) {
    const std::uint32_t j = (bits >> l) & 1u ? list[l] : 0u;
    const float* t = base + 3 * static_cast<std::size_t>(j);
    row[l] = _mm_movelh_ps(_mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(t))), _mm_load_ss(t + 2));
  }
  __m256 r[4];
  for (int k = 0; k < 4; ++k) r[k] = _mm256_insertf128_ps(_mm256_castps128_ps256(row[k]), row[k + 4], 1);
  const __m256d xy01 = _mm256_castps_pd(_mm256_unpacklo_ps(r[0], r[1]));  // x0 x1 y0 y1 per half
  const __m256d z01 = _mm256_castps_pd(_mm256_unpackhi_ps(r[0], r[1]));   // z0 z1 0 0
  const __m256d xy23 = _mm256_castps_pd(_mm256_unpacklo_ps(r[2], r[3]));
  const __m256d z23 = _mm256_castps_pd(_mm256_unpackhi_ps(r[2], r[3]));
  x = _mm256_and_ps(live, _mm256_castpd_ps(_mm256_unpacklo_pd(xy01, xy23)));
  y = _mm256_and_ps(live, _mm256_castpd_ps(_mm256_unpackhi_pd(xy01, xy23)));
  z = _mm256_and_ps(live, _mm256_castpd_ps(_mm256_unpacklo_pd(z01, z23)));
}

}  // namespace sph::lanes2

SPH_AVX2_END
