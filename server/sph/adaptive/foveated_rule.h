// The foveated method (foveated.h): as many levels as the run has, water starting at the
// coarsest, each particle as fine as the eye resolves where it is seen; further split passes in
// the same step where the eye sees water more than a level too coarse (a saccade's new fovea), and
// what the eye gets measured apart from the rule (perceptual_budget.h).
#pragma once

#include <cstdint>
#include <vector>

#include "sph/adaptive/adaptive_rule.h"
#include "sph/adaptive/foveated.h"
#include "sph/adaptive/perceptual_budget.h"

namespace sph {

class FoveatedRule : public AdaptiveRule {
 public:
  Method method() const override { return Method::Foveated; }
  Level coarsest(int levels) const override;
  // A fine particle left over where the eye allows a coarser one holds its neighbourhood fine
  // (grading) until it pairs, and where it may merge the eye does not resolve where its mass goes.
  float stragglerReach() const override { return 4.0f; }
  void step(Simulation& sim, const RuleInput& in, LevelChanges& changes, AdaptiveStats& stats) override;
  void measure(const Simulation& sim, const RuleInput& in, AdaptiveStats& stats) override;

 private:
  FoveatedScratch scratch_;
  PerceptualBudgetMeter meter_;
  // A further split pass's scratch: the step's placements, them and their neighbours, the marks.
  std::vector<std::uint32_t> fresh_, fresh_neighbourhoods_;
  std::vector<std::uint8_t> mark_;
};

}  // namespace sph
