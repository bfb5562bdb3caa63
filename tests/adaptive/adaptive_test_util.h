// Shared set-up for the adaptive tests: small scenes built in code, a camera looking at them, and
// conservation checks.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "sph/adaptive/adaptive_controller.h"
#include "sph/camera.h"
#include "sph/simulation.h"

namespace adaptive_test {

// A resting pool: `large` L1 particles of water filling a box of the given footprint from the
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

// A column of water released into a wider box: it surges, so split and merge meet moving water.
inline sph::Scene surgeScene() {
  sph::Scene scene = poolScene(0.6, 0.3, 1200);
  scene.water.max = Eigen::Vector3d(0.25, 1.0, 0.3);
  return scene;
}

// A simulation with a method's adaptive step, and the controller to feed gaze between steps.
struct Rig {
  std::unique_ptr<sph::Simulation> sim;
  sph::AdaptiveController* controller = nullptr;
};

inline Rig makeRig(const sph::Scene& scene, sph::Method method, const sph::AdaptiveConfig& config = {}) {
  Rig rig;
  rig.sim = std::make_unique<sph::Simulation>(scene, sph::startLevel(method, scene.params.levels));
  auto controller = sph::makeAdaptiveController(method, scene.params.levels, config, cameraOf(scene));
  rig.controller = controller.get();
  rig.sim->setAdaptiveStep(std::move(controller));
  return rig;
}

// A fresh, valid gaze sample at normalized screen coordinates.
inline sph::GazeInput gazeAt(double x, double y) {
  sph::GazeInput g;
  g.present = true;
  g.x = x;
  g.y = y;
  g.age_s = 0.0;
  return g;
}

// What a thread-count comparison compares: ids, levels, and the bits of positions and velocities.
struct Snapshot {
  std::vector<std::uint32_t> id;
  std::vector<sph::Vec3> position;
  std::vector<sph::Vec3> velocity;
  std::vector<sph::Level> level;
};

inline Snapshot snapshotOf(const sph::ParticleSet& p) { return {p.id, p.position, p.velocity, p.level}; }

inline void expectSameBits(const Snapshot& one, const Snapshot& two) {
  ASSERT_EQ(one.id, two.id);
  ASSERT_EQ(one.level, two.level);
  ASSERT_EQ(std::memcmp(one.position.data(), two.position.data(), one.position.size() * sizeof(sph::Vec3)), 0);
  ASSERT_EQ(std::memcmp(one.velocity.data(), two.velocity.data(), one.velocity.size() * sizeof(sph::Vec3)), 0);
}

// Total mass must equal the sum over the levels of m_k N_k exactly (the float masses are exact
// binary multiples, and the double sum of up to 20,000 of them is exact).
inline void expectMassByClass(const sph::Simulation& sim, double initial_mass) {
  const sph::ParticleSet& p = sim.particles();
  const auto levels = sim.params().levelProps();
  double expected = 0.0;
  for (int k = 0; k < sph::kMaxLevels; ++k) {
    expected +=
        static_cast<double>(static_cast<float>(levels[k].mass)) * static_cast<double>(p.countOf(sph::asLevel(k)));
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
