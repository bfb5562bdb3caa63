#include "sph/scene.h"

#include <cmath>
#include <stdexcept>
#include <string>

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

int initialParticleCount(const Scene& scene, SizeClass start_class) {
  if (start_class == SizeClass::Large) return scene.large_particles;
  const double ratio = scene.params.mass_large / scene.params.classes()[classIndex(start_class)].mass;
  return static_cast<int>(std::lround(scene.large_particles * ratio));
}

}  // namespace sph
