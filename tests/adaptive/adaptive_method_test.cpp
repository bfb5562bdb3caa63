// The adaptive methods end to end through Simulation::step: mass by class after every step, where
// the gaze and surface methods refine, the hysteresis ring, the lost-gaze policy, and thread-count
// independence.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "adaptive_test_util.h"

namespace {

using adaptive_test::cameraOf;
using adaptive_test::expectMassByClass;
using adaptive_test::expectSameBits;
using adaptive_test::gazeAt;
using adaptive_test::makeRig;
using adaptive_test::poolScene;
using adaptive_test::Rig;
using adaptive_test::Snapshot;
using adaptive_test::snapshotOf;
using adaptive_test::surgeScene;

// Distance in viewport widths from the gaze to a particle's projected centre, and that disc's radius.
struct Seen {
  double distance;
  double radius;
};
Seen seenFrom(const sph::Projector& proj, const sph::ParticleSet& p, std::size_t i, double gx, double gy) {
  const sph::ScreenDisc d = proj.project(p.position[i].cast<double>(), p.radius[i]);
  const double dx = d.x - gx;
  const double dy = (d.y - gy) / proj.aspect();
  return {std::sqrt(dx * dx + dy * dy), d.radius};
}

// A dam-break in miniature: the water fills half the box and surges, so particles move a lot.
TEST(AdaptiveMethods, MassIsExactByClassAfterEveryStep) {
  for (sph::Method method : {sph::Method::Surface, sph::Method::Gaze, sph::Method::Hybrid}) {
    SCOPED_TRACE(sph::methodName(method));
    Rig rig = makeRig(surgeScene(), method);
    const double initial = rig.sim->particles().totalMass();
    int class_changes = 0;
    for (int s = 0; s < 60; ++s) {
      // Sweep the gaze across the screen so both split and merge happen.
      rig.controller->setGaze(gazeAt(0.2 + 0.01 * s, 0.5));
      rig.sim->step();
      expectMassByClass(*rig.sim, initial);
      class_changes += rig.controller->lastStats().splits + rig.controller->lastStats().merges;
      for (const sph::Vec3& x : rig.sim->particles().position) ASSERT_TRUE(x.allFinite());
    }
    EXPECT_GT(class_changes, 0);
  }
}

TEST(AdaptiveMethods, GazeSplitsOnlyInsideTheCircleAndTheRestMergesLater) {
  const sph::Scene scene = poolScene(0.6, 0.6, 2000);
  sph::AdaptiveConfig config;
  config.gaze_radius = 0.06;
  config.gaze_ring_radius = 0.06;  // no ring: the thesis's rule (3.48)
  Rig rig = makeRig(scene, sph::Method::Gaze, config);
  const sph::Projector proj(cameraOf(scene));
  // Gaze on the water's front-left corner.
  const sph::ScreenDisc corner = proj.project(Eigen::Vector3d(0.05, 0.05, 0.55), 0.0);
  rig.controller->setGaze(gazeAt(corner.x, corner.y));
  rig.sim->step();
  const sph::ParticleSet& p = rig.sim->particles();
  ASSERT_GT(rig.controller->lastStats().splits, 0);
  ASSERT_LT(p.countOf(sph::Level{0}), p.size() / 2);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Seen s = seenFrom(proj, p, i, corner.x, corner.y);
    if (p.level[i] == sph::Level{1}) {
      // Unsplit particles did not overlap the circle when the decision was made (f >= 0, 3.47).
      EXPECT_GE(s.distance, config.gaze_radius + s.radius - 1e-9) << "L1 particle " << i;
    } else {
      // Children sit within half a parent radius of a parent that overlapped the circle.
      EXPECT_LT(s.distance, config.gaze_radius + 3.0 * s.radius) << "L0 particle " << i;
    }
  }
  // The gaze moves to the opposite corner: the first region merges back over the next steps.
  const sph::ScreenDisc other = proj.project(Eigen::Vector3d(0.55, 0.05, 0.05), 0.0);
  const auto smallNearFirstCorner = [&] {
    std::size_t count = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      count += p.level[i] == sph::Level{0} && seenFrom(proj, p, i, corner.x, corner.y).distance < config.gaze_radius;
    }
    return count;
  };
  const std::size_t small_before = smallNearFirstCorner();
  ASSERT_GT(small_before, 10u);
  rig.controller->setGaze(gazeAt(other.x, other.y));
  for (int s = 0; s < 30; ++s) rig.sim->step();
  EXPECT_LE(smallNearFirstCorner(), small_before / 10) << "before " << small_before;
  EXPECT_GT(rig.controller->lastStats().gaze_mode == sph::GazeMode::Tracking, 0);
}

