#include "sph/adaptive/split_axis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace sph {

namespace {

// Largest t such that centre +- t * dir both lie inside the box shrunk by `margin`, capped at
// `wanted`. The parent already sits inside the box shrunk by its own, larger radius, so t > 0.
float symmetricReach(const Vec3& centre, const Vec3& dir, const BoxState& box, float margin, float wanted) {
  float t = wanted;
  for (int a = 0; a < 3; ++a) {
    const float d = std::abs(dir[a]);
    if (d < 1e-6f) continue;
    const float room = std::min(centre[a] - (box.min[a] + margin), (box.max[a] - margin) - centre[a]);
    t = std::min(t, std::max(room, 0.0f) / d);
  }
  return t;
}

// `dir` turned along the walls that would cut it short. A parent in the wall layer sits about a
// L1 half-spacing from the wall, which is all but the L0 radius the children keep off it,
// so along a direction into the wall its children landed on one point; nothing separates two
// particles on one point (the kernel's gradient vanishes there), and the doubled mass kicked the
// water around it (a dfsph tank split by the surface method moved much faster than with the
// children turned). Unchanged where no wall is that close, and where every axis is (a box hardly
// larger than a particle).
Vec3 alongWalls(const Vec3& centre, const Vec3& dir, const BoxState& box, float margin, float wanted) {
  Vec3 along = dir;
  for (int a = 0; a < 3; ++a) {
    const float room = std::min(centre[a] - (box.min[a] + margin), (box.max[a] - margin) - centre[a]);
    if (room < wanted * std::abs(dir[a])) along[a] = 0.0f;
  }
  const float length = along.norm();
  return length > 1e-3f ? Vec3(along / length) : dir;
}

// The candidates, in the order ties go: the cubes' four diagonals (a lattice split along one of
// them keeps each child farthest from the parent's neighbours), six face diagonals, three axes.
constexpr std::size_t kCandidates = 13;
constexpr std::size_t kLanes = 16;

std::array<Vec3, kCandidates> candidateAxes() {
  const float d = 1.0f / std::sqrt(3.0f);
  const float f = 1.0f / std::sqrt(2.0f);
  return {Vec3(d, d, d),          Vec3(d, d, -d),         Vec3(d, -d, d),        Vec3(-d, d, d),   Vec3(f, f, 0.0f),
          Vec3(f, -f, 0.0f),      Vec3(f, 0.0f, f),       Vec3(f, 0.0f, -f),     Vec3(0.0f, f, f), Vec3(0.0f, f, -f),
          Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 0.0f, 1.0f)};
}

// A later candidate must give more room than this share of `wanted` to win: water near a lattice
// then splits along one diagonal throughout, not along whichever rounding favours.
constexpr float kLead = 0.05f;

// The neighbours lie to one side (a free surface) where their mean offset from the parent is
// more than this share of the children's separation (zero in a full neighbourhood, about half a
// spacing at a flat surface).
constexpr float kOneSided = 0.2f;

// The unit normal of the plane the candidates are turned into: towards the neighbours where
// they lie to one side, else zero (no turn).
Vec3 sideOfNeighbours(const ParticleSet& p, std::span<const std::uint32_t> neighbors, const Vec3& centre,
                      float separation) {
  if (neighbors.empty()) return Vec3::Zero();
  Vec3 towards = Vec3::Zero();
  for (std::uint32_t j : neighbors) towards += p.position[j] - centre;
  towards /= static_cast<float>(neighbors.size());
  return towards.norm() > kOneSided * separation ? Vec3(towards.normalized()) : Vec3::Zero();
}

}  // namespace

Vec3 childOffsetInBox(const Vec3& centre, const Vec3& dir, const BoxState& box, float margin, float wanted) {
  const Vec3 along = alongWalls(centre, dir, box, margin, wanted);
  return symmetricReach(centre, along, box, margin, wanted) * along;
}

Vec3 awayFromNearestFaces(const Vec3& centre, const BoxState& box) {
  Vec3 away;
  for (int a = 0; a < 3; ++a) away[a] = centre[a] - box.min[a] <= box.max[a] - centre[a] ? 1.0f : -1.0f;
  return away / std::sqrt(3.0f);
}

Vec3 roomiestChildOffset(const ParticleSet& p, const NeighborGrid& grid, std::size_t i, const BoxState& box,
                         float margin, float wanted) {
  static const std::array<Vec3, kCandidates> candidates = candidateAxes();
  const Vec3 centre = p.position[i];
  const std::span<const std::uint32_t> neighbors = grid.neighbors(i);
  const Vec3 normal = sideOfNeighbours(p, neighbors, centre, 2.0f * wanted);
  // The candidates' offsets side by side, one lane each (the lanes past `count` stay at zero room
  // and are never read): each neighbour is read once for all of them, and the lanes vectorise.
  std::array<float, kLanes> ox{}, oy{}, oz{}, room2{};
  std::size_t count = 0;
  for (const Vec3& candidate : candidates) {
    // Turned into the surface's plane: out of the water is where the most room is, and a child
    // put there would stand off the surface (at the front of a flow, ahead of it).
    Vec3 axis = candidate - candidate.dot(normal) * normal;
    if (axis.norm() < 0.5f) continue;  // mostly along the normal: another candidate covers the plane
    axis.normalize();
    const Vec3 offset = childOffsetInBox(centre, axis, box, margin, wanted);
    ox[count] = offset.x();
    oy[count] = offset.y();
    oz[count] = offset.z();
    room2[count] = 4.0f * offset.squaredNorm();  // the children's own distance
    ++count;
  }
  for (std::uint32_t j : neighbors) {
    const Vec3 r = p.position[j] - centre;
    const float rx = r.x(), ry = r.y(), rz = r.z();
    for (std::size_t k = 0; k < kLanes; ++k) {
      const float ax = rx - ox[k], ay = ry - oy[k], az = rz - oz[k];
      const float bx = rx + ox[k], by = ry + oy[k], bz = rz + oz[k];
      const float to_a = ax * ax + ay * ay + az * az;
      const float to_b = bx * bx + by * by + bz * bz;
      room2[k] = std::min(room2[k], std::min(to_a, to_b));
    }
  }
  Vec3 best = Vec3::Zero();
  float best_room = -1.0f;
  for (std::size_t k = 0; k < count; ++k) {
    const float room = std::sqrt(room2[k]);
    if (room > best_room + kLead * wanted) {
      best_room = room;
      best = Vec3(ox[k], oy[k], oz[k]);
    }
  }
  return best;
}

}  // namespace sph
