// Merge partners: each particle that wants to merge picks its nearest neighbour of its own level
// that wants to as well; mutual choices become pairs (split_merge.h applies them).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sph/neighbor_grid.h"
#include "sph/particles.h"

namespace sph {

// Scratch of choosePartners, kept between steps so the step does not allocate.
struct PartnerScratch {
  std::vector<std::int32_t> merging;  // per particle: its level + 1 where it may merge and is flagged MERGE, else 0
};

// For each particle below `coarsest` flagged MERGE, its nearest neighbour of the same level also
// flagged MERGE (the least squared distance, ties to the lower id), or -1. Pairs are the mutual choices: partner[i] ==
// j and partner[j] == i. Each particle writes only its own entry, so no particle can be claimed by two pairs and the
// choice does not depend on the thread count. The AVX-512 form tests the neighbours 16 at a time and chooses exactly as
// the scalar one (simd_level.h).
void choosePartners(const ParticleSet& particles, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                    std::span<std::int32_t> partner, Level coarsest, PartnerScratch& scratch);

namespace scalar {
void choosePartners(const ParticleSet& particles, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                    std::span<std::int32_t> partner, Level coarsest, PartnerScratch& scratch);
}  // namespace scalar
namespace avx2 {
void choosePartners(const ParticleSet& particles, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                    std::span<std::int32_t> partner, Level coarsest, PartnerScratch& scratch);
}  // namespace avx2
namespace avx512 {
void choosePartners(const ParticleSet& particles, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                    std::span<std::int32_t> partner, Level coarsest, PartnerScratch& scratch);
}  // namespace avx512

// The partner search as one form (simd_level.h).
struct PartnerSearchForms {
  void (*choosePartners)(const ParticleSet& particles, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                         std::span<std::int32_t> partner, Level coarsest, PartnerScratch& scratch);
};
namespace scalar {
PartnerSearchForms partnerSearchForms();
}  // namespace scalar
namespace avx2 {
PartnerSearchForms partnerSearchForms();
}  // namespace avx2
namespace avx512 {
PartnerSearchForms partnerSearchForms();
}  // namespace avx512
// The forms this CPU runs.
PartnerSearchForms partnerSearchForms();

namespace detail {
// The nearest neighbour of particle i in `list` (packed x, y, z positions) whose `merging` flag is
// i's own (the same level, flagged), or -1.
using NearestMergingNeighbourFn = std::int32_t (*)(const float* positions, const std::uint32_t* ids,
                                                   std::span<const std::uint32_t> list, const std::int32_t* merging,
                                                   std::size_t i);
// The search's one parallel region (both forms): flag the merging particles with their level, then
// each of them searches its list with `nearest`.
void choosePartnersWith(NearestMergingNeighbourFn nearest, const ParticleSet& particles, const NeighborGrid& grid,
                        std::span<const std::int8_t> decision, std::span<std::int32_t> partner, Level coarsest,
                        PartnerScratch& scratch);
}  // namespace detail

}  // namespace sph
