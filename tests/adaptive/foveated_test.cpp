// The foveated method (adaptive/foveated.h): more than two levels, sized by the eye's acuity, on
// the incompressible solvers: mass exact by level through many level changes, the same result for
// any thread count, levels that hold still under a still gaze, a rule or a merge request for
// every particle finer than the coarsest level, neighbours within the grading step, the finest
// level under the gaze on a spread sheet, a new fovea at its levels within three frames of a
// saccade, and a surface distance settled before the first decision.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <vector>

#include <Eigen/Geometry>

#include "adaptive_test_util.h"
#include "sph/adaptive/foveated.h"

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

// The foveated method's rig on a preset's surge.
Rig foveatedRig(const sph::Scene& scene) { return makeRig(scene, sph::Method::Foveated, scene.adaptive); }

sph::Scene surgeScene(const char* preset) {
  sph::Scene scene = adaptive_test::surgeScene();
  EXPECT_TRUE(sph::presetByName(preset, scene.params));
  return scene;
}

// A gaze that jumps across the screen every few frames, as saccades do.
sph::GazeInput wanderingGaze(int frame) {
  static const double kPoints[][2] = {{0.35, 0.55}, {0.6, 0.6}, {0.45, 0.45}, {0.7, 0.5}, {0.4, 0.65}};
  const auto& at = kPoints[(frame / 6) % 5];
  return gazeAt(at[0], at[1]);
}

// Particles (by id: the arrays are re-sorted) whose level differs from before, or that are new.
struct Levels {
  std::map<std::uint32_t, sph::Level> by_id;
};
Levels levelsOf(const sph::ParticleSet& p) {
  Levels l;
  for (std::size_t i = 0; i < p.size(); ++i) l.by_id[p.id[i]] = p.level[i];
  return l;
}
int levelChanges(const Levels& before, const sph::ParticleSet& p) {
  int changes = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto it = before.by_id.find(p.id[i]);
    changes += it == before.by_id.end() || it->second != p.level[i];
  }
  return changes;
}

void expectHealthy(const sph::Simulation& sim) {
  const sph::ParticleSet& p = sim.particles();
  const sph::BoxState box = sim.boxNow();
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_TRUE(p.position[i].allFinite() && p.velocity[i].allFinite()) << "particle " << i;
    ASSERT_TRUE((p.position[i].array() >= box.min.array() - 1e-4f).all() &&
                (p.position[i].array() <= box.max.array() + 1e-4f).all())
        << "particle " << i << " left the box";
  }
}

void expectExactAndHealthy(const char* preset) {
  Rig rig = foveatedRig(surgeScene(preset));
  const double initial = rig.sim->particles().totalMass();
  int changes = 0;
  int levels_seen = 0;
  for (int s = 0; s < 90; ++s) {
    const Levels before = levelsOf(rig.sim->particles());
    rig.controller->setGaze(wanderingGaze(s));
    rig.sim->step();
    changes += levelChanges(before, rig.sim->particles());
    expectMassByClass(*rig.sim, initial);
    expectHealthy(*rig.sim);
    int present = 0;
    for (int k = 0; k < sph::kMaxLevels; ++k) present += rig.sim->particles().countOf(sph::asLevel(k)) > 0;
    levels_seen = std::max(levels_seen, present);
  }
  EXPECT_GT(changes, 300) << "the wandering gaze should change many particles' levels";
  EXPECT_GE(levels_seen, 3) << "at least three levels at once";
}

TEST(Foveated, MassIsExactByLevelAndWaterStaysHealthyPbf) { expectExactAndHealthy("pbf"); }
TEST(Foveated, MassIsExactByLevelAndWaterStaysHealthyDfsph) { expectExactAndHealthy("dfsph"); }

Snapshot runWithThreads(const char* preset, int threads) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  sph::Scene scene = surgeScene(preset);
  scene.adaptive.foveated_merge_hold_s = 0.05;  // the merges' wait counted too
  Rig rig = foveatedRig(scene);
  for (int s = 0; s < 50; ++s) {
    rig.controller->setGaze(wanderingGaze(s));
    rig.sim->step();
  }
  omp_set_num_threads(previous);
  return snapshotOf(rig.sim->particles());
}

