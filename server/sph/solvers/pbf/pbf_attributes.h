// pbf's own per-particle state, for a level change in still water (still_water_changes.h).
// ParticleAttributes (particle_attributes.h) inherits it and kParticleAttributes gathers
// kPbfAttributes, so it moves with its particle through re-sorts, splits, merges and checkpoints
// like every other attribute.
#pragma once

#include <cstdint>
#include <tuple>
#include <vector>

#include "sph/attribute_spec.h"

namespace sph {

struct PbfAttributes {
  // How much denser (negative: less dense) than rest density the density constraint leaves the
  // particle, kg/m^3, fading frame by frame.
  std::vector<float> density_offset;
  // The frames left in which a still particle keeps only part of the speed a step gives it.
  std::vector<std::uint8_t> still_damping;
};

inline constexpr auto kPbfAttributes = std::make_tuple(
    // An intensive quantity: the children and the merged particle keep the water's value there.
    AttributeSpec<float, PbfAttributes>{&PbfAttributes::density_offset, "density_offset", 0.0f, SplitRule::kCopy,
                                        MergeRule::kAverage},
    // The merged particle keeps the longer of the two's damping.
    AttributeSpec<std::uint8_t, PbfAttributes>{&PbfAttributes::still_damping, "still_damping", std::uint8_t{0},
                                               SplitRule::kCopy, MergeRule::kMax});

}  // namespace sph
