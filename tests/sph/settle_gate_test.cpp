// Fresh incompressible water settles inside a gate (sph::gatedScene): a dam-break column is still
// a column when the simulation starts, for pbf and dfsph, instead of having collapsed while it
// relaxed. The thesis preset does not settle at all (its start is the thesis's).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sph/fill_water.h"
#include "sph/simulation.h"
#include "support/box_scene.h"

namespace {

sph::Scene column(const std::string& preset) {
  return sph_test::boxScene("settle_gate_test", preset, {0.8, 0.5, 0.2}, {0.0, 0.0, 0.0}, {0.2, 0.5, 0.2}, 300);
}

float maxX(const sph::ParticleSet& p) {
  float x = 0.0f;
  for (const auto& position : p.position) x = std::max(x, position.x());
  return x;
}

TEST(SettleGate, GatedSceneIsTheWaterRegionInsideTheBox) {
  sph::Scene s = column("pbf");
  s.water.max = Eigen::Vector3d(0.2, 0.9, 0.3);  // taller and deeper than the box
  const sph::Scene gated = sph::gatedScene(s);
  EXPECT_LT((gated.boundary.box.max - Eigen::Vector3d(0.2, 0.5, 0.2)).norm(), 1e-6);
  EXPECT_LT(gated.boundary.box.min.norm(), 1e-6);
}

TEST(SettleGate, ADamBreakColumnStandsUntilItIsReleased) {
  for (const char* preset : {"pbf", "dfsph"}) {
    const sph::Scene scene = column(preset);
    sph::Simulation sim(scene, sph::Level{0});
    EXPECT_LE(maxX(sim.particles()), 0.2f) << preset << ": the column spread while it settled";
    sim.step();
    EXPECT_GT(maxX(sim.particles()), 0.0f);
  }
}

// The thesis's water starts on its lattice, unmoved, with the density and pressure it has there
// (what a frame of the start shows).
TEST(SettleGate, TheThesisStartsOnItsLatticeWithItsDensityKnown) {
  const sph::Scene scene = column("thesis");
  sph::Simulation sim(scene, sph::Level{0});
  sph::ParticleSet fresh;
  sph::fillWater(scene, sph::Level{0}, sim.solver(), fresh);
  ASSERT_EQ(fresh.size(), sim.particles().size());
  double sum = 0.0;
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    EXPECT_EQ(sim.particles().position[i], fresh.position[i]);
    EXPECT_GT(sim.particles().density[i], 0.0f);  // a particle counts itself (3.11)
    EXPECT_TRUE(std::isfinite(sim.particles().pressure[i]));
    sum += sim.particles().density[i];
  }
  // The thesis's walls do not count in the density: the corners read less than rho0, the inside more.
  EXPECT_GT(sum / static_cast<double>(fresh.size()), 0.5 * scene.params.rest_density);
}

}  // namespace