void expectThreadIndependent(const char* preset) {
  expectSameBits(runWithThreads(preset, 1), runWithThreads(preset, 2));
}

TEST(Foveated, ResultIndependentOfThreadCountPbf) { expectThreadIndependent("pbf"); }
TEST(Foveated, ResultIndependentOfThreadCountDfsph) { expectThreadIndependent("dfsph"); }

// A pbf tank of water at rest, 0.4 x 0.4 m, for the gaze to look at.
sph::Scene restingTank() {
  sph::Scene scene = poolScene(0.4, 0.4, 2000);
  EXPECT_TRUE(sph::presetByName("pbf", scene.params));
  scene.boundary.box.max.y() = 0.6;
  return scene;
}

double rmsSpeed(const sph::ParticleSet& p) {
  double v2 = 0.0;
  for (const sph::Vec3& v : p.velocity) v2 += v.squaredNorm();
  return std::sqrt(v2 / static_cast<double>(p.size()));
}

// Mean |rho / rho0 - 1| below the free surface (a surface particle's support lies partly in air).
double interiorDensityError(const sph::ParticleSet& p, double rho0) {
  double error = 0.0;
  int interior = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.surface_distance[i] > 0.0f) {
      error += std::abs(p.density[i] / rho0 - 1.0);
      ++interior;
    }
  }
  EXPECT_GT(interior, 0);
  return interior > 0 ? error / interior : 0.0;
}

// The field the first foveated step reads where nothing has tracked it: each particle's
// distance to the free surface along its neighbours, no shorter than the straight line to the
// nearest surface particle and longer by less than a neighbour's reach; the hops as the solver's
// pass leaves them.
TEST(Foveated, ASettledSurfaceDistanceIsThePathToTheSurface) {
  const sph::Scene scene = restingTank();
  Rig rig = makeRig(scene, sph::Method::Regular);  // no adaptive step: nothing tracks the field
  rig.sim->step();
  sph::FoveatedScratch scratch;
  const int sweeps = sph::settleSurfaceDistance(*rig.sim, scene.adaptive, scratch);
  const sph::ParticleSet& p = rig.sim->particles();
  std::vector<std::size_t> surface;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.surface_distance[i] == 0.0f) surface.push_back(i);
  }
  ASSERT_FALSE(surface.empty());
  ASSERT_LT(surface.size(), p.size() / 2) << "most of a tank lies under its surface";
  const float reach = p.support[0];
  float deepest = 0.0f;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const float d = p.surface_distance[i];
    ASSERT_TRUE(std::isfinite(d)) << "particle " << i;
    if (d == 0.0f) continue;
    float straight = std::numeric_limits<float>::infinity();
    for (const std::size_t s : surface) straight = std::min(straight, (p.position[i] - p.position[s]).norm());
    EXPECT_GE(d, straight * (1.0f - 1e-5f)) << "particle " << i;
    EXPECT_LE(d, straight + reach) << "particle " << i;
    EXPECT_FLOAT_EQ(p.surface_hop[i], d) << "particle " << i;
    deepest = std::max(deepest, d);
  }
  std::printf("settled in %d sweeps: %zu surface particles of %zu, the deepest %.3f m under\n", sweeps, surface.size(),
              p.size(), deepest);
  EXPECT_GT(sweeps, 2);
}

