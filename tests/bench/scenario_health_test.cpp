// Scenario tier: 900 frames of every shipped scene with the regular method keep every particle in
// the box, produce no NaN and keep the mass.
#include <gtest/gtest.h>

#include "bench/bench_run.h"
#include "scene/scene_loader.h"

namespace {

class ScenarioHealth : public ::testing::TestWithParam<std::string> {};

TEST_P(ScenarioHealth, NineHundredFramesStayInTheBoxWithoutNaN) {
  const sph::Scene s = scene::loadScene(GetParam());
  bench::RunOptions options;
  options.frames = 900;
  options.threads = 2;
  std::size_t worst_outside = 0;
  std::size_t worst_nan = 0;
  options.on_frame = [&](const sph::Simulation&, const bench::FrameRecord& r) {
    worst_outside = std::max(worst_outside, r.outside_box);
    worst_nan = std::max(worst_nan, r.nan_values);
  };
  const bench::RunResult run = bench::runScene(s, "regular", options);
  ASSERT_EQ(run.records.size(), 900u);
  EXPECT_EQ(worst_outside, 0u);
  EXPECT_EQ(worst_nan, 0u);
  EXPECT_EQ(run.records.back().n_small, 20000u);
  EXPECT_DOUBLE_EQ(run.mass_start, run.mass_end);
}

INSTANTIATE_TEST_SUITE_P(AllScenes, ScenarioHealth,
                         ::testing::Values("dambreak", "dambreak_obstacles", "large_box", "small_box", "wave"));

}  // namespace
