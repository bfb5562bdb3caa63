#include "sph/adaptive/partner_search.h"

#include <limits>

#include "sph/adaptive/decide.h"
#include "sph/simd/simd_level.h"
#include "sph/thread_share.h"

namespace sph {

namespace {

// The nearest neighbour of particle i among those flagged in `merging` (candidates from the
// neighbour list, i.e. within (hi + hj) / 2, eq. (3.34)): least squared distance, ties to the
// lower id; -1 when there is none.
std::int32_t nearestMergingNeighbour(const float* pos, const std::uint32_t* ids, std::span<const std::uint32_t> list,
                                     const std::int32_t* merging, std::size_t i) {
  float best_d2 = std::numeric_limits<float>::infinity();
  std::uint32_t best_id = 0;
  std::int32_t best = -1;
  const std::int32_t own = merging[i];
  for (std::uint32_t j : list) {
    if (merging[j] != own) continue;
    const float dx = pos[3 * i] - pos[3 * j];
    const float dy = pos[3 * i + 1] - pos[3 * j + 1];
    const float dz = pos[3 * i + 2] - pos[3 * j + 2];
    // Built with -ffp-contract=off (CMakeLists.txt), as is the AVX-512 form, so both round the
    // same three products and two sums and choose alike.
    const float d2 = dx * dx + dy * dy + dz * dz;
    if (d2 < best_d2 || (d2 == best_d2 && ids[j] < best_id)) {
      best_d2 = d2;
      best_id = ids[j];
      best = static_cast<std::int32_t>(j);
    }
  }
  return best;
}

}  // namespace

namespace detail {

void choosePartnersWith(NearestMergingNeighbourFn nearest, const ParticleSet& p, const NeighborGrid& grid,
                        std::span<const std::int8_t> decision, std::span<std::int32_t> partner, Level coarsest,
                        PartnerScratch& scratch) {
  const std::size_t n = p.size();
  scratch.merging.resize(n);
  std::int32_t* merging = scratch.merging.data();
  const float* pos = p.position.data()->data();
#pragma omp parallel
  {
    const ThreadShare share = threadShare(n);
    for (std::size_t i = share.begin; i < share.end; ++i) {
      merging[i] =
          static_cast<std::int32_t>(wantsMerge(decision[i], p.level[i], coarsest)) * (levelIndex(p.level[i]) + 1);
    }
#pragma omp barrier
    // Only the flagged particles search, and they sit together: chunks even out the threads.
#pragma omp for schedule(dynamic, kPairLoopChunk)
    for (std::size_t i = 0; i < n; ++i) {
      partner[i] = merging[i] == 0 ? -1 : nearest(pos, p.id.data(), grid.neighbors(i), merging, i);
    }
  }
}

}  // namespace detail

void choosePartners(const ParticleSet& p, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                    std::span<std::int32_t> partner, Level coarsest, PartnerScratch& scratch) {
  partnerSearchForms().choosePartners(p, grid, decision, partner, coarsest, scratch);
}

PartnerSearchForms partnerSearchForms() {
  return formsForThisCpu(scalar::partnerSearchForms, avx2::partnerSearchForms, avx512::partnerSearchForms);
}

PartnerSearchForms scalar::partnerSearchForms() { return {scalar::choosePartners}; }

void scalar::choosePartners(const ParticleSet& p, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                            std::span<std::int32_t> partner, Level coarsest, PartnerScratch& scratch) {
  detail::choosePartnersWith(nearestMergingNeighbour, p, grid, decision, partner, coarsest, scratch);
}

}  // namespace sph