// A resting tank under a still gaze: once its levels have settled around the fovea they stay
// (no particle flickers between two levels) and the tank settles with its density. (Flickering
// levels drive it at about 0.1 m/s.) Counted over the last 300 frames: a change stirs the water
// near it, which may carry another particle across a level's edge, and such a burst as the water
// settles can reach 34 changes in 100 frames; one flickering particle changes every frame or two,
// 150-300 times in 300 frames.
TEST(Foveated, ARestingTankUnderAStillGazeKeepsItsLevelsAndSettles) {
  const sph::Scene scene = restingTank();
  Rig rig = foveatedRig(scene);
  int changes = 0;
  double rms_sum = 0.0;
  constexpr int kFrames = 700;
  constexpr int kLast = 300;
  for (int s = 0; s < kFrames; ++s) {
    const Levels before = levelsOf(rig.sim->particles());
    rig.controller->setGaze(gazeAt(0.5, 0.55));
    rig.sim->step();
    if (s < kFrames - kLast) continue;
    changes += levelChanges(before, rig.sim->particles());
    rms_sum += rmsSpeed(rig.sim->particles());
  }
  const sph::ParticleSet& p = rig.sim->particles();
  int levels_present = 0;
  for (int k = 0; k < sph::kMaxLevels; ++k) levels_present += p.countOf(sph::asLevel(k)) > 0;
  const double rms = rms_sum / kLast;
  const double density_error = interiorDensityError(p, scene.params.rest_density);
  std::printf(
      "still gaze: %d levels, %d level changes and a mean rms speed of %.4f m/s in the last %d frames, "
      "mean |rho/rho0 - 1| %.4f\n",
      levels_present, changes, rms, kLast, density_error);
  EXPECT_GE(levels_present, 3);
  // An occasional change as the water settles; a flickering particle changes every frame or two.
  EXPECT_LE(changes, 90) << "levels flicker under a still gaze";
  EXPECT_LT(rms, 0.05);
  EXPECT_LE(density_error, 0.01);
}

// A resting tank under a gaze that sweeps across it and back, a pass a second, once its levels
// have settled under a still gaze. With merges held longer than the gaze takes to come back
// (foveated_merge_hold_s) the swept water keeps the levels the first passes gave it, and those
// changes, in still water, are taken up slowly (pbf/still_water_changes.h): the tank comes back
// to rest, as calm as the same tank under a still gaze. Without the hold the water behind the
// gaze merges and in front of it splits on every pass, and keeps moving.
struct SweepResult {
  int changes = 0;
  double rms = 0.0;            // mean over the last frames
  double density_error = 0.0;  // mean |rho / rho0 - 1| below the surface, at the end
};
// The gaze sweeps across `width` of the display (0: it stays at the centre).
SweepResult sweepTheTank(double merge_hold_s, double width = 0.4) {
  const sph::Scene scene = restingTank();
  Rig rig = foveatedRig(scene);
  constexpr int kSettle = 1200, kSweep = 1500, kLast = 300, kPass = 100;
  for (int s = 0; s < kSettle; ++s) {
    rig.controller->setGaze(gazeAt(0.5, 0.55));
    rig.sim->step();
  }
  sph::AdaptiveConfig held = rig.controller->config();
  held.foveated_merge_hold_s = merge_hold_s;
  rig.controller->setConfig(held);
  SweepResult result;
  for (int s = 0; s < kSweep; ++s) {
    const double phase = std::fmod(s / static_cast<double>(kPass) + 0.5, 2.0);  // from the middle
    const Levels before = levelsOf(rig.sim->particles());
    rig.controller->setGaze(gazeAt(0.5 + width * ((phase < 1.0 ? phase : 2.0 - phase) - 0.5), 0.55));
    rig.sim->step();
    if (s < kSweep - kLast) continue;
    result.changes += levelChanges(before, rig.sim->particles());
    result.rms += rmsSpeed(rig.sim->particles()) / kLast;
  }
  result.density_error = interiorDensityError(rig.sim->particles(), scene.params.rest_density);
  std::printf(
      "gaze sweeping %.1f of the display, merge hold %.0f s: %d level changes, mean rms speed %.4f m/s in the last %d "
      "frames, mean |rho/rho0 - 1| %.4f\n",
      width, merge_hold_s, result.changes, result.rms, kLast, result.density_error);
  return result;
}

