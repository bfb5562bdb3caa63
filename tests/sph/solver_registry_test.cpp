// Adding a solver is a class deriving from sph::FluidSolver and one registerFluidSolver call
// (solvers/fluid_solver_factory.h): this test registers a solver of its own, an explicit free fall
// with the walls, without touching the library, and runs a Simulation on it by name.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sph/collision.h"
#include "sph/simulation.h"
#include "sph/solvers/fluid_solver_factory.h"
#include "support/box_scene.h"

namespace {

constexpr const char* kName = "test_free_fall";

// Gravity and semi-implicit Euler, no pressure: every particle falls as a stone until a wall stops it.
class FreeFallSolver : public sph::FluidSolver {
 public:
  explicit FreeFallSolver(const sph::Scene& /*scene*/) {}
  void advance(const sph::FrameContext& f) override {
    f.grid.build(f.particles);
    const sph::BoxState box = f.scene.boundary.stateAt(f.time + f.dt);
    const sph::Vec3 g(0.0f, static_cast<float>(f.scene.params.gravity), 0.0f);
    const auto dt = static_cast<float>(f.dt);
    sph::ParticleSet& p = f.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.velocity[i] += dt * g;
      p.position[i] += dt * p.velocity[i];
      sph::collideBoundary(f.scene.boundary, box, sph::WallReach(p.radius[i]), p.position[i], p.velocity[i]);
    }
  }
  // The first lattice point a whole spacing in from the water region's faces.
  double fillInset(double spacing, double /*radius*/) const override { return spacing; }
};

sph::Scene airborneWater() {
  sph::Scene scene =
      sph_test::boxScene("solver_registry_test", "thesis", {1.0, 1.0, 1.0}, {0.4, 0.5, 0.4}, {0.6, 0.7, 0.6}, 50);
  scene.params.solver = kName;
  return scene;
}

TEST(SolverRegistry, ASolverRegisteredByNameRunsASimulation) {
  sph::registerFluidSolver(kName, [](const sph::Scene& s) { return std::make_unique<FreeFallSolver>(s); });
  ASSERT_TRUE(sph::isFluidSolverName(kName));
  const sph::Scene scene = airborneWater();
  sph::Simulation sim(scene, sph::Level{0});
  ASSERT_EQ(sim.particles().size(), 100u);
  const double spacing = std::cbrt(scene.params.mass_small / scene.params.rest_density);
  float lowest = 1.0f;
  for (const sph::Vec3& x : sim.particles().position) lowest = std::min(lowest, x.y());
  EXPECT_NEAR(lowest, 0.5 + spacing, 1e-5) << "the solver's fill inset was not used";

  const double mass = sim.particles().totalMass();
  for (int s = 0; s < 10; ++s) sim.step();
  const auto expected = static_cast<float>(10 * scene.params.time_step * scene.params.gravity);
  for (const sph::Vec3& v : sim.particles().velocity) EXPECT_NEAR(v.y(), expected, 1e-4f);
  EXPECT_EQ(sim.particles().totalMass(), mass);
  EXPECT_EQ(sim.solver().splitPlacement(), sph::SplitPlacement::kHashedDirection);

  // Long enough to land: the walls it asked for hold every particle.
  for (int s = 0; s < 200; ++s) sim.step();
  for (const sph::Vec3& x : sim.particles().position) {
    EXPECT_GE(x.y(), 0.0f);
    EXPECT_LT(x.y(), 0.1f);
  }
}

TEST(SolverRegistry, AnUnknownSolverNameIsRefusedWithItsName) {
  sph::Scene scene = airborneWater();
  scene.params.solver = "no_such_solver";
  try {
    sph::Simulation sim(scene, sph::Level{0});
    FAIL() << "a simulation started on an unknown solver";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_solver"), std::string::npos) << e.what();
  }
}

TEST(SolverRegistry, TheBuiltInSolversAreRegistered) {
  for (const char* name : {"thesis", "pbf", "dfsph"}) EXPECT_TRUE(sph::isFluidSolverName(name)) << name;
}

}  // namespace
