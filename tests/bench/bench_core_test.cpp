// sph_bench's pieces: replaying a gaze recording into the adaptive step, the method list, and the
// comparison table.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "bench/bench_compare.h"
#include "bench/bench_output.h"
#include "bench/bench_plan.h"
#include "bench/bench_run.h"
#include "bench/gaze_replay.h"

namespace {

gaze::GazeRecording threeSamples() {
  gaze::GazeRecording rec;
  rec.samples = {{0.0, 0.1, 0.2, true}, {0.5, 0.3, 0.4, true}, {1.0, 0.0, 0.0, false}};
  return rec;
}

// A 0.5 m box with water from its floor corner up to `water_extent` on each axis.
sph::Scene tinyScene(double water_extent, int large_particles) {
  sph::Scene s;
  s.name = "tiny";
  s.boundary.box.max = Eigen::Vector3d(0.5, 0.5, 0.5);
  s.water.max = Eigen::Vector3d::Constant(water_extent);
  s.large_particles = large_particles;
  return s;
}

TEST(GazeReplay, NewestValidSampleWithItsAge) {
  const gaze::GazeRecording rec = threeSamples();
  sph::GazeInput g = bench::gazeInputAt(rec, 0.25);
  ASSERT_TRUE(g.present);
  EXPECT_DOUBLE_EQ(g.x, 0.1);
  EXPECT_DOUBLE_EQ(g.y, 0.2);
  EXPECT_DOUBLE_EQ(g.age_s, 0.25);
  // After the invalid sample at 1.0 the last valid one (0.5) is held, ageing.
  g = bench::gazeInputAt(rec, 1.2);
  ASSERT_TRUE(g.present);
  EXPECT_DOUBLE_EQ(g.x, 0.3);
  EXPECT_NEAR(g.age_s, 0.7, 1e-12);
}

TEST(GazeReplay, LoopsPastTheEndAndIsEmptyWithoutSamples) {
  const gaze::GazeRecording rec = threeSamples();
  // Period = duration * n / (n - 1) = 1.5 s: t = 1.6 replays t = 0.1.
  const sph::GazeInput g = bench::gazeInputAt(rec, 1.6);
  ASSERT_TRUE(g.present);
  EXPECT_DOUBLE_EQ(g.x, 0.1);
  EXPECT_FALSE(bench::gazeInputAt(gaze::GazeRecording{}, 0.3).present);
}

TEST(BenchRun, EveryMethodIsKnownAndOthersAreRejected) {
  for (const char* m : {"regular", "surface", "gaze", "hybrid"}) {
    EXPECT_NO_THROW(bench::requireKnownMethod(m)) << m;
  }
  EXPECT_THROW(bench::requireKnownMethod("eye"), std::invalid_argument);
  EXPECT_TRUE(bench::methodNeedsGaze("gaze"));
  EXPECT_TRUE(bench::methodNeedsGaze("hybrid"));
  EXPECT_FALSE(bench::methodNeedsGaze("surface"));
  EXPECT_FALSE(bench::methodNeedsGaze("regular"));
  EXPECT_FALSE(bench::methodNeedsGaze("eye"));
}

TEST(BenchRun, GazeMethodWithoutARecordingIsAClearError) {
  const sph::Scene s = tinyScene(0.5, 200);
  bench::RunOptions options;
  options.frames = 2;
  try {
    bench::runScene(s, "gaze", options);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gaze recording"), std::string::npos) << e.what();
  }
}

// Runs taking turns in one process (sph_bench --interleave) compute what they compute alone.
TEST(BenchRun, InterleavedRunsMatchRunsAlone) {
  const sph::Scene s = tinyScene(0.25, 300);
  const gaze::GazeRecording rec = threeSamples();
  bench::RunOptions options;
  options.frames = 12;
  options.gaze = &rec;
  const bench::RunResult regular_alone = bench::runScene(s, "regular", options);
  const bench::RunResult gaze_alone = bench::runScene(s, "gaze", options);

  bench::SceneRun regular(s, "regular", options);
  bench::SceneRun gaze_run(s, "gaze", options);
  bench::SceneRun* both[] = {&regular, &gaze_run};
  bench::runInTurns(both, 5);  // sph_bench's own scheduler
  for (const auto& [alone, turns] :
       {std::pair{regular_alone, regular.result()}, std::pair{gaze_alone, gaze_run.result()}}) {
    ASSERT_EQ(turns.records.size(), 12u) << alone.method;
    EXPECT_EQ(turns.mass_end, alone.mass_end) << alone.method;
    for (std::size_t f = 0; f < alone.records.size(); ++f) {
      EXPECT_EQ(turns.records[f].by_level, alone.records[f].by_level) << alone.method << " frame " << f;
      EXPECT_EQ(turns.records[f].mean_density_ratio, alone.records[f].mean_density_ratio)
          << alone.method << " frame " << f;
    }
  }
}

// --save-state / --load-state: 6 frames, a checkpoint, 6 more from it, gives the checkpoint that 12
// uninterrupted frames give, byte for byte (gaze method: the replay follows the restored clock).
TEST(BenchRun, RunContinuedFromACheckpointEndsWhereTheUninterruptedOneDoes) {
  sph::Scene s = tinyScene(0.25, 300);
  s.params = sph::pbfPreset();
  const gaze::GazeRecording rec = threeSamples();
  const auto dir = std::filesystem::temp_directory_path() / ("bench_ckpt_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = [&](const char* name) { return (dir / name).string(); };
  const auto bytesOf = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  bench::RunOptions options;
  options.gaze = &rec;
  options.frames = 12;
  options.save_state = file("whole.ckpt");
  bench::runScene(s, "gaze", options);
  options.frames = 6;
  options.save_state = file("half.ckpt");
  bench::runScene(s, "gaze", options);
  options.load_state = file("half.ckpt");
  options.save_state = file("resumed.ckpt");
  const bench::RunResult resumed = bench::runScene(s, "gaze", options);
  EXPECT_DOUBLE_EQ(resumed.records.back().sim_time, 12 * s.params.time_step);
  const std::string whole = bytesOf(file("whole.ckpt"));
  EXPECT_GT(whole.size(), 1000u);
  EXPECT_TRUE(whole == bytesOf(file("resumed.ckpt")));
  std::filesystem::remove_all(dir);
}

// The run's result reads the water at its last frame: a pbf pool over the whole floor, at rest
// from the start, stands at the depth its mass fills at rho0 (water_level.h), and the summary says so.
TEST(BenchRun, ResultReadsTheWaterLevelAtTheEnd) {
  sph::Scene s = tinyScene(0.5, 1058);  // 4 full L0 layers of 23 x 23
  s.water.max.y() = 0.12;
  s.params = sph::pbfPreset();
  bench::RunOptions options;
  options.frames = 10;
  const bench::RunResult run = bench::runScene(s, "regular", options);
  const bench::WaterLevel& level = run.water_level;
  EXPECT_NEAR(level.incompressible_depth, run.incompressible_volume / (0.5 * 0.5), 1e-9);
  EXPECT_GT(level.gauges, 4);
  EXPECT_EQ(level.wet, level.gauges);
  // pbf holds it within its 1 % tolerance of compression; the level reads a little low and
  // sum m / rho a little high, as the top layer reads under-dense, hence the wider bound.
  EXPECT_NEAR(level.depth / level.incompressible_depth, 1.0, 0.03);
  EXPECT_NEAR(run.records.back().volume / run.incompressible_volume, 1.0, 0.03);
  const std::string text = bench::describeVolume(run);
  EXPECT_NE(text.find("level"), std::string::npos) << text;
  // with the water's motion then, so a reader sees whether it is a settled depth
  char rms[64];
  std::snprintf(rms, sizeof rms, "rms speed %.3f m/s", run.records.back().rms_speed);
  EXPECT_NE(text.find(rms), std::string::npos) << text;
}

// A run stopped early says so, with the frames it ran, wherever its figures go.
TEST(BenchSummary, AnInterruptedRunSaysSoAndCountsTheFramesRun) {
  bench::RunSummary s;
  s.run.scene = "dambreak";
  s.run.method = "gaze";
  s.run.frames = 3000;
  s.run.records.resize(30);
  EXPECT_TRUE(s.run.interrupted());
  EXPECT_EQ(bench::framesText(s.run), "30 of 3000 frames (INTERRUPTED)");
  EXPECT_NE(bench::summaryText(s.run, s.summary).find("30 of 3000 frames (INTERRUPTED)"), std::string::npos);
  EXPECT_NE(bench::comparisonMarkdown({s}).find("30 of 3000 frames (INTERRUPTED)"), std::string::npos);
  s.run.records.resize(3000);
  EXPECT_FALSE(s.run.interrupted());
  EXPECT_EQ(bench::framesText(s.run), "3000 frames");
}

// Saccades are read from the gaze's jumps between frames: a jump over several frames counts
// once, at its last frame; one whose third frame falls off the water is not judged.
TEST(BenchSummary, SaccadesCountWhetherTheGazePointIsAtL0ByTheThirdFrame) {
  bench::RunResult run;
  run.records.resize(40);
  for (auto& r : run.records) {
    r.gaze_jump_deg = 0.1;
    r.fovea_level = 0;
  }
  // Frame 5: a one-frame saccade, L0 at once.
  run.records[5].gaze_jump_deg = 6.0;
  // Frames 10-11: a saccade over two frames; L2, L1, then L0 in the third frame after its last.
  run.records[10].gaze_jump_deg = 4.0;
  run.records[11].gaze_jump_deg = 5.0;
  run.records[11].fovea_level = 2;
  run.records[12].fovea_level = 1;
  // Frame 20: too coarse still at its third frame, L0 in its fourth.
  run.records[20].gaze_jump_deg = 8.0;
  for (int f = 20; f <= 22; ++f) run.records[static_cast<std::size_t>(f)].fovea_level = 1;
  // Frame 30: the gaze lands off the water.
  run.records[30].gaze_jump_deg = 8.0;
  for (int f = 30; f <= 32; ++f) run.records[static_cast<std::size_t>(f)].fovea_level = -1;
  // A drift under the threshold is no saccade.
  run.records[35].gaze_jump_deg = bench::kSaccadeDeg * 0.9;
  run.records[35].fovea_level = 3;
  const bench::Summary s = bench::summarize(run);
  EXPECT_EQ(s.saccades_on_water, 3);
  EXPECT_EQ(s.saccades_finest_in_time, 2);
  EXPECT_EQ(s.saccade_most_frames_to_finest, 4);
  EXPECT_NE(bench::summaryText(run, s).find("after 3 saccades L0 by frame 3 in 2 (at most 4 frames)"),
            std::string::npos);
}

TEST(BenchCompare, TableHasOneColumnPerMethodAndTheRatioToRegular) {
  bench::RunSummary regular, gaze_run;
  regular.run.scene = gaze_run.run.scene = "dambreak";
  regular.run.method = "regular";
  gaze_run.run.method = "gaze";
  regular.summary.total.mean = 10.0;
  gaze_run.summary.total.mean = 4.0;
  gaze_run.summary.adaptive.mean = 0.2;
  regular.run.frames = gaze_run.run.frames = 300;
  regular.run.records.resize(300);
  gaze_run.run.records.resize(300);
  regular.run.threads = gaze_run.run.threads = 2;
  regular.run.omp_wait = gaze_run.run.omp_wait = "GOMP_SPINCOUNT=1000";
  regular.run.machine_load = gaze_run.run.machine_load = {true, 0.25, 0.05};
  const std::string md = bench::comparisonMarkdown({regular, gaze_run});
  EXPECT_NE(md.find("## dambreak"), std::string::npos) << md;
  EXPECT_NE(md.find("| phase | regular | gaze |"), std::string::npos) << md;
  EXPECT_NE(md.find("| **Total (ms)** | **10.000** | **4.000** |"), std::string::npos) << md;
  EXPECT_NE(md.find("| Total / regular | 1.00 | 0.40 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| Adaptive share of step | 0.0 % | 5.0 % |"), std::string::npos) << md;
  // Timings mean little without how the threads waited for each other (process/omp_wait.h).
  EXPECT_NE(md.find("300 frames, 2 threads (OpenMP wait: GOMP_SPINCOUNT=1000)"), std::string::npos) << md;
  // Nor without what else the machine did meanwhile (bench/machine_load.h).
  EXPECT_NE(md.find("Other load while the scene ran: 0.25 cores in other processes, 0.05 stolen."), std::string::npos)
      << md;
}

// Presets side by side: the same scene and methods, a table each, and their cost against the first.
TEST(BenchCompare, SeveralPresetsGetATableEachAndTheirCostSideBySide) {
  std::vector<bench::RunSummary> runs(4);
  const char* presets[] = {"thesis", "thesis", "dfsph", "dfsph"};
  const char* methods[] = {"regular", "gaze", "regular", "gaze"};
  const double cost[] = {0.34, 0.10, 2.38, 0.85};
  for (std::size_t k = 0; k < runs.size(); ++k) {
    runs[k].run.scene = "dambreak";
    runs[k].run.preset = presets[k];
    runs[k].run.method = methods[k];
    runs[k].summary.total.mean = 10.0 * cost[k];
    runs[k].summary.wall_per_simulated = cost[k];
  }
  const std::string md = bench::comparisonMarkdown(runs);
  EXPECT_NE(md.find("## dambreak, preset thesis"), std::string::npos) << md;
  EXPECT_NE(md.find("## dambreak, preset dfsph"), std::string::npos) << md;
  EXPECT_NE(md.find("| Wall s per simulated s | 2.38 | 0.85 |"), std::string::npos) << md;
  EXPECT_NE(md.find("### dambreak: presets compared"), std::string::npos) << md;
  EXPECT_NE(md.find("| method | thesis | dfsph |"), std::string::npos) << md;
  EXPECT_NE(md.find("| regular | 0.34 (1.00) | 2.38 (7.00) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| gaze | 0.10 (1.00) | 0.85 (8.50) |"), std::string::npos) << md;
}

// --preset thesis,pbf: each scene once per preset, all its runs in one group (so that they take
// turns), each in a folder of its own; the runs write what the table compares. A preset named
// twice is an error before anything runs.
TEST(BenchPlan, SeveralPresetsRunEachSceneOncePerPresetTakingTurns) {
  char tmpl[] = "/tmp/bench_plan_XXXXXX";
  ASSERT_NE(mkdtemp(tmpl), nullptr);
  const std::filesystem::path dir(tmpl);
  std::ofstream(dir / "pool.json") << R"({"name": "pool", "box": {"min": [0, 0, 0], "max": [0.3, 0.3, 0.3]},
             "water": {"min": [0, 0, 0], "max": [0.3, 0.1, 0.3]}, "large_particles": 150, "frames": 2})";
  bench::BenchRequest request;
  request.scenes = "pool";
  request.scene_dir = dir.string();
  request.methods = "regular,surface";
  request.presets = {"thesis", "pbf"};
  request.out_dir = (dir / "out").string();
  const bench::BenchPlan plan = bench::planBench(request);
  ASSERT_EQ(plan.scenes.size(), 2u);
  EXPECT_EQ(plan.scenes[0].params.preset, "thesis");
  EXPECT_EQ(plan.scenes[1].params.preset, "pbf");
  ASSERT_EQ(plan.runs.size(), 1u);
  ASSERT_EQ(plan.runs[0].size(), 4u);
  EXPECT_EQ(plan.runs[0][0].dir, dir / "out" / "pool" / "thesis" / "regular");
  EXPECT_EQ(plan.runs[0][3].dir, dir / "out" / "pool" / "pbf" / "surface");
  EXPECT_EQ(plan.runs[0][3].scene->params.preset, "pbf");

  const auto summaries = bench::runPlan(plan, request, nullptr, nullptr);
  ASSERT_EQ(summaries.size(), 4u);
  for (const auto& s : summaries) {
    // The cost figure is the steps' mean time over the frame's simulated time (no time asserted).
    const sph::Scene& scene = plan.scenes[s.run.preset == "thesis" ? 0 : 1];
    EXPECT_EQ(s.run.frame_seconds, scene.params.time_step) << s.run.preset << '/' << s.run.method;
    EXPECT_DOUBLE_EQ(s.summary.wall_per_simulated, s.summary.total.mean / 1000.0 / s.run.frame_seconds)
        << s.run.preset << '/' << s.run.method;
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / "pool" / s.run.preset / s.run.method / "summary.json"));
  }
  EXPECT_NE(bench::comparisonMarkdown(summaries).find("### pool: presets compared"), std::string::npos);

  request.presets = {"pbf", "pbf"};
  EXPECT_THROW(bench::planBench(request), std::invalid_argument);
  std::filesystem::remove_all(dir);
}

}  // namespace