TEST(Foveated, ATankUnderASweepingGazeWithAMergeHoldStaysAtRest) {
  // How calm the tank gets at all: under a still gaze, over the same frames, it keeps 3-4 mm/s rms
  // with the hold and 4-11 mm/s without (the odd change as it settles stirs it); float rounding
  // alone (the SIMD forms) moves such a mean by up to 2.8 times.
  const SweepResult unswept = sweepTheTank(5.0, 0.0);
  const SweepResult held = sweepTheTank(5.0);
  EXPECT_LT(held.rms, 2.0 * unswept.rms);
  EXPECT_LE(held.density_error, 0.01);
  const SweepResult at_once = sweepTheTank(0.0);
  EXPECT_LT(held.changes * 4, at_once.changes);
  EXPECT_LT(held.rms * 2.0, at_once.rms);
}

// Water spread on the floor thinner than a coarse particle is wide: the shallow rule keeps it at
// L1 and finer, so it keeps its volume (a layer of coarse particles reads a low density and
// swells the water's sum m / rho, by 38 % without the rule; the water starts at the coarsest
// level). A film a particle thick reads a few per cent light as its particles lie: settled from
// its splits gently (pbf/still_water_changes.h), 2.4 %; shaken into place, 1-4 %.
TEST(Foveated, ShallowWaterOnTheFloorKeepsItsVolume) {
  sph::Scene scene = poolScene(0.5, 0.5, 360);  // about 1.1 L1 layers
  ASSERT_TRUE(sph::presetByName("pbf", scene.params));
  scene.boundary.box.max.y() = 0.3;
  Rig rig = foveatedRig(scene);
  for (int s = 0; s < 400; ++s) {
    rig.controller->setGaze(gazeAt(0.05, 0.05));  // the far corner of the display: the eye allows coarse water
    rig.sim->step();
  }
  const sph::ParticleSet& p = rig.sim->particles();
  int coarser_than_large = 0;
  double volume = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    coarser_than_large += sph::levelIndex(p.level[i]) > 1;
    volume += p.mass[i] / p.density[i];
  }
  const double swell = volume / (p.totalMass() / scene.params.rest_density) - 1.0;
  std::printf("shallow water: %d of %zu particles coarser than L1, sum m / rho %+.2f %%\n", coarser_than_large,
              p.size(), 100.0 * swell);
  EXPECT_EQ(coarser_than_large, 0);
  EXPECT_LT(std::abs(swell), 0.03);
}

// A block dropped into a wide box spreads into a sheet thinner than the support, which has no
// particle the free-surface test finds (its faces' colour-field gradients cancel), so its
// surface distance reads it as deep as it is wide; the hidden rule must not take it for water
// under the surface: the particle under the gaze on the sheet is L0.
TEST(Foveated, TheGazeOnASpreadSheetFindsTheFinestLevel) {
  sph::Scene scene = poolScene(1.0, 1.0, 1350);
  ASSERT_TRUE(sph::presetByName("pbf", scene.params));
  scene.boundary.box.max.y() = 0.6;
  scene.water.min = Eigen::Vector3d(0.345, 0.1, 0.345);  // 0.31 m a side: a sheet about 2.7 cm deep
  scene.water.max = Eigen::Vector3d(0.655, 0.41, 0.655);
  Rig rig = foveatedRig(scene);
  int on_water = 0, finest = 0;
  for (int s = 0; s < 400; ++s) {
    // Elsewhere while the block falls and spreads, then on the sheet's middle, which has been
    // coarse meanwhile.
    rig.controller->setGaze(s < 300 ? gazeAt(0.15, 0.85) : gazeAt(0.5, 0.5));
    rig.sim->step();
    const int level = rig.controller->lastStats().fovea_level;
    if (s < 303 || level < 0) continue;  // three frames for the new fovea
    ++on_water;
    finest += level == 0;
  }
  std::printf("spread sheet: the gaze on water in %d of 97 frames, at L0 in %d\n", on_water, finest);
  ASSERT_GT(on_water, 87);
  EXPECT_GE(finest, on_water * 9 / 10);
}

