// Applying the decisions: split (3.37)-(3.39), merge (3.40)-(3.43), then the merged-away particles
// leave the arrays (ParticleSet::swapRemove moves every attribute). Mass is conserved exactly: each
// level's mass is exactly twice the one below's (params.h; L1 twice L0, checked when the
// parameters are), and split and merge only ever trade one for two of the level below.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sph/adaptive/partner_search.h"
#include "sph/simulation.h"

namespace sph {

// Scratch of pairStragglers, kept between steps so the step does not allocate.
struct StragglerScratch {
  std::vector<std::uint32_t> lonely;  // the stragglers' particle indices, ascending (room for all)
  std::vector<std::int32_t> nearest;  // per straggler: position in `lonely` of its nearest, or -1
  std::vector<std::uint32_t> by_x;    // positions in `lonely`, sorted by x
  std::vector<std::size_t> ranges;    // per thread: where its stragglers start, how many
};

// Stragglers: particles that want to merge but found no candidate of their level at all within
// the neighbour reach (partner -1), typically one child left behind in coarser water, would stay
// fine for good. Pairs them among themselves, each level with its own: mutual nearest of the same
// level within `reach` times the particle's support (ties to the lower index), at most 512 per
// step (the lowest indices), so the result is deterministic.
void pairStragglers(const ParticleSet& particles, std::span<const std::int8_t> decision,
                    std::span<std::int32_t> partner, float reach, Level coarsest, StragglerScratch& scratch);

struct SplitMergeCounts {
  int splits = 0;
  int merges = 0;
};

// Splits every particle above L0 flagged SPLIT into two children of the level below, placed
// symmetrically about its centre (split_axis.h: on incompressible water along the axis with the most room among its
// neighbours, or from a box corner one at the centre and one into the box; on the thesis's along a
// direction drawn from its id; deterministic), and merges
// every mutual pair into one of the level above at the pair's midpoint with the mean velocity. Children
// and merged particles stay inside the box with their radius. `keep` and `split_list` are scratch.
SplitMergeCounts applySplitMerge(Simulation& sim, std::span<const std::int8_t> decision,
                                 std::span<const std::int32_t> partner, std::vector<std::uint8_t>& keep,
                                 std::vector<std::uint32_t>& split_list);

// Unit vector drawn from a particle id (splitmix64), the axis a split on the thesis's water places
// its children along.
Vec3 splitDirection(std::uint32_t id);

}  // namespace sph
