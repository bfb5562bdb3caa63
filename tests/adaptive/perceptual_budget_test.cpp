// The perceptual budget (adaptive/perceptual_budget.h): what the eye gets, measured from the
// particles and the camera alone, apart from the foveated rule.
#include "sph/adaptive/perceptual_budget.h"

#include <cmath>

#include <gtest/gtest.h>

#include "sph/camera.h"
#include "sph/params.h"

namespace {

// A camera at the origin looking down -z, 60 degrees wide (the display the same: fov 0 takes the
// camera's own).
struct Rig {
  sph::SimParams params = sph::pbfPreset();
  sph::AdaptiveConfig config;
  sph::ScreenCamera camera;
  sph::ParticleSet particles{64};
  Rig() {
    camera.view = sph::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0});
    const double aspect = 16.0 / 9.0;
    const double fov_y = 2.0 * std::atan(std::tan(30.0 * M_PI / 180.0) / aspect) * 180.0 / M_PI;
    camera.projection = sph::perspective(fov_y, aspect, 0.05, 50.0);
    config.foveated_display_fov_deg = 0.0;
  }
  void add(const sph::Vec3& x, int level) {
    const auto props = params.levelProps();
    particles.add(x, sph::Vec3::Zero(), sph::asLevel(level), props[static_cast<std::size_t>(level)]);
  }
  sph::PerceptualBudget measure(double gx = 0.5, double gy = 0.5) {
    return meter.measure(particles, params, camera, gx, gy, config);
  }
  sph::PerceptualBudgetMeter meter;
};

TEST(PerceptualBudget, AParticleBehindAnotherIsNotSeen) {
  Rig rig;
  rig.add({0, 0, -2}, 1);
  rig.add({0, 0, -2.5}, 1);  // straight behind the first, hidden by it
  const sph::PerceptualBudget b = rig.measure();
  EXPECT_EQ(b.visible, 1);
  EXPECT_EQ(b.gaze_level, 1);
}

// A far particle narrower than a depth-grid cell covers the gaze point but no cell's centre, and a
// nearer one beside it owns the cell of its centre: the grid samples nothing of it, yet it is what
// the eye sees at the gaze point.
TEST(PerceptualBudget, AParticleNarrowerThanACellUnderTheGazeIsSeen) {
  Rig rig;
  rig.add({0, 0, -20}, 1);  // on the line of sight, 0.05 degrees in radius: a cell is 0.23 wide
  rig.add({2.0f * std::tan(0.45f * static_cast<float>(M_PI) / 180.0f), 0, -2}, 0);  // 0.45 degrees off
  const sph::PerceptualBudget b = rig.measure();
  EXPECT_EQ(b.gaze_level, 1);
  EXPECT_EQ(b.visible, 2);
}

TEST(PerceptualBudget, TheGazeParticleIsMeasuredInArcminutes) {
  Rig rig;
  rig.add({0, 0, -2}, 0);
  const sph::PerceptualBudget b = rig.measure();
  const double radius = rig.params.levelProps()[0].radius;
  const double expected = 2.0 * std::atan(radius / 2.0) * 180.0 / M_PI * 60.0;
  EXPECT_NEAR(b.gaze_width_arcmin, expected, 0.02 * expected);
  EXPECT_NEAR(b.gaze_mar_arcmin, 60.0 * rig.config.foveated_mar_w0_deg, 1e-3);
  EXPECT_EQ(b.over_budget, 0) << "the finest level is never over budget";
}

TEST(PerceptualBudget, ACoarseParticleIsOverBudgetAtTheGazeButNotInThePeriphery) {
  Rig rig;
  rig.add({0, 0, -2}, 0);      // under the gaze: the reference
  rig.add({0.25, 0, -2}, 3);   // about 7 degrees off: 4 levels coarser is twice as wide (8x the mass)
  rig.add({0.9, 0.0, -2}, 3);  // about 24 degrees off
  rig.config.foveated_quality = 1.0;
  // MAR(e) / MAR(0) = 1 + m e / w0: about 8 at 7 degrees with these figures, so both are within.
  EXPECT_EQ(rig.measure().over_budget, 0);
  // A steep fall of acuity no longer: MAR flat, so twice as wide as the reference is over.
  rig.config.foveated_mar_slope = 0.0;
  const sph::PerceptualBudget b = rig.measure();
  EXPECT_EQ(b.visible, 3);
  EXPECT_EQ(b.over_budget, 2);
  rig.config.foveated_quality = 2.5;  // allows 2.5 finest widths everywhere
  EXPECT_EQ(rig.measure().over_budget, 0);
}

TEST(PerceptualBudget, WaterOffTheDisplayOrBehindTheEyeIsNotCounted) {
  Rig rig;
  rig.add({0, 0, 2}, 3);    // behind the eye
  rig.add({30, 0, -2}, 3);  // far off to the side
  const sph::PerceptualBudget b = rig.measure();
  EXPECT_EQ(b.visible, 0);
  EXPECT_EQ(b.gaze_level, -1);
  EXPECT_EQ(b.gaze_width_arcmin, 0.0);
}

TEST(PerceptualBudget, AGazeOffTheWaterTakesTheNearestWaterAsItsReference) {
  Rig rig;
  rig.add({0.3, 0, -2}, 0);
  rig.add({0.32, 0.05, -2}, 1);
  rig.config.foveated_mar_slope = 0.0;
  const sph::PerceptualBudget b = rig.measure(0.1, 0.5);  // the gaze on empty display
  EXPECT_EQ(b.gaze_level, -1);
  EXPECT_EQ(b.visible, 2);
  EXPECT_EQ(b.over_budget, 1) << "the L1 particle is wider than the L0 reference at q 1";
}

}  // namespace
