// How an attribute of ParticleAttributes (particle_attributes.h) is declared: its name, a new
// particle's value and what becomes of it when particles split and merge. Apart from
// particle_attributes.h so that a solver's folder can declare its own attributes with it.
#pragma once

#include <cstdint>
#include <vector>

namespace sph {

// A particle splits into two of the level below, an L1 into two L0 children (eqs.
// (3.37)-(3.39)); each child's attribute is:
enum class SplitRule : std::uint8_t {
  kCopy,     // the parent's value (velocity, eq. (3.39); position, then moved apart along the split axis)
  kHalve,    // half the parent's value: an extensive quantity (mass, eq. (3.38); volume)
  kReset,    // the attribute's reset value
  kFreshId,  // the first child keeps the parent's value, the second its own fresh one (the id)
  kLevel,    // the level below the parent's (L0 for L1; ParticleSet::setLevel: size class, radius, support)
  kMark,     // kPlacedThisFrame for both: the adaptive step placed them (the `placed` flag)
};

// Two particles of a level merge into one of the level above, two L0 into one L1 (eqs.
// (3.40)-(3.43)); the survivor's attribute is:
enum class MergeRule : std::uint8_t {
  kKeep,     // the survivor's own value (the id)
  kAverage,  // the mean of the two: equal masses, so the centre of mass and momentum are kept
  kSum,      // the sum: an extensive quantity (mass, eq. (3.41); volume)
  kMin,      // the smaller (a distance: the nearer of the two is the merged particle's)
  kMax,      // the larger
  kReset,    // the attribute's reset value
  kLevel,    // the level above the two's (L1 for L0; ParticleSet::setLevel)
  kMark,     // kPlacedThisFrame: the adaptive step placed it (the `placed` flag)
};

struct ParticleAttributes;

// Permute and swap-remove move every attribute with its particle: they need no rule. `Holder` is
// the struct that declares the member: ParticleAttributes, or a solver's attributes, which
// ParticleAttributes inherits (so `particles.*member` reaches it all the same).
template <typename T, typename Holder = ParticleAttributes>
struct AttributeSpec {
  using Value = T;
  std::vector<T> Holder::*member;
  const char* name;
  T reset_value;  // a new particle's value (ParticleSet::add, appendReset) and the kReset rules'
  SplitRule split;
  MergeRule merge;
};

}  // namespace sph