// The real-time governor's periphery gain coarsens the water around the gaze, not the particle the
// gaze falls on: at g = 16 that particle stays as fine as g = 1 allows it (L1 or finer in this
// view, where the eye allows a particle a degree off the gaze L3 at that gain).
TEST(Foveated, ThePeripheryGainSparesTheGazePoint) {
  sph::Scene scene = surgeScene("pbf");
  scene.adaptive.foveated_periphery_gain = 16.0;
  Rig rig = foveatedRig(scene);
  int on_water = 0;
  for (int s = 0; s < 60; ++s) {
    rig.controller->setGaze(s < 40 ? gazeAt(0.3, 0.6) : gazeAt(0.62, 0.55));
    rig.sim->step();
    const int level = rig.controller->lastStats().fovea_level;
    if (s < 42 || level < 0) continue;  // the saccade's first frames; the gaze off the water
    ++on_water;
    EXPECT_LE(level, 1) << "frame " << s << ": the gaze point coarsened with the periphery";
  }
  EXPECT_GT(on_water, 10) << "the gaze should fall on the water after the saccade";
}

// The eye measured on request (the server: once a published frame; the bench: outside its timed
// step) gives what measuring at the end of every step gives, and nothing until asked.
TEST(Foveated, TheEyeMeasuredOnRequestMatchesEveryStep) {
  const sph::Scene scene = surgeScene("pbf");
  Rig each = foveatedRig(scene);
  Rig asked = foveatedRig(scene);
  asked.controller->setMeasureEachStep(false);
  for (int s = 0; s < 30; ++s) {
    each.controller->setGaze(gazeAt(0.3, 0.6));
    asked.controller->setGaze(gazeAt(0.3, 0.6));
    each.sim->step();
    asked.sim->step();
    ASSERT_EQ(asked.controller->lastStats().visible, 0) << "frame " << s << ": measured unasked";
    asked.controller->measureEye(*asked.sim);
    const sph::AdaptiveStats& a = asked.controller->lastStats();
    const sph::AdaptiveStats& e = each.controller->lastStats();
    ASSERT_GT(e.visible, 0);
    EXPECT_EQ(a.visible, e.visible) << "frame " << s;
    EXPECT_EQ(a.over_budget, e.over_budget) << "frame " << s;
    EXPECT_EQ(a.fovea_level, e.fovea_level) << "frame " << s;
    EXPECT_EQ(a.fovea_width_arcmin, e.fovea_width_arcmin) << "frame " << s;
  }
}

// The decision accounts for every particle finer than the coarsest level: a rule keeps it (the
// eye, grading, thin water, a wait) or it asks to merge. On a surge under a still gaze the eye
// keeps the fovea fine and grading keeps rings around it.
TEST(Foveated, EveryFinerParticleIsKeptByARuleOrAsksToMerge) {
  const sph::Scene scene = surgeScene("pbf");
  Rig rig = foveatedRig(scene);
  const int coarsest = scene.params.levels - 1;
  int by_eye = 0, by_grading = 0, finer_seen = 0;
  for (int s = 0; s < 60; ++s) {
    rig.controller->setGaze(gazeAt(0.45, 0.55));
    const sph::ParticleSet& p = rig.sim->particles();
    int finer = 0;
    for (std::size_t i = 0; i < p.size(); ++i) finer += sph::levelIndex(p.level[i]) < coarsest;
    rig.sim->step();
    const sph::AdaptiveStats& st = rig.controller->lastStats();
    ASSERT_EQ(st.held.total() + st.merge_wanted, finer) << "frame " << s;
    by_eye += st.held.eye;
    by_grading += st.held.grading;
    finer_seen += finer;
  }
  std::printf("finer than the coarsest over 60 frames: %d, kept by the eye %d, by grading %d\n", finer_seen, by_eye,
              by_grading);
  EXPECT_GT(by_eye, 0);
  EXPECT_GT(by_grading, 0);
}

