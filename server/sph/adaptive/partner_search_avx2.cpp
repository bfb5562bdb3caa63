// The AVX2 form of the merge-partner search (partner_search.h).
#include <cstdint>
#include <limits>

#include "sph/adaptive/partner_search.h"
#include "sph/simd/avx2_lanes.h"
#include "sph/simd/avx2_target.h"

SPH_AVX2_BEGIN

namespace sph {

namespace {

// nearestMergingNeighbour 8 neighbours at a time, as the AVX-512 form does 16: each lane keeps its
// own best (distance, id), and the lanes' bests are compared at the end (the least distance, then
// the lower id), the scalar search's choice in list order.
std::int32_t nearestMergingNeighbour(const float* pos, const std::uint32_t* ids, std::span<const std::uint32_t> list,
                                     const std::int32_t* merging, std::size_t i) {
  const __m256 xi = _mm256_set1_ps(pos[3 * i]);
  const __m256 yi = _mm256_set1_ps(pos[3 * i + 1]);
  const __m256 zi = _mm256_set1_ps(pos[3 * i + 2]);
  const __m256i own = _mm256_set1_epi32(merging[i]);
  // Ids compare unsigned; AVX2 compares signed, so both sides are offset by 2^31.
  const __m256i sign = _mm256_set1_epi32(std::numeric_limits<std::int32_t>::min());
  __m256 best_d2 = _mm256_set1_ps(std::numeric_limits<float>::infinity());
  __m256i best_id = _mm256_set1_epi32(-1);  // as unsigned: above every id
  __m256i best_j = _mm256_set1_epi32(-1);
  const auto size = static_cast<std::uint32_t>(list.size());
  for (std::uint32_t b = 0; b < size; b += 8) {
    const __m256 live = lanes2::liveLanes(size - b);
    const __m256i j = _mm256_maskload_epi32(reinterpret_cast<const int*>(list.data() + b), _mm256_castps_si256(live));
    const __m256i flag = lanes2::gatherInt(live, j, merging);
    const __m256 candidate = _mm256_and_ps(live, _mm256_castsi256_ps(_mm256_cmpeq_epi32(flag, own)));
    if (_mm256_movemask_ps(candidate) == 0) continue;
    const __m256i j3 = lanes2::tripleIndex(j);
    const __m256 dx = _mm256_sub_ps(xi, lanes2::gather(candidate, j3, pos));
    const __m256 dy = _mm256_sub_ps(yi, lanes2::gather(candidate, j3, pos + 1));
    const __m256 dz = _mm256_sub_ps(zi, lanes2::gather(candidate, j3, pos + 2));
    // No FMA, and this file is built with -ffp-contract=off: the scalar form's roundings exactly.
    const __m256 d2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)), _mm256_mul_ps(dz, dz));
    const __m256i id = lanes2::gatherInt(candidate, j, reinterpret_cast<const std::int32_t*>(ids));
    const __m256 nearer = _mm256_cmp_ps(d2, best_d2, _CMP_LT_OQ);
    const __m256 id_lower =
        _mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_xor_si256(best_id, sign), _mm256_xor_si256(id, sign)));
    const __m256 tie = _mm256_and_ps(_mm256_cmp_ps(d2, best_d2, _CMP_EQ_OQ), id_lower);
    const __m256 better = _mm256_and_ps(candidate, _mm256_or_ps(nearer, tie));
    best_d2 = _mm256_blendv_ps(best_d2, d2, better);
    best_id = _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(best_id), _mm256_castsi256_ps(id), better));
    best_j = _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(best_j), _mm256_castsi256_ps(j), better));
  }
  alignas(32) float d2s[8];
  alignas(32) std::uint32_t id_of[8];
  alignas(32) std::int32_t j_of[8];
  _mm256_store_ps(d2s, best_d2);
  _mm256_store_si256(reinterpret_cast<__m256i*>(id_of), best_id);
  _mm256_store_si256(reinterpret_cast<__m256i*>(j_of), best_j);
  std::int32_t best = -1;
  float least = std::numeric_limits<float>::infinity();
  std::uint32_t lowest_id = 0;
  for (int l = 0; l < 8; ++l) {
    if (d2s[l] < least || (best >= 0 && d2s[l] == least && id_of[l] < lowest_id)) {
      least = d2s[l];
      lowest_id = id_of[l];
      best = j_of[l];
    }
  }
  return best;
}

}  // namespace

void avx2::choosePartners(const ParticleSet& p, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                          std::span<std::int32_t> partner, Level coarsest, PartnerScratch& scratch) {
  detail::choosePartnersWith(nearestMergingNeighbour, p, grid, decision, partner, coarsest, scratch);
}

PartnerSearchForms avx2::partnerSearchForms() { return {avx2::choosePartners}; }

}  // namespace sph

SPH_AVX2_END
