// The basin (ten times the dam break's water) under the foveated method: after a saccade across
// its water the particle under the new gaze point is at the finest level within three frames, as
// on the dam break (Foveated.ANewFoveaIsAtItsLevelsWithinThreeFrames), read by the perceptual
// budget's own measure (adaptive/perceptual_budget.h), not by the rule's.
#include <gtest/gtest.h>

#include <cstdio>

#include "bench/bench_run.h"
#include "scene/scene_loader.h"

namespace {

// A fixation at `from` until `jump_s`, then one at `to`.
gaze::GazeRecording saccade(double jump_s, double from_x, double from_y, double to_x, double to_y) {
  gaze::GazeRecording r;
  r.samples.push_back({0.0, from_x, from_y, true});
  r.samples.push_back({jump_s, to_x, to_y, true});
  r.samples.push_back({jump_s + 100.0, to_x, to_y, true});
  return r;
}

TEST(BasinFovea, ANewFoveaIsAtTheFinestLevelWithinThreeFrames) {
  const sph::Scene scene = scene::loadScene("basin");
  constexpr double kJump = 0.4;  // s: the collapse under way, the water still on the column's side
  const int jump_frame = static_cast<int>(kJump / scene.params.time_step + 0.5);
  // From the column's top near its front edge to the lower middle of its face towards the camera
  // (about 5 degrees apart on the display).
  const gaze::GazeRecording gaze = saccade(kJump, 0.21, 0.47, 0.33, 0.58);
  bench::RunOptions options;
  options.frames = jump_frame + 3;
  options.gaze = &gaze;
  std::vector<int> fovea_level;
  options.on_frame = [&](const sph::Simulation&, const bench::FrameRecord& r) { fovea_level.push_back(r.fovea_level); };
  bench::runScene(scene, "foveated", options);
  ASSERT_EQ(fovea_level.size(), static_cast<std::size_t>(jump_frame + 3));
  std::printf("fovea level in the frame before the jump %d, in the three frames after: %d %d %d\n",
              fovea_level[jump_frame - 1], fovea_level[jump_frame], fovea_level[jump_frame + 1],
              fovea_level[jump_frame + 2]);
  // The first fixation is at the column's top edge, where the gaze may fall just between or past
  // the particles in a frame (-1: no visible disc covers it): over its last five frames it falls on
  // water, and that water is L0.
  int on_water = 0;
  for (int f = jump_frame - 5; f < jump_frame; ++f) {
    EXPECT_LE(fovea_level[f], 0) << "frame " << f << ": the first fixation's water should be at L0";
    on_water += fovea_level[f] == 0;
  }
  EXPECT_GT(on_water, 0) << "the first fixation should fall on water";
  EXPECT_EQ(fovea_level.back(), 0) << "the new fovea should be at L0 three frames after the saccade";
}

}  // namespace
