// Scenario tier: 900 frames of every shipped scene with every method of the thesis keep every
// particle in the box, produce no NaN and keep the mass exactly (by level, every frame): with each
// scene's own preset (the thesis's), and for 300 frames (3 s: the collapse, the splash and the
// first slosh) with the server's default, pbf, whose step costs far more than the thesis's, with
// the foveated method too (its coarser levels need an incompressible solver), and the basin
// under the foveated method.
#include <gtest/gtest.h>

#include "bench/bench_run.h"
#include "scene/scene_loader.h"

namespace {

void expectHealthyRun(const std::string& scene_name, const std::string& method, const std::string& preset, int frames) {
  const sph::Scene s = scene::loadScene(scene_name, scene::defaultSceneDir(), preset);
  gaze::GazeRecording recording;
  bench::RunOptions options;
  options.frames = frames;
  options.threads = 2;
  if (bench::methodNeedsGaze(method)) {
    recording = gaze::readGazeRecording(s.gaze_recording);
    options.gaze = &recording;
  }
  const auto levels = s.params.levelProps();
  const auto massOf = [&](int level) { return static_cast<double>(static_cast<float>(levels[level].mass)); };
  std::size_t worst_outside = 0;
  std::size_t worst_nan = 0;
  std::size_t mass_mismatches = 0;
  options.on_frame = [&](const sph::Simulation& sim, const bench::FrameRecord& r) {
    worst_outside = std::max(worst_outside, r.outside_box);
    worst_nan = std::max(worst_nan, r.nan_values);
    double by_level = 0.0;
    for (int k = 0; k < sph::kMaxLevels; ++k)
      by_level += massOf(k) * static_cast<double>(r.by_level[static_cast<std::size_t>(k)]);
    mass_mismatches += sim.particles().totalMass() != by_level;
  };
  const bench::RunResult run = bench::runScene(s, method, options);
  ASSERT_EQ(run.records.size(), static_cast<std::size_t>(frames));
  EXPECT_EQ(worst_outside, 0u);
  EXPECT_EQ(worst_nan, 0u);
  EXPECT_EQ(mass_mismatches, 0u);
  EXPECT_EQ(run.mass_start, run.mass_end);
  if (method == "regular") {
    EXPECT_EQ(run.records.back().by_level[0], 20000u);
  }
}

using SceneAndMethod = std::tuple<std::string, std::string>;
class ScenarioHealth : public ::testing::TestWithParam<SceneAndMethod> {};
class ScenarioHealthPbf : public ::testing::TestWithParam<SceneAndMethod> {};

TEST_P(ScenarioHealth, NineHundredFramesStayInTheBoxWithoutNaN) {
  expectHealthyRun(std::get<0>(GetParam()), std::get<1>(GetParam()), "", 900);
}

TEST_P(ScenarioHealthPbf, ThreeHundredFramesStayInTheBoxWithoutNaN) {
  expectHealthyRun(std::get<0>(GetParam()), std::get<1>(GetParam()), "pbf", 300);
}

const auto kAllScenesThesisMethods =
    ::testing::Combine(::testing::Values("dambreak", "dambreak_obstacles", "large_box", "small_box", "wave"),
                       ::testing::Values("regular", "surface", "gaze", "hybrid"));
const auto kAllScenesAllMethods =
    ::testing::Combine(::testing::Values("dambreak", "dambreak_obstacles", "large_box", "small_box", "wave"),
                       ::testing::Values("regular", "surface", "gaze", "hybrid", "foveated"));
std::string caseName(const ::testing::TestParamInfo<SceneAndMethod>& test) {
  return std::get<0>(test.param) + "_" + std::get<1>(test.param);
}
INSTANTIATE_TEST_SUITE_P(AllScenesAllMethods, ScenarioHealth, kAllScenesThesisMethods, caseName);
INSTANTIATE_TEST_SUITE_P(AllScenesAllMethods, ScenarioHealthPbf, kAllScenesAllMethods, caseName);
// The basin (ten times the dam break's water) with the method it ships for: its regular run
// costs ten dam breaks, the bench's to measure.
INSTANTIATE_TEST_SUITE_P(Basin, ScenarioHealthPbf,
                         ::testing::Combine(::testing::Values("basin"), ::testing::Values("foveated")), caseName);

}  // namespace