TEST(AdaptiveMethods, SurfaceSplitsTheSurfaceAndKeepsTheDeepInteriorLarge) {
  // A pool deep enough to have an interior: 0.5 x 0.5 footprint, about 0.33 m of water.
  const sph::Scene scene = poolScene(0.5, 0.5, 5000);
  sph::AdaptiveConfig config;
  Rig rig = makeRig(scene, sph::Method::Surface, config);
  for (int s = 0; s < 5; ++s) rig.sim->step();
  const sph::ParticleSet& p = rig.sim->particles();
  float top = 0.0f;
  for (const sph::Vec3& x : p.position) top = std::max(top, x.y());
  std::size_t top_layer = 0, top_layer_small = 0, interior = 0, interior_large = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const sph::Vec3& x = p.position[i];
    if (x.y() > top - 0.02f) {
      ++top_layer;
      top_layer_small += p.level[i] == sph::Level{0};
    }
    const bool far_from_walls = x.x() > 0.17f && x.x() < 0.33f && x.z() > 0.17f && x.z() < 0.33f;
    if (far_from_walls && x.y() > 0.12f && x.y() < top - 0.12f) {
      ++interior;
      interior_large += p.level[i] == sph::Level{1};
    }
  }
  ASSERT_GT(top_layer, 50u);
  ASSERT_GT(interior, 10u);
  EXPECT_GT(top_layer_small, top_layer * 9 / 10) << top_layer_small << " of " << top_layer;
  EXPECT_EQ(interior_large, interior);
}

TEST(AdaptiveMethods, HybridKeepsDeepParticlesUnderTheGazeLarge) {
  const sph::Scene scene = poolScene(0.5, 0.5, 5000);
  const sph::Projector proj(cameraOf(scene));
  const sph::ScreenDisc centre = proj.project(Eigen::Vector3d(0.25, 0.15, 0.25), 0.0);
  sph::AdaptiveConfig config;
  config.gaze_radius = 0.2;
  config.gaze_ring_radius = 0.2;
  Rig gaze = makeRig(scene, sph::Method::Gaze, config);
  Rig hybrid = makeRig(scene, sph::Method::Hybrid, config);
  for (Rig* rig : {&gaze, &hybrid}) {
    rig->controller->setGaze(gazeAt(centre.x, centre.y));
    for (int s = 0; s < 3; ++s) rig->sim->step();
  }
  const auto deepSmall = [&](const sph::ParticleSet& p) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const sph::Vec3& x = p.position[i];
      const bool deep =
          x.x() > 0.17f && x.x() < 0.33f && x.z() > 0.17f && x.z() < 0.33f && x.y() > 0.1f && x.y() < 0.18f;
      count += deep && p.level[i] == sph::Level{0};
    }
    return count;
  };
  EXPECT_GT(deepSmall(gaze.sim->particles()), 20u) << "the gaze method splits under the gaze";
  EXPECT_EQ(deepSmall(hybrid.sim->particles()), 0u) << "hybrid keeps the deep ones L1";
  EXPECT_GT(hybrid.sim->particles().countOf(sph::Level{0}), 0u);
}

// Class changes per step while the gaze jitters in place, with or without the ring.
double churnUnderJitter(double ring_radius) {
  const sph::Scene scene = poolScene(0.6, 0.6, 2000);
  sph::AdaptiveConfig config;
  config.gaze_radius = 0.08;
  config.gaze_ring_radius = ring_radius;
  Rig rig = makeRig(scene, sph::Method::Gaze, config);
  const sph::Projector proj(cameraOf(scene));
  const sph::ScreenDisc centre = proj.project(Eigen::Vector3d(0.3, 0.05, 0.3), 0.0);
  const auto jittered = [&](int s) {
    // Deterministic jitter of +-0.012 of the width, a typical fixation tremor plus tracker noise.
    return gazeAt(centre.x + 0.012 * std::sin(1.7 * s), centre.y + 0.012 * std::cos(2.3 * s));
  };
  for (int s = 0; s < 15; ++s) {
    rig.controller->setGaze(jittered(s));
    rig.sim->step();
  }
  int changes = 0;
  constexpr int kSteps = 30;
  for (int s = 15; s < 15 + kSteps; ++s) {
    rig.controller->setGaze(jittered(s));
    rig.sim->step();
    changes += rig.controller->lastStats().splits + rig.controller->lastStats().merges;
  }
  return static_cast<double>(changes) / kSteps;
}

TEST(AdaptiveMethods, HysteresisRingStopsSplitMergeOscillation) {
  const double without_ring = churnUnderJitter(0.08);
  const double with_ring = churnUnderJitter(0.11);
  // Without the ring the jitter changes the class of many particles every step; with it only a
  // few remain (the settling fluid crossing the ring's edges).
  EXPECT_GT(without_ring, 50.0) << "the jitter should churn particles without a ring";
  EXPECT_LT(with_ring, 0.05 * without_ring) << "with " << with_ring << " without " << without_ring;
  EXPECT_LT(with_ring, 10.0);
}

