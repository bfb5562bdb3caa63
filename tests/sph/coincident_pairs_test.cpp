// Particles on one point push each other apart (coincident_pairs.h): equal and opposite, the same
// in the scalar and the vector stages, and a pile clamped into a box corner comes apart.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "sph/simulation.h"
#include "sph/solvers/thesis/coincident_pairs.h"
#include "support/box_scene.h"

namespace {

TEST(CoincidentPairs, DirectionIsAntisymmetricUnitAndPairSpecific) {
  const sph::Vec3 ab = sph::coincidentPairDirection(3, 8);
  EXPECT_NEAR(ab.norm(), 1.0f, 1e-6f);
  EXPECT_TRUE(ab.isApprox(-sph::coincidentPairDirection(8, 3)));
  EXPECT_FALSE(ab.isApprox(sph::coincidentPairDirection(3, 9)));
}

// Twelve particles of each class on one point (dense enough for a positive pressure), one beside.
struct Stack {
  sph::SimParams params = sph::thesisPreset();
  sph::ParticleSet particles{64};
  sph::NeighborGrid grid;
};

void makeStack(Stack& s) {
  const auto classes = s.params.levelProps();
  const sph::Vec3 centre(0.1f, 0.1f, 0.1f);
  for (int k = 0; k < 24; ++k) {
    const sph::Level c = k < 12 ? sph::Level{0} : sph::Level{1};
    s.particles.add(centre, sph::Vec3::Zero(), c, classes[sph::levelIndex(c)]);
  }
  s.particles.add(centre + sph::Vec3(0.01f, 0.0f, 0.0f), sph::Vec3::Zero(), sph::Level{0}, classes[0]);
  sph::Aabb bounds;
  bounds.min = Eigen::Vector3d::Zero();
  bounds.max = Eigen::Vector3d::Constant(0.2);
  s.grid.configure(bounds, static_cast<float>(std::max(classes[0].support, classes[1].support)), s.particles.size());
  s.grid.build(s.particles);
}

TEST(CoincidentPairs, PressurePushesThemApartAndConservesMomentum) {
  for (bool vector : {false, true}) {
    Stack s;
    makeStack(s);
    s.params.gravity = 0.0;
    s.params.surface_tension_enabled = false;
    const sph::KernelTable kernels = sph::makeKernelTable(s.params);
    if (vector) {
      sph::computeDensityPressure(s.params, kernels, s.grid, s.particles);
      sph::computeAccelerations(s.params, kernels, s.grid, s.particles);
    } else {
      sph::scalar::computeDensityPressure(s.params, kernels, s.grid, s.particles);
      sph::scalar::computeAccelerations(s.params, kernels, s.grid, s.particles);
    }
    const sph::ParticleSet& p = s.particles;
    ASSERT_GT(p.pressure[0], 0.0f) << "a pile is compressed";
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    double magnitude = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Eigen::Vector3d f = static_cast<double>(p.mass[i]) * p.acceleration[i].cast<double>();
      total += f;
      magnitude += f.norm();
    }
    EXPECT_LT(total.norm(), 1e-4 * magnitude) << (vector ? "vector" : "scalar");
    // The stacked particles no longer move as one.
    for (std::size_t i = 1; i < 24; ++i) {
      EXPECT_GT((p.acceleration[i] - p.acceleration[0]).norm(), 1.0f)
          << "particle " << i << (vector ? " vector" : " scalar");
    }
  }
}

TEST(CoincidentPairs, PileInABoxCornerComesApart) {
  const sph::Scene scene = sph_test::boxScene("coincident_pairs_test", "thesis", Eigen::Vector3d::Constant(0.5),
                                              {0.2, 0.0, 0.2}, {0.4, 0.1, 0.4}, 140);
  sph::Simulation sim(scene, sph::Level{1});
  sph::ParticleSet& p = sim.particles();
  const float r = p.radius[0];
  // 20 particles on the point the box clamps an L1 particle in the (min, min, min) corner to.
  for (std::size_t k = 0; k < 20; ++k) {
    p.position[k] = sph::Vec3::Constant(r);
    p.velocity[k] = sph::Vec3::Zero();
  }
  for (int step = 0; step < 100; ++step) sim.step();

  std::map<std::tuple<float, float, float>, int> at;
  int most = 0;
  for (const sph::Vec3& x : p.position) most = std::max(most, ++at[{x.x(), x.y(), x.z()}]);
  EXPECT_EQ(most, 1) << "particles still share a point after 100 steps";
}

}  // namespace
