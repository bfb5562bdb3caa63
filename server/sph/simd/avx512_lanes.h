// Small AVX-512 helpers shared by the library's vector loops (the pair stages, the neighbour scan,
// the merge-partner search): which of 16 lanes are live, and gathers from per-particle arrays.
// For the AVX-512 forms only (the *_avx512.cpp files); built for AVX-512 like them.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sph/simd/avx512_target.h"

SPH_AVX512_BEGIN

namespace sph::lanes {

// The first `left` lanes (all 16 when left >= 16): the live lanes of a batch near a range's end.
inline __mmask16 liveLanes(std::uint32_t left) { return left >= 16 ? __mmask16(0xFFFF) : __mmask16((1u << left) - 1u); }

// base[idx[l]] on live lanes, 0 on the others.
inline __m512 gather(__mmask16 live, __m512i idx, const float* base) {
  return _mm512_mask_i32gather_ps(_mm512_setzero_ps(), live, idx, base, 4);
}

// The same for 32-bit integers.
inline __m512i gatherInt(__mmask16 live, __m512i idx, const std::int32_t* base) {
  return _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), live, idx, base, 4);
}

// Lane l of v.
inline std::int32_t laneOf(__m512i v, int l) {
  alignas(64) std::int32_t lanes[16];
  _mm512_store_si512(lanes, v);
  return lanes[l];
}

// Positions and velocities are packed x, y, z triples: the gather index of particle j is 3 j.
inline __m512i tripleIndex(__m512i idx) { return _mm512_add_epi32(idx, _mm512_add_epi32(idx, idx)); }

// The triples base[3 j .. 3 j + 2] of the particles j = list[l] on the live lanes, as x, y and z
// lanes (0 on dead lanes): one three-float load per particle, then a 4 x 4 transpose within each
// 128-bit quarter, faster than three gathers of the same triples (docs/performance.md). Lane l's
// triple goes to quarter l / 4 of register l % 4, so that after the transpose lane l holds it.
inline void gatherTriples(__mmask16 live, const std::uint32_t* list, const float* base, __m512& x, __m512& y,
                          __m512& z) {
  __m128 row[16];
  for (int l = 0; l < 16; ++l) {
    const std::uint32_t j = (live >> l) & 1u ? list[l] : 0u;
    row[l] = _mm_maskz_loadu_ps(0x7, base + 3 * static_cast<std::size_t>(j));
  }
  // r[k] holds the triples of lanes k, k + 4, k + 8, k + 12 in its four quarters.
  __m512 r[4];
  for (int k = 0; k < 4; ++k) {
    __m512 v = _mm512_castps128_ps512(row[k]);
    v = _mm512_insertf32x4(v, row[k + 4], 1);
    v = _mm512_insertf32x4(v, row[k + 8], 2);
    r[k] = _mm512_insertf32x4(v, row[k + 12], 3);
  }
  const __m512d xy01 = _mm512_castps_pd(_mm512_unpacklo_ps(r[0], r[1]));  // x0 x1 y0 y1 per quarter
  const __m512d z01 = _mm512_castps_pd(_mm512_unpackhi_ps(r[0], r[1]));   // z0 z1 0 0
  const __m512d xy23 = _mm512_castps_pd(_mm512_unpacklo_ps(r[2], r[3]));
  const __m512d z23 = _mm512_castps_pd(_mm512_unpackhi_ps(r[2], r[3]));
  x = _mm512_maskz_mov_ps(live, _mm512_castpd_ps(_mm512_unpacklo_pd(xy01, xy23)));
  y = _mm512_maskz_mov_ps(live, _mm512_castpd_ps(_mm512_unpackhi_pd(xy01, xy23)));
  z = _mm512_maskz_mov_ps(live, _mm512_castpd_ps(_mm512_unpacklo_pd(z01, z23)));
}

}  // namespace sph::lanes

SPH_AVX512_END