TEST(AdaptiveMethods, LostGazeIsHeldThenFallsBackToSurface) {
  const sph::Scene scene = poolScene(0.5, 0.5, 1500);
  sph::AdaptiveConfig config;
  config.gaze_stale_s = 0.1;
  config.gaze_hold_s = 0.5;
  Rig rig = makeRig(scene, sph::Method::Gaze, config);
  rig.sim->step();
  EXPECT_EQ(rig.controller->lastStats().gaze_mode, sph::GazeMode::Fallback) << "no gaze yet";
  sph::GazeInput g = gazeAt(0.5, 0.5);
  rig.controller->setGaze(g);
  rig.sim->step();
  EXPECT_EQ(rig.controller->lastStats().gaze_mode, sph::GazeMode::Tracking);
  EXPECT_FALSE(rig.sim->surfaceDistanceTracking()) << "a tracked gaze needs no surface field";
  g.age_s = 0.3;
  rig.controller->setGaze(g);
  rig.sim->step();
  EXPECT_EQ(rig.controller->lastStats().gaze_mode, sph::GazeMode::Holding);
  EXPECT_EQ(rig.controller->lastStats().gaze_x, 0.5);
  EXPECT_TRUE(rig.sim->surfaceDistanceTracking()) << "the hold warms the field for the fallback";
  g.age_s = 0.8;
  rig.controller->setGaze(g);
  rig.sim->step();
  EXPECT_EQ(rig.controller->lastStats().gaze_mode, sph::GazeMode::Fallback);
  EXPECT_TRUE(rig.sim->surfaceDistanceTracking());
  // Falling back means surface refinement: the surface layer is split.
  EXPECT_GT(rig.sim->particles().countOf(sph::Level{0}), 100u);
}

TEST(AdaptiveMethods, BadSettingsAreRejected) {
  const sph::Scene scene = poolScene(0.5, 0.5, 500);
  sph::AdaptiveConfig config;
  config.gaze_ring_radius = 0.01;  // smaller than the circle
  EXPECT_THROW(sph::AdaptiveController(sph::Method::Gaze, 4, config, cameraOf(scene)), std::invalid_argument);
  config = {};
  config.alpha = std::nan("");
  EXPECT_THROW(sph::AdaptiveController(sph::Method::Surface, 4, config, cameraOf(scene)), std::invalid_argument);
  EXPECT_THROW(sph::AdaptiveController(sph::Method::Regular, 4, {}, cameraOf(scene)), std::invalid_argument);
  EXPECT_EQ(sph::makeAdaptiveController(sph::Method::Regular, 4, {}, cameraOf(scene)), nullptr);
  EXPECT_THROW(sph::AdaptiveController(sph::Method::Foveated, sph::kMaxLevels + 1, {}, cameraOf(scene)),
               std::invalid_argument);
  EXPECT_THROW(sph::AdaptiveController(sph::Method::Foveated, 1, {}, cameraOf(scene)), std::invalid_argument);
  sph::Method m;
  EXPECT_FALSE(sph::methodByName("eye", m));
  ASSERT_TRUE(sph::methodByName("hybrid", m));
  EXPECT_EQ(m, sph::Method::Hybrid);
}

Snapshot runWithThreads(sph::Method method, int threads, const char* preset = "thesis") {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  sph::Scene scene = surgeScene();
  EXPECT_TRUE(sph::presetByName(preset, scene.params));
  Rig rig = makeRig(scene, method);
  for (int s = 0; s < 40; ++s) {
    rig.controller->setGaze(gazeAt(0.3 + 0.005 * s, 0.55));
    rig.sim->step();
  }
  omp_set_num_threads(previous);
  return snapshotOf(rig.sim->particles());
}

void expectThreadIndependent(const char* preset) {
  for (sph::Method method : {sph::Method::Surface, sph::Method::Gaze, sph::Method::Hybrid}) {
    SCOPED_TRACE(sph::methodName(method));
    expectSameBits(runWithThreads(method, 1, preset), runWithThreads(method, 2, preset));
  }
}

TEST(AdaptiveMethods, ResultIndependentOfThreadCount) { expectThreadIndependent("thesis"); }

// The incompressible solvers with split and merge: their placement iterations
// (local_placement.h) included.
TEST(AdaptiveMethods, PbfResultIndependentOfThreadCount) { expectThreadIndependent("pbf"); }
TEST(AdaptiveMethods, DfsphResultIndependentOfThreadCount) { expectThreadIndependent("dfsph"); }

}  // namespace
