#include "sph/adaptive/partner_search.h"

#if defined(__AVX512F__)
// GCC 12's AVX-512 headers build the reductions on *_undefined_*(), which its own flow analysis
// reports as maybe-uninitialized once inlined (GCC bug 105593).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#endif

#include "sph/avx512_lanes.h"

#include <cmath>
#include <limits>

#include "sph/adaptive/decide.h"
#include "sph/fluid_stages.h"
#include "sph/thread_share.h"

namespace sph {

namespace {

#if defined(__AVX512F__)
constexpr bool kPartnerSearchAvx512 = true;
#else
constexpr bool kPartnerSearchAvx512 = false;
#endif

// |a - b|^2. Where the CPU has FMA (every AVX-512 one does), with explicit fused multiply-adds,
// so that the scalar and the vector search round alike (left to the compiler, contraction may
// differ between the two); without it std::fma would be a library call per neighbour.
inline float squaredDistance(float dx, float dy, float dz) {
#if defined(__FMA__)
  return std::fma(dz, dz, std::fma(dy, dy, dx * dx));
#else
  return dx * dx + dy * dy + dz * dz;
#endif
}

// The nearest neighbour of particle i among those flagged in `merging` (candidates from the
// neighbour list, i.e. within (hi + hj) / 2, eq. (3.34)): least squared distance, ties to the
// lower id; -1 when there is none.
std::int32_t nearestMergingNeighbour(const ParticleSet& p, std::span<const std::uint32_t> list,
                                     const std::int32_t* merging, std::size_t i) {
  float best_d2 = std::numeric_limits<float>::infinity();
  std::uint32_t best_id = 0;
  std::int32_t best = -1;
  const Vec3 xi = p.position[i];
  for (std::uint32_t j : list) {
    if (merging[j] == 0) continue;
    const Vec3 xj = p.position[j];
    const float d2 = squaredDistance(xi.x() - xj.x(), xi.y() - xj.y(), xi.z() - xj.z());
    if (d2 < best_d2 || (d2 == best_d2 && p.id[j] < best_id)) {
      best_d2 = d2;
      best_id = p.id[j];
      best = static_cast<std::int32_t>(j);
    }
  }
  return best;
}

#if defined(__AVX512F__)
// nearestMergingNeighbour 16 neighbours at a time. Each lane keeps its own best (distance, id)
// and the lanes' bests are compared at the end: the least distance, then the lower id, the same
// choice as the scalar search makes in list order. Only the candidate lanes gather positions and
// ids, and most batches have none or few.
std::int32_t nearestMergingNeighbourAvx512(const float* pos, const std::uint32_t* ids,
                                           std::span<const std::uint32_t> list, const std::int32_t* merging,
                                           std::size_t i) {
  const __m512 xi = _mm512_set1_ps(pos[3 * i]);
  const __m512 yi = _mm512_set1_ps(pos[3 * i + 1]);
  const __m512 zi = _mm512_set1_ps(pos[3 * i + 2]);
  const __m512 inf = _mm512_set1_ps(std::numeric_limits<float>::infinity());
  __m512 best_d2 = inf;
  __m512i best_id = _mm512_set1_epi32(-1);  // as unsigned: above every id
  __m512i best_j = _mm512_set1_epi32(-1);
  const auto size = static_cast<std::uint32_t>(list.size());
  for (std::uint32_t b = 0; b < size; b += 16) {
    const std::uint32_t left = size - b;
    const __mmask16 live = lanes::liveLanes(left);
    const __m512i j = _mm512_maskz_loadu_epi32(live, list.data() + b);
    const __m512i flag = _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), live, j, merging, 4);
    const __mmask16 candidate = _mm512_mask_test_epi32_mask(live, flag, flag);
    if (candidate == 0) continue;
    const __m512i j3 = lanes::tripleIndex(j);
    const __m512 dx = _mm512_sub_ps(xi, lanes::gather(candidate, j3, pos));
    const __m512 dy = _mm512_sub_ps(yi, lanes::gather(candidate, j3, pos + 1));
    const __m512 dz = _mm512_sub_ps(zi, lanes::gather(candidate, j3, pos + 2));
    const __m512 d2 = _mm512_fmadd_ps(dz, dz, _mm512_fmadd_ps(dy, dy, _mm512_mul_ps(dx, dx)));
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
#endif

// The search's one parallel region: flag the merging SMALL particles, then each of them searches
// its list. `kVector`: 16 neighbours at a time.
template <bool kVector>
void choosePartnersWith(const ParticleSet& p, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                        std::span<std::int32_t> partner, PartnerScratch& scratch) {
  const std::size_t n = p.size();
  scratch.merging.resize(n);
  std::int32_t* merging = scratch.merging.data();
#pragma omp parallel
  {
    const ThreadShare share = threadShare(n);
    for (std::size_t i = share.begin; i < share.end; ++i) {
      merging[i] = -static_cast<std::int32_t>(wantsMerge(decision[i], p.size_class[i]));
    }
#pragma omp barrier
    // Only the flagged particles search, and they sit together: chunks even out the threads.
#pragma omp for schedule(dynamic, kPairLoopChunk)
    for (std::size_t i = 0; i < n; ++i) {
      if (merging[i] == 0) {
        partner[i] = -1;
        continue;
      }
#if defined(__AVX512F__)
      if constexpr (kVector) {
        partner[i] =
            nearestMergingNeighbourAvx512(p.position.data()->data(), p.id.data(), grid.neighbors(i), merging, i);
        continue;
      }
#endif
      partner[i] = nearestMergingNeighbour(p, grid.neighbors(i), merging, i);
    }
  }
}

}  // namespace

bool partnerSearchVectorized() { return kPartnerSearchAvx512; }

void choosePartners(const ParticleSet& p, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                    std::span<std::int32_t> partner, PartnerScratch& scratch) {
  choosePartnersWith<kPartnerSearchAvx512>(p, grid, decision, partner, scratch);
}

void scalar::choosePartners(const ParticleSet& p, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                            std::span<std::int32_t> partner, PartnerScratch& scratch) {
  choosePartnersWith<false>(p, grid, decision, partner, scratch);
}

}  // namespace sph
