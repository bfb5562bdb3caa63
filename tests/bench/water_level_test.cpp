// The water's level as the bench's gauges read it (bench/water_level.h): a lattice at rest density
// reads its own depth, squeezed water reads lower, and the depth the water's mass fills at rho0
// accounts for the obstacles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <vector>

#include "bench/water_level.h"
#include "sph/params.h"

namespace {

// A box `cells` spacings square and 1 m high, with `layers` layers of `level` particles on
// a cubic lattice at rest density (the spacing cbrt(m / rho0)), squeezed vertically by `squeeze`.
struct Pool {
  sph::Scene scene;  // the pbf preset's parameters, the box as its boundary
  sph::BoxState box;
  sph::ParticleSet particles{40000};
  double spacing = 0.0;
  double rest_density = 0.0;

  bench::WaterLevel level() const { return bench::measureWaterLevel(particles, scene, box); }
};

Pool latticePool(sph::Level level, int cells, int layers, double squeeze = 1.0) {
  Pool pool;
  sph::SimParams& params = pool.scene.params;
  EXPECT_TRUE(sph::presetByName("pbf", params));
  pool.rest_density = params.rest_density;
  const sph::LevelProps props = params.levelProps()[sph::levelIndex(level)];
  pool.spacing = std::cbrt(props.mass / params.rest_density);
  const double side = cells * pool.spacing;
  pool.scene.boundary.box.max = Eigen::Vector3d(side, 1.0, side);
  pool.box = pool.scene.boundary.stateAt(0.0);
  for (int y = 0; y < layers; ++y) {
    for (int z = 0; z < cells; ++z) {
      for (int x = 0; x < cells; ++x) {
        const sph::Vec3 at(static_cast<float>((x + 0.5) * pool.spacing),
                           static_cast<float>((y + 0.5) * pool.spacing * squeeze),
                           static_cast<float>((z + 0.5) * pool.spacing));
        pool.particles.add(at, sph::Vec3::Zero(), level, props);
      }
    }
  }
  return pool;
}

TEST(WaterLevel, ALatticeAtRestDensityReadsItsOwnDepth) {
  for (const sph::Level c : {sph::Level{0}, sph::Level{1}}) {
    const Pool pool = latticePool(c, 24, 10);
    const bench::WaterLevel level = pool.level();
    const double depth = 10 * pool.spacing;
    std::printf("class %d: level %.5f m, lattice %.5f m, incompressible %.5f m, %d of %d gauges wet\n",
                static_cast<int>(c), level.depth, depth, level.incompressible_depth, level.wet, level.gauges);
    EXPECT_NEAR(level.incompressible_depth, depth, 1e-6 * depth);
    EXPECT_GT(level.gauges, 16);
    EXPECT_EQ(level.wet, level.gauges);
    EXPECT_NEAR(level.depth / depth, 1.0, 0.002);
  }
}

// Water whose particles stand off their lattice (each by up to 0.3 spacings on each axis, as
// moving water does) still reads its depth: the gauge finds where the water ends, not a layer.
TEST(WaterLevel, DisorderedWaterReadsItsDepth) {
  Pool pool = latticePool(sph::Level{0}, 24, 10);
  std::uint32_t state = 12345;
  auto offset = [&] {  // in [-0.3, 0.3) spacings, a linear congruential sequence
    state = state * 1664525u + 1013904223u;
    return static_cast<float>((static_cast<double>(state >> 8) / (1 << 24) - 0.5) * 0.6 * pool.spacing);
  };
  for (sph::Vec3& x : pool.particles.position) x += sph::Vec3(offset(), offset(), offset());
  const bench::WaterLevel level = pool.level();
  EXPECT_NEAR(level.depth / level.incompressible_depth, 1.0, 0.005);
}

// A sheet thinner than a support reads its depth: the floor's share of the kernel counts, as the
// solvers count it (boundary_volume.h), so the sheet's top reads like the top of deep water.
TEST(WaterLevel, ASheetOneOrTwoLayersDeepReadsItsDepth) {
  for (const int layers : {1, 2}) {
    const Pool pool = latticePool(sph::Level{0}, 24, layers);
    const bench::WaterLevel level = pool.level();
    std::printf("%d layers: level %.5f m against %.5f m\n", layers, level.depth, level.incompressible_depth);
    EXPECT_EQ(level.wet, level.gauges);
    EXPECT_NEAR(level.depth / level.incompressible_depth, 1.0, 0.005);
  }
}

// Water piled against one wall (a wave running into it) reads its volume: the gauges reach the
// walls, the wall's share of their kernel divided out.
TEST(WaterLevel, WaterPiledAgainstAWallReadsItsVolume) {
  Pool pool = latticePool(sph::Level{0}, 24, 12);
  std::vector<std::uint8_t> keep(pool.particles.size());
  for (std::size_t i = 0; i < keep.size(); ++i) {  // 12 layers at the wall down to 6 from the 7th column on
    const sph::Vec3& x = pool.particles.position[i];
    const long column = std::lround(x.x() / pool.spacing - 0.5);
    const long layer = std::lround(x.y() / pool.spacing - 0.5);
    keep[i] = layer < 6 + std::max(0L, 6 - column);
  }
  pool.particles.compact(keep);
  const bench::WaterLevel level = pool.level();
  std::printf("piled: level %.5f m against %.5f m\n", level.depth, level.incompressible_depth);
  EXPECT_NEAR(level.depth / level.incompressible_depth, 1.0, 0.005);
}

// Water round a floor-to-roof cylinder and round a sphere that stands out of it (the dam break's
// obstacles) reads its depth: the gauges beside them divide out the obstacle's share of their
// kernel, and the depth the mass fills leaves the obstacles' volume out.
TEST(WaterLevel, WaterRoundObstaclesReadsItsDepth) {
  for (const bool sphere : {false, true}) {
    Pool pool = latticePool(sph::Level{0}, 36, 10);
    const double centre = pool.box.max.x() / 2.0;
    const Eigen::Vector3d at(centre, 0.0, centre);
    const double radius = (sphere ? 14.0 : 5.0) * pool.spacing;
    if (sphere) {
      pool.scene.boundary.spheres.push_back({at, radius});
    } else {
      pool.scene.boundary.cylinders.push_back({centre, centre, radius});
    }
    std::vector<std::uint8_t> keep(pool.particles.size());
    for (std::size_t i = 0; i < keep.size(); ++i) {  // the lattice's cells whose centre the obstacle leaves free
      const sph::Vec3& x = pool.particles.position[i];
      const double y = sphere ? x.y() : 0.0;
      keep[i] = std::hypot(x.x() - centre, y, x.z() - centre) > radius;
    }
    pool.particles.compact(keep);
    const bench::WaterLevel level = pool.level();
    std::printf("%s: level %.5f m against %.5f m (lattice %.5f m), %d gauges\n", sphere ? "sphere" : "cylinder",
                level.depth, level.incompressible_depth, 10 * pool.spacing, level.gauges);
    EXPECT_NEAR(level.depth / (10 * pool.spacing), 1.0, 0.005);
    EXPECT_NEAR(level.incompressible_depth / (10 * pool.spacing), 1.0, 0.005);
  }
}

// Water squeezed 2 % reads 2 % lower, where its sum m / rho0 fills the same depth as before.
TEST(WaterLevel, SqueezedWaterReadsLower) {
  const Pool pool = latticePool(sph::Level{0}, 24, 10, 0.98);
  const bench::WaterLevel level = pool.level();
  EXPECT_NEAR(level.depth / level.incompressible_depth, 0.98, 0.004);
}

// L1 layers under L0 ones (the surface method's water at rest): the gauges read the depth
// both fill together. The L0 layers' horizontal spacing is the box's side over a whole count,
// their vertical one keeps them at rest density.
TEST(WaterLevel, LayersOfBothClassesReadTheirJointDepth) {
  Pool pool = latticePool(sph::Level{1}, 20, 4);
  sph::SimParams params;
  ASSERT_TRUE(sph::presetByName("pbf", params));
  const sph::LevelProps small = params.levelProps()[sph::levelIndex(sph::Level{0})];
  const double side = pool.box.max.x();
  const int cells = static_cast<int>(std::lround(side / std::cbrt(small.mass / params.rest_density)));
  const double across = side / cells;
  const double up = small.mass / (params.rest_density * across * across);
  const double floor_of_small = 4 * pool.spacing;
  for (int y = 0; y < 6; ++y) {
    for (int z = 0; z < cells; ++z) {
      for (int x = 0; x < cells; ++x) {
        const sph::Vec3 at(static_cast<float>((x + 0.5) * across), static_cast<float>(floor_of_small + (y + 0.5) * up),
                           static_cast<float>((z + 0.5) * across));
        pool.particles.add(at, sph::Vec3::Zero(), sph::Level{0}, small);
      }
    }
  }
  const bench::WaterLevel level = pool.level();
  EXPECT_NEAR(level.incompressible_depth, floor_of_small + 6 * up, 1e-5);
  EXPECT_NEAR(level.depth / level.incompressible_depth, 1.0, 0.005);
}

// Water over half the floor: the gauges over the other half are dry.
TEST(WaterLevel, GaugesOverDryFloorReadNothing) {
  Pool pool = latticePool(sph::Level{0}, 24, 6);
  const float half = pool.box.max.x() / 2.0f;
  std::vector<std::uint8_t> keep(pool.particles.size());
  for (std::size_t i = 0; i < keep.size(); ++i) keep[i] = pool.particles.position[i].x() < half;
  pool.particles.compact(keep);
  const bench::WaterLevel level = pool.level();
  EXPECT_GT(level.wet, level.gauges * 2 / 5);
  EXPECT_LE(level.wet, level.gauges * 3 / 5);
  EXPECT_LT(level.depth, 0.6 * 6 * pool.spacing);
}

// The depth a volume fills: a 1 x 1 m floor with a floor-to-roof cylinder of radius 0.1 and a
// sphere of radius 0.2 centred on the floor, so below 0.2 m a depth d holds
// d - pi 0.01 d - pi (0.04 d - d^3 / 3).
TEST(WaterLevel, IncompressibleDepthLeavesOutTheObstacles) {
  sph::Boundary boundary;
  boundary.box.max = Eigen::Vector3d(1.0, 1.0, 1.0);
  boundary.cylinders.push_back({0.3, 0.3, 0.1});
  boundary.spheres.push_back({Eigen::Vector3d(0.7, 0.0, 0.7), 0.2});
  const sph::BoxState box = boundary.stateAt(0.0);
  const double d = 0.1;
  const double held = d - std::numbers::pi * 0.01 * d - std::numbers::pi * (0.04 * d - d * d * d / 3.0);
  EXPECT_NEAR(bench::incompressibleDepth(held, boundary, box), d, 1e-9);
  sph::Boundary bare;
  bare.box = boundary.box;
  EXPECT_NEAR(bench::incompressibleDepth(0.5, bare, box), 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(bench::incompressibleDepth(2.0, boundary, box), 1.0);  // more than the box holds
  // Obstacles beyond the box (the dam break's, before its box opens) take nothing from it.
  sph::Boundary beyond = bare;
  beyond.cylinders.push_back({1.3, 0.5, 0.1});
  beyond.spheres.push_back({Eigen::Vector3d(0.5, 0.0, 1.4), 0.2});
  EXPECT_NEAR(bench::incompressibleDepth(0.5, beyond, box), 0.5, 1e-9);
}

// No gauge stands on an obstacle.
TEST(WaterLevel, GaugesStayClearOfObstacles) {
  Pool pool = latticePool(sph::Level{0}, 24, 4);
  const int open = pool.level().gauges;
  const double centre = pool.box.max.x() / 2.0;
  pool.scene.boundary.cylinders.push_back({centre, centre, 0.05});
  const int around = pool.level().gauges;
  EXPECT_LT(around, open);
  EXPECT_GT(around, 0);
}
}  // namespace
