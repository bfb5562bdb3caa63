// What every adaptive method does with its decisions (thesis 3.6): partners for the particles that
// merge (choosePartners, then stragglers within a reach), then split (3.37)-(3.39) and merge
// (3.40)-(3.43) applied and the arrays compacted. A method's rule (adaptive_rule.h) fills
// decisions() and calls apply(); its scratch is sized once to the particle capacity.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sph/adaptive/decide.h"
#include "sph/adaptive/partner_search.h"
#include "sph/adaptive/split_merge.h"
#include "sph/simulation.h"

namespace sph {

class LevelChanges {
 public:
  // The decisions for the current particles (sized to them), for the rule to fill.
  std::span<std::int8_t> decisions(std::size_t particles);
  // Partners (merges pair within the level, `coarsest` never merges; stragglers within
  // `straggler_reach` of their support radii), then the splits and merges.
  SplitMergeCounts apply(Simulation& sim, const DecisionCounts& wanted, Level coarsest, float straggler_reach);
  // The splits of decisions() alone (a further split pass in the same step: no merges).
  int applySplits(Simulation& sim);

 private:
  std::vector<std::int8_t> decision_;
  std::vector<std::int32_t> partner_;
  std::vector<std::uint8_t> keep_;
  std::vector<std::uint32_t> split_list_;
  PartnerScratch partner_scratch_;
  StragglerScratch stragglers_;
};

}  // namespace sph
