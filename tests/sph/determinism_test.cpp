// The step gives the same result, bit for bit, on one thread and on two (every stage writes only
// its own particle and reads neighbours in a fixed order), and keeps every particle in the box.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>

#include "sph/simulation.h"
#include "support/box_scene.h"

namespace {

sph::Scene smallScene() {
  return sph_test::boxScene("determinism_test", "thesis", {0.6, 0.6, 0.6}, {0.0, 0.0, 0.0}, {0.3, 0.3, 0.3}, 1000);
}

struct RunResult {
  std::vector<std::uint32_t> id;
  std::vector<sph::Vec3> position;
  std::vector<sph::Vec3> velocity;
  std::vector<float> radius;
};

RunResult runWithThreads(int threads, int steps) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  EXPECT_EQ(omp_get_max_threads(), threads);
  sph::Simulation sim(smallScene(), sph::Level{0});
  for (int s = 0; s < steps; ++s) sim.step();
  omp_set_num_threads(previous);
  const sph::ParticleSet& p = sim.particles();
  return {p.id, p.position, p.velocity, p.radius};
}

bool sameBits(const sph::Vec3& a, const sph::Vec3& b) {
  return std::memcmp(a.data(), b.data(), sizeof(float) * 3) == 0;
}

TEST(Simulation, ResultIndependentOfThreadCount) {
  constexpr int kSteps = 60;
  const RunResult one = runWithThreads(1, kSteps);
  const RunResult two = runWithThreads(2, kSteps);
  ASSERT_EQ(one.id.size(), 2000u);  // 1000 L1 worth of mass as L0 particles
  ASSERT_EQ(one.id, two.id);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < one.position.size(); ++i) {
    if (!sameBits(one.position[i], two.position[i]) || !sameBits(one.velocity[i], two.velocity[i])) {
      if (differing++ < 5) {
        ADD_FAILURE() << "particle id " << one.id[i] << ": " << one.position[i].transpose() << " vs "
                      << two.position[i].transpose();
      }
    }
  }
  EXPECT_EQ(differing, 0u);
}

TEST(Simulation, ParticlesStayFiniteAndInsideBox) {
  const sph::Scene scene = smallScene();
  sph::Simulation sim(scene, sph::Level{0});
  const sph::Vec3 start = sim.particles().position[0];
  for (int s = 0; s < 60; ++s) sim.step();
  EXPECT_EQ(sim.stepCount(), 60);
  EXPECT_NEAR(sim.time(), 60 * scene.params.time_step, 1e-12);

  const sph::ParticleSet& p = sim.particles();
  const sph::BoxState box = sim.boxNow();
  bool moved = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_TRUE(p.position[i].allFinite() && p.velocity[i].allFinite()) << "particle id " << p.id[i];
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(p.position[i][a], box.min[a] + p.radius[i] - 1e-5f) << "id " << p.id[i] << " axis " << a;
      EXPECT_LE(p.position[i][a], box.max[a] - p.radius[i] + 1e-5f) << "id " << p.id[i] << " axis " << a;
    }
    if (p.id[i] == 0 && (p.position[i] - start).norm() > 1e-4f) moved = true;
  }
  EXPECT_TRUE(moved) << "the fluid did not move under gravity";
}

}  // namespace
