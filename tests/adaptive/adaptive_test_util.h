// Shared set-up for the adaptive tests: small scenes built in code, a camera looking at them, and
// conservation checks.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>

#include "sph/adaptive/adaptive_controller.h"
#include "sph/camera.h"
#include "sph/simulation.h"

namespace adaptive_test {

// A resting pool: `large` LARGE particles of water filling a box of the given footprint from the
// floor up (so the count sets the depth: one layer of a 0.5 x 0.5 footprint holds 324).
inline sph::Scene poolScene(double width, double length, int large) {
  sph::Scene scene;
  scene.name = "pool";
  scene.source = "adaptive_test";
  scene.params = sph::thesisPreset();
  scene.boundary.box.min = Eigen::Vector3d::Zero();
  scene.boundary.box.max = Eigen::Vector3d(width, 1.0, length);
  scene.water.min = Eigen::Vector3d::Zero();
  scene.water.max = Eigen::Vector3d(width, 1.0, length);
  scene.large_particles = large;
  // Looking down at the pool from the front, above.
  scene.camera.eye = Eigen::Vector3d(width / 2, 1.2, length + 1.2);
  scene.camera.target = Eigen::Vector3d(width / 2, 0.0, length / 2);
  return scene;
}

inline sph::ScreenCamera cameraOf(const sph::Scene& scene) { return sph::cameraFromSpec(scene.camera); }

// Total mass must equal the sum over the levels of m_k N_k exactly (the float masses are exact
// binary multiples, and the double sum of up to 20,000 of them is exact).
inline void expectMassByClass(const sph::Simulation& sim, double initial_mass) {
  const sph::ParticleSet& p = sim.particles();
  const auto levels = sim.params().classes();
  double expected = 0.0;
  for (int k = 0; k < sph::kSizeClassCount; ++k) {
    expected +=
        static_cast<double>(static_cast<float>(levels[k].mass)) * static_cast<double>(p.countOf(sph::sizeLevel(k)));
  }
  EXPECT_EQ(p.totalMass(), expected);
  EXPECT_EQ(p.totalMass(), initial_mass);
}

inline Eigen::Vector3d momentum(const sph::ParticleSet& p) {
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) {
    m += static_cast<double>(p.mass[i]) * p.velocity[i].cast<double>();
  }
  return m;
}

}  // namespace adaptive_test
