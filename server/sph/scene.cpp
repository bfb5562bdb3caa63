#include "sph/scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sph/particles.h"

namespace sph {

Scene gatedScene(const Scene& scene) {
  Scene gated = scene;
  const BoxState box = scene.boundary.stateAt(0.0);
  gated.boundary.box.min = scene.water.min.cwiseMax(box.min.cast<double>());
  gated.boundary.box.max = scene.water.max.cwiseMin(box.max.cast<double>());
  gated.boundary.changes.clear();
  gated.boundary.moving_walls.clear();
  return gated;
}

std::array<int, kMaxLevels> initialFill(const Scene& scene, Level start) {
  std::array<int, kMaxLevels> counts{};
  const int k = levelIndex(start);
  if (k < 0 || k >= kMaxLevels) throw std::invalid_argument("initialFill: no level " + std::to_string(k));
  // The water's mass in L0 particles (m_L1 = 2 m_L0, SimParams::validate).
  const long long finest = 2LL * scene.large_particles;
  counts[static_cast<std::size_t>(k)] = static_cast<int>(finest >> k);
  const long long rest = finest - ((finest >> k) << k);
  for (int j = 0; j < k; ++j) counts[static_cast<std::size_t>(j)] = static_cast<int>((rest >> j) & 1);
  return counts;
}

int initialParticleCount(const Scene& scene, Level start) {
  int n = 0;
  for (const int c : initialFill(scene, start)) n += c;
  return n;
}

std::size_t refinedCapacity(const Scene& scene) {
  return std::max<std::size_t>(ParticleSet::kDefaultCapacity,
                               static_cast<std::size_t>(initialParticleCount(scene, Level{0})));
}

}  // namespace sph
