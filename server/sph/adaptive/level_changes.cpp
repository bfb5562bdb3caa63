#include "sph/adaptive/level_changes.h"

#include <algorithm>

namespace sph {

std::span<std::int8_t> LevelChanges::decisions(std::size_t particles) {
  decision_.resize(particles);
  partner_.resize(particles);
  return decision_;
}

SplitMergeCounts LevelChanges::apply(Simulation& sim, const DecisionCounts& wanted, Level coarsest,
                                     float straggler_reach) {
  const ParticleSet& p = sim.particles();
  if (wanted.merge_wanted > 0) {
    choosePartners(p, sim.grid(), decision_, partner_, coarsest, partner_scratch_);
    pairStragglers(p, decision_, partner_, straggler_reach, coarsest, stragglers_);
  } else {
    std::fill(partner_.begin(), partner_.end(), -1);
  }
  return applySplitMerge(sim, decision_, partner_, keep_, split_list_);
}

int LevelChanges::applySplits(Simulation& sim) {
  partner_.assign(decision_.size(), -1);
  return applySplitMerge(sim, decision_, partner_, keep_, split_list_).splits;
}

}  // namespace sph
