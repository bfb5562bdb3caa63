// Pressure and viscosity forces act in equal and opposite pairs (eqs. (3.13), (3.14) with the
// averaged kernels of (3.35)), so without gravity and surface tension the total momentum change
// sum_i m_i a_i vanishes.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "sph/neighbor_grid.h"
#include "sph/params.h"
#include "sph/particles.h"
#include "sph/solvers/thesis/thesis_stages.h"

namespace {

struct Cloud {
  sph::SimParams params;
  sph::ParticleSet particles{400};
  sph::NeighborGrid grid;
};

// ~400 particles of both classes scattered in a 0.2 m cube with small random velocities.
void makeCloud(Cloud& cloud) {
  cloud.params = sph::thesisPreset();
  cloud.params.surface_tension_enabled = false;
  cloud.params.gravity = 0.0;
  const auto classes = cloud.params.levelProps();
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> pos(0.0f, 0.2f);
  std::uniform_real_distribution<float> vel(-0.05f, 0.05f);
  std::bernoulli_distribution large(0.5);
  for (int i = 0; i < 400; ++i) {
    const sph::Level c = large(rng) ? sph::Level{1} : sph::Level{0};
    const sph::Vec3 x(pos(rng), pos(rng), pos(rng));
    const sph::Vec3 u(vel(rng), vel(rng), vel(rng));
    cloud.particles.add(x, u, c, classes[sph::levelIndex(c)]);
  }
  const double max_support = std::max(classes[0].support, classes[1].support);
  sph::Aabb bounds;
  bounds.min = Eigen::Vector3d::Zero();
  bounds.max = Eigen::Vector3d::Constant(0.2);
  cloud.grid.configure(bounds, static_cast<float>(max_support), cloud.particles.size());
  cloud.grid.build(cloud.particles);
}

TEST(Momentum, InternalForcesSumToZero) {
  Cloud cloud;
  makeCloud(cloud);
  ASSERT_GT(cloud.particles.countOf(sph::Level{0}), 100u);
  ASSERT_GT(cloud.particles.countOf(sph::Level{1}), 100u);
  ASSERT_GT(cloud.grid.meanNeighbors(), 2.0);  // the forces are not trivially zero

  const sph::KernelTable kernels = sph::makeKernelTable(cloud.params);
  sph::computeDensityPressure(cloud.params, kernels, cloud.grid, cloud.particles);
  sph::computeAccelerations(cloud.params, kernels, cloud.grid, cloud.particles);

  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  double magnitude = 0.0;
  const auto& p = cloud.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector3d f = static_cast<double>(p.mass[i]) * p.acceleration[i].cast<double>();
    ASSERT_TRUE(f.allFinite()) << "particle " << i;
    total += f;
    magnitude += f.norm();
  }
  ASSERT_GT(magnitude, 0.0);
  EXPECT_LT(total.norm() / magnitude, 1e-4) << "total " << total.transpose() << ", sum |f| " << magnitude;
}

}  // namespace
