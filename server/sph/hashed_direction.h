// Deterministic directions drawn from integer keys: a split's axis (from the parent's id) and the
// push between two particles on one point (from the pair's ids).
#pragma once

#include <cstdint>

#include "sph/particles.h"

namespace sph {

// Unit vector drawn from a 64-bit key (splitmix64, then a uniform point on the sphere).
Vec3 hashedUnitVector(std::uint64_t key);

}  // namespace sph
