#include "sph/hashed_direction.h"

#include <algorithm>
#include <cmath>

namespace sph {

namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

Vec3 hashedUnitVector(std::uint64_t key) {
  const std::uint64_t h = splitmix64(key);
  // Two 24-bit uniforms -> a point on the unit sphere (Archimedes: z uniform in [-1, 1]).
  const float u1 = static_cast<float>(h & 0xFFFFFFu) / 16777216.0f;
  const float u2 = static_cast<float>((h >> 24) & 0xFFFFFFu) / 16777216.0f;
  const float z = 1.0f - 2.0f * u1;
  const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 6.2831853f * u2;
  return {s * std::cos(phi), s * std::sin(phi), z};
}

}  // namespace sph
