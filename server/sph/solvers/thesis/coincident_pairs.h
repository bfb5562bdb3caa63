// Two particles on the same point: the spiky gradient of eq. (3.4) has no direction at r = 0, so
// the pressure force between them vanishes and nothing ever separates them. Collisions make such
// pairs: the box clamps every particle of a class that is driven into a corner to the same point,
// and a thesis-preset dam break piled L1 particles there at many times rest density, for good.
// The force takes the gradient's limit instead, |grad W| -> 45 h^2 / (pi h^6), along a direction
// hashed from the pair's ids and opposite for the two particles, so momentum is still conserved
// and the result does not depend on the order or thread that evaluates it.
#pragma once

#include <algorithm>
#include <cstdint>

#include "sph/hashed_direction.h"
#include "sph/solvers/thesis/thesis_stages.h"

namespace sph {

// The direction particle id_i is pushed away from id_j when both sit on the same point;
// coincidentPairDirection(a, b) == -coincidentPairDirection(b, a).
inline Vec3 coincidentPairDirection(std::uint32_t id_i, std::uint32_t id_j) {
  const std::uint64_t key = (std::uint64_t{std::min(id_i, id_j)} << 32) | std::max(id_i, id_j);
  const Vec3 u = hashedUnitVector(key);
  return id_i < id_j ? Vec3(u) : Vec3(-u);
}

// Pressure acceleration on i, eq. (3.13) divided by rho_i, from a neighbour j on the same point.
inline Vec3 coincidentPressureAcceleration(const ParticleSet& p, const KernelTable& kernels, std::size_t i,
                                           std::uint32_t j) {
  const KernelConstants& ki = kernels[levelIndex(p.level[i])];
  const KernelConstants& kj = kernels[levelIndex(p.level[j])];
  // spiky_grad (h - r)^2 at r = 0, averaged over the two supports as eq. (3.35) does.
  const float gradient = 0.5f * (ki.spiky_grad * ki.h * ki.h + kj.spiky_grad * kj.h * kj.h);
  return (-p.mass[j] * (p.pressure_term[i] + p.pressure_term[j]) * gradient) *
         coincidentPairDirection(p.id[i], p.id[j]);
}

}  // namespace sph
