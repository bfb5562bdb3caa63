// The small box under the foveated method: its camera is close (an L0 particle looks 35-40' wide),
// so a coarser particle can cover the gaze point with its centre a quarter of a degree off, where
// the eye's MAR alone would allow the next level. The particle the gaze falls on is judged at the
// gaze point: under the scene's recorded gaze, which moves on the water, it is L0 in nearly every
// frame the gaze falls on water, read by the perceptual budget's own measure
// (adaptive/perceptual_budget.h), not by the rule's.
#include <gtest/gtest.h>

#include <cstdio>

#include "bench/bench_run.h"
#include "gaze/gaze_recording.h"
#include "scene/scene_loader.h"

namespace {

TEST(SmallBoxFovea, TheWaterUnderAMovingGazeIsAtTheFinestLevel) {
  const sph::Scene scene = scene::loadScene("small_box", scene::defaultSceneDir(), "pbf");
  const gaze::GazeRecording gaze = gaze::readGazeRecording(scene.gaze_recording);
  bench::RunOptions options;
  options.frames = 200;
  options.gaze = &gaze;
  int on_water = 0, finest = 0;
  options.on_frame = [&](const sph::Simulation&, const bench::FrameRecord& r) {
    on_water += r.fovea_level >= 0;
    finest += r.fovea_level == 0;
  };
  bench::runScene(scene, "foveated", options);
  std::printf("small box: the gaze on water in %d of 200 frames, at L0 in %d\n", on_water, finest);
  ASSERT_GT(on_water, 150) << "the recorded gaze should fall on the water";
  EXPECT_GE(finest, on_water * 9 / 10);
}

}  // namespace
