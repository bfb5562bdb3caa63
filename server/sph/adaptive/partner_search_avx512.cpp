// The AVX-512 form of the merge-partner search (partner_search.h).
#include <limits>

#include "sph/adaptive/partner_search.h"
#include "sph/simd/avx512_lanes.h"
#include "sph/simd/avx512_target.h"

SPH_AVX512_BEGIN

namespace sph {

namespace {

// nearestMergingNeighbour 16 neighbours at a time. Each lane keeps its own best (distance, id)
// and the lanes' bests are compared at the end: the least distance, then the lower id, the same
// choice as the scalar search makes in list order. Only the candidate lanes gather positions and
// ids, and most batches have none or few.
std::int32_t nearestMergingNeighbour(const float* pos, const std::uint32_t* ids, std::span<const std::uint32_t> list,
                                     const std::int32_t* merging, std::size_t i) {
  const __m512 xi = _mm512_set1_ps(pos[3 * i]);
  const __m512 yi = _mm512_set1_ps(pos[3 * i + 1]);
  const __m512 zi = _mm512_set1_ps(pos[3 * i + 2]);
  const __m512 inf = _mm512_set1_ps(std::numeric_limits<float>::infinity());
  const __m512i own = _mm512_set1_epi32(merging[i]);
  __m512 best_d2 = inf;
  __m512i best_id = _mm512_set1_epi32(-1);  // as unsigned: above every id
  __m512i best_j = _mm512_set1_epi32(-1);
  const auto size = static_cast<std::uint32_t>(list.size());
  for (std::uint32_t b = 0; b < size; b += 16) {
    const std::uint32_t left = size - b;
    const __mmask16 live = lanes::liveLanes(left);
    const __m512i j = _mm512_maskz_loadu_epi32(live, list.data() + b);
    const __m512i flag = _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), live, j, merging, 4);
    const __mmask16 candidate = _mm512_mask_cmpeq_epi32_mask(live, flag, own);
    if (candidate == 0) continue;
    const __m512i j3 = lanes::tripleIndex(j);
    const __m512 dx = _mm512_sub_ps(xi, lanes::gather(candidate, j3, pos));
    const __m512 dy = _mm512_sub_ps(yi, lanes::gather(candidate, j3, pos + 1));
    const __m512 dz = _mm512_sub_ps(zi, lanes::gather(candidate, j3, pos + 2));
    // No FMA, and this file is built with -ffp-contract=off: the scalar form's roundings exactly.
    const __m512 d2 = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)), _mm512_mul_ps(dz, dz));
    const __m512i id = _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), candidate, j, ids, 4);
    const __mmask16 nearer = _mm512_mask_cmp_ps_mask(candidate, d2, best_d2, _CMP_LT_OQ);
    const __mmask16 tie =
        _mm512_mask_cmp_ps_mask(candidate, d2, best_d2, _CMP_EQ_OQ) & _mm512_cmplt_epu32_mask(id, best_id);
    const __mmask16 better = nearer | tie;
    best_d2 = _mm512_mask_mov_ps(best_d2, better, d2);
    best_id = _mm512_mask_mov_epi32(best_id, better, id);
    best_j = _mm512_mask_mov_epi32(best_j, better, j);
  }
  const float least = _mm512_reduce_min_ps(best_d2);
  if (!(least < std::numeric_limits<float>::infinity())) return -1;
  const __mmask16 at_least = _mm512_cmp_ps_mask(best_d2, _mm512_set1_ps(least), _CMP_EQ_OQ);
  const __m512i ids_at_least = _mm512_mask_mov_epi32(_mm512_set1_epi32(-1), at_least, best_id);
  const auto lowest_id = static_cast<std::uint32_t>(_mm512_reduce_min_epu32(ids_at_least));
  const __mmask16 winner =
      _mm512_mask_cmpeq_epi32_mask(at_least, ids_at_least, _mm512_set1_epi32(static_cast<int>(lowest_id)));
  alignas(64) std::int32_t lanes[16];
  _mm512_store_si512(lanes, best_j);
  return lanes[__builtin_ctz(winner)];
}

}  // namespace

void avx512::choosePartners(const ParticleSet& p, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                            std::span<std::int32_t> partner, Level coarsest, PartnerScratch& scratch) {
  detail::choosePartnersWith(nearestMergingNeighbour, p, grid, decision, partner, coarsest, scratch);
}

PartnerSearchForms avx512::partnerSearchForms() { return {avx512::choosePartners}; }

}  // namespace sph

SPH_AVX512_END
