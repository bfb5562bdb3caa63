// Small AVX-512 helpers shared by the library's vector loops (the pair stages, the neighbour scan,
// the merge-partner search): which of 16 lanes are live, and gathers from per-particle arrays.
// For the AVX-512 forms only (the *_avx512.cpp files); built for AVX-512 like them.
#pragma once

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

// Positions and velocities are packed x, y, z triples: the gather index of particle j is 3 j.
inline __m512i tripleIndex(__m512i idx) { return _mm512_add_epi32(idx, _mm512_add_epi32(idx, idx)); }

}  // namespace sph::lanes

SPH_AVX512_END
