// Density, eq. (3.11), in the middle of a block of particles on the rest lattice of spacing
// cbrt(m / rho0): close to rho0 for both size classes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sph/neighbor_grid.h"
#include "sph/params.h"
#include "sph/particles.h"
#include "sph/solvers/thesis/thesis_stages.h"

namespace {

// Relative deviation (rho - rho0) / rho0 of the centre particle of an n^3 lattice block.
double centreDensityDeviation(sph::Level c, int n) {
  const sph::SimParams params = sph::thesisPreset();
  const auto classes = params.levelProps();
  const sph::LevelProps props = classes[sph::levelIndex(c)];
  const double spacing = std::cbrt(props.mass / params.rest_density);

  sph::ParticleSet particles(static_cast<std::size_t>(n) * n * n);
  std::size_t centre = 0;
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        if (x == n / 2 && y == n / 2 && z == n / 2) centre = particles.size();
        particles.add(sph::Vec3(static_cast<float>(x * spacing), static_cast<float>(y * spacing),
                                static_cast<float>(z * spacing)),
                      sph::Vec3::Zero(), c, props);
      }
    }
  }

  const double max_support = std::max(classes[0].support, classes[1].support);
  sph::Aabb bounds;
  bounds.min = Eigen::Vector3d::Constant(-2.0 * max_support);
  bounds.max = Eigen::Vector3d::Constant((n - 1) * spacing + 2.0 * max_support);
  sph::NeighborGrid grid;
  grid.configure(bounds, static_cast<float>(max_support), particles.size());
  grid.build(particles);

  sph::computeDensityPressure(params, sph::makeKernelTable(params), grid, particles);
  const double rho = particles.density[centre];
  EXPECT_NEAR(particles.pressure[centre], params.gas_stiffness * (rho - params.rest_density),
              1e-3 * params.rest_density);
  return (rho - params.rest_density) / params.rest_density;
}

TEST(Density, SmallLatticeCentreNearRestDensity) {
  const double dev = centreDensityDeviation(sph::Level{0}, 13);
  EXPECT_LT(std::abs(dev), 0.05);
  EXPECT_NEAR(dev, 0.009, 0.01);  // about +0.9 %
}

TEST(Density, LargeLatticeCentreNearRestDensity) {
  const double dev = centreDensityDeviation(sph::Level{1}, 13);
  EXPECT_LT(std::abs(dev), 0.05);
  EXPECT_NEAR(dev, -0.037, 0.01);  // about -3.7 %
}

// An L0 and an L1 particle closer than both supports: each sees the other through the average
// of the two kernels, eq. (3.35), and itself through its own kernel.
TEST(Density, MixedPairUsesAveragedKernel) {
  const sph::SimParams params = sph::thesisPreset();
  const auto classes = params.levelProps();
  const sph::KernelTable kernels = sph::makeKernelTable(params);
  sph::ParticleSet particles(2);
  const float d = 0.5f * static_cast<float>(std::min(classes[0].support, classes[1].support));
  particles.add(sph::Vec3(0.1f, 0.1f, 0.1f), sph::Vec3::Zero(), sph::Level{0}, classes[0]);
  particles.add(sph::Vec3(0.1f + d, 0.1f, 0.1f), sph::Vec3::Zero(), sph::Level{1}, classes[1]);
  sph::Aabb bounds;
  bounds.max = Eigen::Vector3d::Constant(0.3);
  sph::NeighborGrid grid;
  grid.configure(bounds, static_cast<float>(std::max(classes[0].support, classes[1].support)), 2);
  grid.build(particles);
  ASSERT_EQ(grid.neighborCount(0), 1u);
  ASSERT_EQ(grid.neighborCount(1), 1u);
  sph::computeDensityPressure(params, kernels, grid, particles);

  const double r2 = (particles.position[0] - particles.position[1]).squaredNorm();
  const double w_pair =
      0.5 * (sph::poly6(kernels[0], static_cast<float>(r2)) + sph::poly6(kernels[1], static_cast<float>(r2)));
  for (int i = 0; i < 2; ++i) {
    const int j = 1 - i;
    const double expected = particles.mass[i] * sph::poly6(kernels[i], 0.0f) + particles.mass[j] * w_pair;
    EXPECT_NEAR(particles.density[i], expected, 1e-5 * expected) << "particle " << i;
  }
}

}  // namespace
