// The water's first fill (scene.h, fill_water.h): every start level holds the same mass, the
// rest of a coarse fill going to one particle each of some finer levels, water a coarse lattice
// cannot hold starts at the coarsest level whose lattice holds it, and a scene whose water would
// not fit the particle capacity once refined to L0 is refused with the key named.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sph/scene.h"
#include "sph/simulation.h"

namespace {

sph::Scene tank(int large_particles) {
  sph::Scene scene;
  scene.name = "tank";
  scene.source = "fill_water_test";
  EXPECT_TRUE(sph::presetByName("pbf", scene.params));
  scene.params.levels = sph::kMaxLevels;
  scene.boundary.box.min = Eigen::Vector3d::Zero();
  scene.boundary.box.max = Eigen::Vector3d(0.4, 0.6, 0.4);
  scene.water.min = Eigen::Vector3d::Zero();
  scene.water.max = Eigen::Vector3d(0.4, 0.6, 0.4);
  scene.large_particles = large_particles;
  return scene;
}

// The fill's mass in L0 particles' masses.
long long finestMasses(const std::array<int, sph::kMaxLevels>& fill) {
  long long m = 0;
  for (int k = 0; k < sph::kMaxLevels; ++k) m += static_cast<long long>(fill[static_cast<std::size_t>(k)]) << k;
  return m;
}

TEST(FillWater, EveryStartLevelHoldsTheSameMass) {
  for (const int large : {1000, 1001, 1003, 1234}) {
    const sph::Scene scene = tank(large);
    for (int k = 0; k < sph::kMaxLevels; ++k) {
      const auto fill = sph::initialFill(scene, sph::asLevel(k));
      EXPECT_EQ(finestMasses(fill), 2LL * large) << large << " L1 particles started at L" << k;
      for (int j = k + 1; j < sph::kMaxLevels; ++j) EXPECT_EQ(fill[static_cast<std::size_t>(j)], 0);
      for (int j = 0; j < k; ++j) EXPECT_LE(fill[static_cast<std::size_t>(j)], 1);
    }
  }
}

TEST(FillWater, ACoarseStartHasTheRegularRunsMassExactly) {
  const sph::Scene scene = tank(1003);  // 2006 L0 masses: 250 L3 and one L1 at L3
  const sph::Simulation regular(scene, sph::Level{0});
  const sph::Simulation coarse(scene, sph::asLevel(3));
  EXPECT_EQ(regular.particles().size(), 2006u);
  EXPECT_EQ(coarse.particles().countOf(sph::asLevel(3)), 250u);
  EXPECT_EQ(coarse.particles().countOf(sph::Level{1}), 1u);
  EXPECT_EQ(coarse.particles().totalMass(), regular.particles().totalMass());
}

// A 0.3 x 0.4 x 0.3 m region: its L3 lattice holds 324 sites, its L2 lattice 704.
sph::Scene narrowTank(int large_particles) {
  sph::Scene scene = tank(large_particles);
  scene.boundary.box.max = Eigen::Vector3d(0.3, 0.4, 0.3);
  scene.water.max = scene.boundary.box.max;
  return scene;
}

TEST(FillWater, WaterTheCoarseLatticeCannotHoldStartsAtTheCoarsestLevelThatHoldsIt) {
  const sph::Scene scene = narrowTank(1320);  // 330 L3 particles, 660 L2
  const sph::Simulation regular(scene, sph::Level{0});
  const sph::Simulation coarse(scene, sph::asLevel(3));
  EXPECT_EQ(coarse.particles().countOf(sph::asLevel(3)), 0u);
  EXPECT_EQ(coarse.particles().countOf(sph::asLevel(2)), 660u);
  EXPECT_EQ(coarse.particles().totalMass(), regular.particles().totalMass());
}

TEST(FillWater, WaterNoLatticeHoldsIsRefused) {
  const sph::Scene scene = narrowTank(1800);  // 3,600 L0 particles where the L0 lattice holds 3,042
  try {
    const sph::Simulation sim(scene, sph::asLevel(3));
    FAIL() << "no level's lattice holds the water";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("water region holds"), std::string::npos) << e.what();
  }
}

TEST(FillWater, WaterThatCannotRefineWithinTheCapacityIsRefused) {
  const sph::Scene scene = tank(1003);
  try {
    const sph::Simulation sim(scene, sph::asLevel(3), 1000);
    FAIL() << "2006 L0 particles do not fit a capacity of 1000";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'large_particles'"), std::string::npos) << e.what();
  }
}

}  // namespace
