// The library tests' scene: a box from the origin to `box_max`, water in [water_min, water_max]
// (filled from its floor up with `large_particles` L1 particles' worth), the preset's parameters.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>

#include "sph/params.h"
#include "sph/scene.h"

namespace sph_test {

inline sph::Scene boxScene(const std::string& source, const std::string& preset, const Eigen::Vector3d& box_max,
                           const Eigen::Vector3d& water_min, const Eigen::Vector3d& water_max, int large_particles) {
  sph::Scene scene;
  scene.name = source;
  scene.source = source;
  if (!sph::presetByName(preset, scene.params)) throw std::invalid_argument("no preset '" + preset + "'");
  scene.boundary.box.min = Eigen::Vector3d::Zero();
  scene.boundary.box.max = box_max;
  scene.water.min = water_min;
  scene.water.max = water_max;
  scene.large_particles = large_particles;
  return scene;
}

}  // namespace sph_test
