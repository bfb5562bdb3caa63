#include "sph/solvers/pbf/still_water_changes.h"

#include <algorithm>
#include <cmath>

namespace sph {

bool StillWaterChanges::markDamped(ParticleSet& p, const NeighborGrid& grid) {
  bool any = false;
  constexpr auto kMark = static_cast<std::uint8_t>(kDampedFrames);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool taking_up = std::abs(p.density_offset[i]) > kTakingUp;
    if (p.placed[i] == kNotPlaced && !taking_up) continue;
    any = any || p.placed[i] != kNotPlaced;
    // A placed particle's neighbours are already marked kNearPlacement: with theirs, two hops.
    p.still_damping[i] = kMark;
    for (const std::uint32_t j : grid.neighbors(i)) p.still_damping[j] = kMark;
  }
  if (any) {
    start_density_.reserve(p.capacity());
    start_density_.assign(p.density.begin(), p.density.end());
  }
  return any;
}

void StillWaterChanges::holdChanges(ParticleSet& p, const NeighborGrid& grid, std::span<const float> start_speed,
                                    PbfArrays& a, const PbfConstants& c) {
  held_.reserve(p.capacity());
  held_.clear();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.placed[i] != kNotPlaced && still(start_speed[i])) held_.push_back(static_cast<std::uint32_t>(i));
  }
  if (held_.empty()) return;
  // Their densities where they now stand.
  a.position = p.position.data()->data();
  a.only = held_.data();
  a.only_count = held_.size();
  pbfPassForms().lambda(a, c, grid);
  a.only = nullptr;
  a.only_count = 0;
  const float limit = kOffsetLimit * c.rest_density;
  for (const std::uint32_t i : held_) {
    p.density_offset[i] = std::clamp(p.density_offset[i] + p.density[i] - start_density_[i], -limit, limit);
  }
}

void StillWaterChanges::fade(ParticleSet& p) {
  constexpr float kKeep = 1.0f - 1.0f / static_cast<float>(kOffsetFadeFrames);
  for (float& o : p.density_offset) {
    o *= kKeep;
    if (std::abs(o) < kOffsetFloor) o = 0.0f;
  }
  for (std::uint8_t& d : p.still_damping) d = d > 0 ? static_cast<std::uint8_t>(d - 1) : 0;
}

}  // namespace sph
