// Merge partners: each SMALL particle that wants to merge picks its nearest neighbour that wants
// to as well; mutual choices become pairs (split_merge.h applies them).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sph/neighbor_grid.h"
#include "sph/particles.h"

namespace sph {

// Scratch of choosePartners, kept between steps so the step does not allocate.
struct PartnerScratch {
  std::vector<std::int32_t> merging;  // per particle: -1 where SMALL and flagged MERGE, else 0
};

// For each SMALL particle flagged MERGE, its nearest SMALL neighbour also flagged MERGE (the least
// squared distance, ties to the lower id), or -1. Pairs are the mutual choices: partner[i] == j
// and partner[j] == i. Each particle writes only its own entry, so no particle can be claimed by
// two pairs and the choice does not depend on the thread count. Where the build targets AVX-512
// the neighbours are tested 16 at a time; the choice is the same as the scalar search's.
void choosePartners(const ParticleSet& particles, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                    std::span<std::int32_t> partner, PartnerScratch& scratch);

namespace scalar {
// The search one neighbour at a time (what choosePartners runs without AVX-512).
void choosePartners(const ParticleSet& particles, const NeighborGrid& grid, std::span<const std::int8_t> decision,
                    std::span<std::int32_t> partner, PartnerScratch& scratch);
}  // namespace scalar

// True when choosePartners tests neighbours 16 at a time (AVX-512).
bool partnerSearchVectorized();

}  // namespace sph
