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
  const double ratio = scene.params.mass_large / scene.params.mass_small;
  return static_cast<int>(std::lround(scene.large_particles * ratio));
}

void fillWater(const Scene& scene, SizeClass start_class, ParticleSet& out) {
  const SizeClassProps props = scene.params.classes()[classIndex(start_class)];
  const int count = initialParticleCount(scene, start_class);
  const double spacing = std::cbrt(props.mass / scene.params.rest_density);
  // First lattice point half a spacing in: the lattice then tiles the region with each particle's
  // volume (the incompressible presets' walls count in the density, boundary_volume.h). The
  // thesis's collision keeps a particle a radius off a wall (3.29): there the first point is a
  // radius in, so no particle starts in contact with the region's walls.
  const bool thesis = scene.params.solver == Solver::kThesis;
  const double inset = thesis ? std::max(0.5 * spacing, props.radius) : 0.5 * spacing;
  int cells[3];
  for (int a = 0; a < 3; ++a) {
    const double room = scene.water.max[a] - scene.water.min[a] - 2.0 * inset;
    cells[a] = room < 0.0 ? 0 : static_cast<int>(std::floor(room / spacing)) + 1;
  }
  const long capacity = static_cast<long>(cells[0]) * cells[1] * cells[2];
  if (capacity < count) {
    throw std::invalid_argument(scene.source + ": water region holds " + std::to_string(capacity) + " " +
                                sizeClassName(start_class) + " particles at spacing " + std::to_string(spacing) +
                                ", the scene needs " + std::to_string(count));
  }
  if (static_cast<std::size_t>(count) > out.capacity()) {
    throw std::invalid_argument(scene.source + ": " + std::to_string(count) + " particles exceed the capacity of " +
                                std::to_string(out.capacity()));
  }
  out.clear();
  // y outermost so that the lowest layers fill first.
  for (int y = 0; y < cells[1] && static_cast<int>(out.size()) < count; ++y) {
    for (int z = 0; z < cells[2] && static_cast<int>(out.size()) < count; ++z) {
      for (int x = 0; x < cells[0] && static_cast<int>(out.size()) < count; ++x) {
        const Eigen::Vector3d p =
            scene.water.min + Eigen::Vector3d(inset + x * spacing, inset + y * spacing, inset + z * spacing);
        out.add(p.cast<float>(), Vec3::Zero(), start_class, props);
      }
    }
  }
  const BoxState box = scene.boundary.stateAt(0.0);
  const auto margin = static_cast<float>(inset);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Vec3& p = out.position[i];
    for (int a = 0; a < 3; ++a) {
      if (p[a] - margin < box.min[a] - 1e-6f || p[a] + margin > box.max[a] + 1e-6f) {
        throw std::invalid_argument(scene.source + ": key 'water' places particles outside 'box'");
      }
    }
  }
}

}  // namespace sph