// Grading as the decision sees it: after each frame, the neighbour pairs whose levels differ by
// more than foveated_grading_step (a split the step just made, which its neighbours follow in
// the next) are few, and pairs that differ by the full step exist wherever the step is wider
// than one level.
struct LevelGaps {
  long pairs = 0;
  long at_step = 0;
  long past_step = 0;
};
LevelGaps levelGapsOverASurge(int step) {
  sph::Scene scene = surgeScene("pbf");
  scene.adaptive.foveated_grading_step = step;
  Rig rig = foveatedRig(scene);
  LevelGaps gaps;
  for (int s = 0; s < 60; ++s) {
    rig.controller->setGaze(gazeAt(0.45, 0.55));
    rig.sim->step();
    if (s < 20) continue;  // the levels form from the coarsest start
    rig.sim->rebuildNeighbors();
    const sph::ParticleSet& p = rig.sim->particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      for (const std::uint32_t j : rig.sim->grid().neighbors(i)) {
        const int gap = std::abs(sph::levelIndex(p.level[i]) - sph::levelIndex(p.level[j]));
        ++gaps.pairs;
        gaps.at_step += gap == step;
        gaps.past_step += gap > step;
      }
    }
  }
  std::printf("grading step %d: %ld neighbour pairs, %ld the step apart, %ld farther\n", step, gaps.pairs, gaps.at_step,
              gaps.past_step);
  return gaps;
}

TEST(Foveated, NeighboursDifferByAtMostTheGradingStep) {
  for (const int step : {1, 2}) {
    const LevelGaps gaps = levelGapsOverASurge(step);
    EXPECT_GT(gaps.at_step, 0) << "step " << step;
    EXPECT_LE(gaps.past_step, gaps.pairs / 1000) << "step " << step;
  }
}

// After a saccade across the water, every seen particle near the new gaze point is as fine as
// the eye resolves there (the finest level at the gaze point itself) within three frames.
TEST(Foveated, ANewFoveaIsAtItsLevelsWithinThreeFrames) {
  sph::Scene scene = surgeScene("pbf");
  Rig rig = foveatedRig(scene);
  for (int s = 0; s < 40; ++s) {
    rig.controller->setGaze(gazeAt(0.3, 0.6));
    rig.sim->step();
  }
  const double to_x = 0.62, to_y = 0.55;
  for (int s = 0; s < 3; ++s) {
    rig.controller->setGaze(gazeAt(to_x, to_y));
    rig.sim->step();
  }
  const sph::ParticleSet& p = rig.sim->particles();
  const sph::ScreenCamera camera = cameraOf(scene);
  const sph::Projector projector(camera);
  const auto levels = scene.params.levelProps();
  const Eigen::Vector4d depth_row = -camera.view.row(2).transpose();
  const double tan_half = std::tan(0.5 * scene.adaptive.foveated_display_fov_deg * M_PI / 180.0);
  const auto direction = [&](double sx, double sy) {
    return Eigen::Vector3d((2 * sx - 1) * tan_half, (1 - 2 * sy) * tan_half / projector.aspect(), 1);
  };
  const auto depthOf = [&](std::size_t i) {
    return depth_row.head<3>().dot(p.position[i].cast<double>()) + depth_row.w();
  };
  const auto eccentricity = [&](const sph::ScreenDisc& d) {
    const Eigen::Vector3d a = direction(to_x, to_y), b = direction(d.x, d.y);
    return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
  };
  // The water at the gaze point: the nearest particle within a degree of it.
  double fovea_depth = 1e30;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const sph::ScreenDisc d = projector.project(p.position[i].cast<double>(), p.radius[i]);
    if (d.in_front && eccentricity(d) < 1.0) fovea_depth = std::min(fovea_depth, depthOf(i));
  }
  ASSERT_LT(fovea_depth, 1e30) << "the gaze should fall on water";
  int near_gaze = 0, too_coarse = 0, finest_needed = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const sph::ScreenDisc d = projector.project(p.position[i].cast<double>(), p.radius[i]);
    if (!d.in_front || p.surface_distance[i] > 0.05f) continue;  // seen: at or near the surface
    const double e = eccentricity(d);
    if (e > 2.0) continue;
    // The coarsest level the eye allows there (adaptive/foveated.h), with slack for the water's
    // motion in the step after the decision (the method decides where the particle was) and the
    // method's single precision: a level is a factor 1.26 apart.
    const double allowed = sph::acuityRatio(scene.adaptive, e) * depthOf(i) / fovea_depth;
    int level = 0;
    while (level + 1 < sph::kMaxLevels && levels[level + 1].radius / levels[0].radius <= allowed / 0.95) ++level;
    ++near_gaze;
    finest_needed += level == 0;
    too_coarse += sph::levelIndex(p.level[i]) > level;
  }
  std::printf("new fovea: %d seen particles within 2 degrees (%d need the finest level), %d too coarse\n", near_gaze,
              finest_needed, too_coarse);
  ASSERT_GT(near_gaze, 0) << "the new fovea should hold particles";
  EXPECT_EQ(too_coarse, 0);
}

}  // namespace

