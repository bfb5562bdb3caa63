// dfsph's own per-particle state. ParticleAttributes (particle_attributes.h) inherits it and
// kParticleAttributes gathers kDfsphAttributes, so it moves with its particle through re-sorts,
// splits, merges and checkpoints like every other attribute.
#pragma once

#include <tuple>
#include <vector>

#include "sph/attribute_spec.h"

namespace sph {

struct DfsphAttributes {
  // k = p / rho^2 of the constant-density and of the divergence solver in the last step, the next
  // step's warm start (Bender & Koschier 2017, 4.3).
  std::vector<float> kappa;
  std::vector<float> kappa_divergence;
};

// p / rho^2 is intensive: the children and the merged particle keep the field's value there, so
// the next step's warm start fits the water around them.
inline constexpr auto kDfsphAttributes =
    std::make_tuple(AttributeSpec<float, DfsphAttributes>{&DfsphAttributes::kappa, "kappa", 0.0f, SplitRule::kCopy,
                                                          MergeRule::kAverage},
                    AttributeSpec<float, DfsphAttributes>{&DfsphAttributes::kappa_divergence, "kappa_divergence", 0.0f,
                                                          SplitRule::kCopy, MergeRule::kAverage});

}  // namespace sph