// A camera inside the water (a headset, a client's pose just over the floor): the water behind the
// eye is not seen and stays at the coarsest level, its top layers (not hidden by water above) as
// well; only grading next to the water in front may hold it finer, within a couple of coarse
// supports of the eye.
TEST(Foveated, WaterBehindTheEyeStaysCoarsest) {
  sph::Scene scene = poolScene(0.4, 1.0, 5000);  // 0.25 m deep
  ASSERT_TRUE(sph::presetByName("pbf", scene.params));
  scene.boundary.box.max.y() = 0.6;
  Rig rig = foveatedRig(scene);
  sph::ScreenCamera camera = cameraOf(scene);
  const Eigen::Vector3d eye(0.2, 0.12, 0.3);
  camera.view = sph::lookAt(eye, Eigen::Vector3d(0.2, 0.12, 0.4), Eigen::Vector3d::UnitY());
  rig.controller->setCamera(camera);
  for (int s = 0; s < 30; ++s) {
    rig.controller->setGaze(gazeAt(0.5, 0.5));
    rig.sim->step();
  }
  const sph::ParticleSet& p = rig.sim->particles();
  const int coarsest = scene.params.levels - 1;
  const double reach = 2.0 * scene.params.levelProps()[static_cast<std::size_t>(coarsest)].support;
  int behind = 0, finer_behind = 0, finest_behind = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double along = p.position[i].z() - eye.z();  // the view direction is +z
    const int level = sph::levelIndex(p.level[i]);
    if (along >= 0.0) continue;
    finest_behind += level == 0;
    if (along > -reach) continue;
    ++behind;
    finer_behind += level < coarsest;
  }
  ASSERT_GT(behind, 100) << "the pose should leave water behind the eye";
  EXPECT_GE(rig.controller->lastStats().fovea_level, 0) << "the gaze should fall on the water in front";
  EXPECT_EQ(finest_behind, 0) << "no L0 particle behind the eye";
  EXPECT_EQ(finer_behind, 0) << "of " << behind << " particles behind the eye, finer than L" << coarsest;
}

// Any level count from 2 to 8: the water starts at the coarsest and reaches L0 at the gaze point,
// mass exact by level.
TEST(Foveated, SixLevelsStartCoarsestAndRefineAtTheGaze) {
  sph::Scene scene = restingTank();
  scene.params.levels = 6;
  Rig rig = foveatedRig(scene);
  const sph::ParticleSet& p = rig.sim->particles();
  const double initial = p.totalMass();
  EXPECT_GT(p.countOf(sph::asLevel(5)), 0u);
  // The gaze on the middle of the water's surface.
  const sph::Projector projector(cameraOf(scene));
  const sph::FastScreenDisc centre = projector.projectFast(sph::Vec3(0.2f, 0.24f, 0.2f), 0.0f);
  for (int s = 0; s < 20; ++s) {
    rig.controller->setGaze(gazeAt(centre.x, centre.y));
    rig.sim->step();
    expectMassByClass(*rig.sim, initial);
  }
  EXPECT_GT(rig.sim->particles().countOf(sph::Level{0}), 0u);
  EXPECT_EQ(rig.sim->particles().countOf(sph::asLevel(6)), 0u);
}
