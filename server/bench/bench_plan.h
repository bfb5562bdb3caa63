// What one sph_bench invocation runs, and the scheduler that runs it: every scene named, each with
// its methods (and, when several are named, once per fluid preset), loaded and checked before
// anything runs (a typo fails fast and writes nothing); then one scene at a time, its runs taking
// turns of a few frames so that a slow spell of the machine falls on all of them alike and their
// ratios hold.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "bench/bench_compare.h"
#include "bench/bench_output.h"
#include "bench/bench_run.h"
#include "gaze/gaze_recording.h"
#include "sph/scene.h"

namespace bench {

// The command line's requests (bench_main.cpp parses them).
struct BenchRequest {
  std::string scenes = "dambreak";  // a name, a path, a comma list, or "all"
  std::string methods;              // a method, a comma list, "all", or empty: each scene's own
  std::string gaze_path;            // a recording for gaze and hybrid instead of the scenes' own
  std::string out_dir = "bench_out";
  std::string scene_dir;
  int frames = 0;  // 0: each scene's own count
  int threads = 2;
  int interleave = 10;  // frames per turn; 0: each method start to end, one after another
  int export_every = 0;
  int levels = 0;  // the level count for every scene (SimParams::levels); 0: each scene's own
  SnapshotFormat export_format = SnapshotFormat::Vtk;
  // thesis, pbf, dfsph: each scene runs once per preset named, the presets taking turns like the
  // methods; none: each scene's own
  std::vector<std::string> presets;
  std::string load_state;  // a checkpoint to continue from (one scene, method and preset)
  std::string save_state;  // where to write the checkpoint at the end (one scene, method and preset)
  // Set (by a signal) to stop early: the runs stop between frames and keep the rows recorded so far.
  const std::atomic<bool>* stop = nullptr;
};

// One run of the plan: a scene (with its preset), a method, where its files go and the gaze it replays.
struct PlannedRun {
  const sph::Scene* scene;
  std::string method;
  std::filesystem::path dir;
  const gaze::GazeRecording* gaze;  // null for methods that need none
};

struct BenchPlan {
  std::vector<sph::Scene> scenes;             // one per scene named and preset
  std::vector<std::vector<PlannedRun>> runs;  // per scene named: its presets' runs, method by method
  // More than one run: a folder per scene and method (out/scene/method), and per preset when
  // several are named (out/scene/preset/method).
  bool matrix = false;
  std::vector<std::unique_ptr<gaze::GazeRecording>> recordings;  // what the runs' gaze points to
};

// The first item of `items` that an earlier one repeats; empty if none does.
std::string firstRepeated(const std::vector<std::string>& items);

// Loads every scene and recording the request names; throws std::invalid_argument naming what is
// unknown or missing. The plan owns what its runs point to (keep it alive while they run).
BenchPlan planBench(const BenchRequest& request);

// Runs every run to its end in turns of `turn` frames each, in the order given; 0: each start to
// end, one after another. Each run computes exactly what it computes alone (tested).
void runInTurns(std::span<SceneRun* const> runs, int turn, const std::atomic<bool>* stop = nullptr);

// Progress of one run: (run, frames done, frames in all, mean step ms so far, particles).
using ProgressFn = std::function<void(const PlannedRun&, const FrameRecord&, int frames, double mean_ms)>;

// Runs the plan scene by scene (runInTurns) and writes each run's summary.json and frames.csv
// (and snapshots, when asked) into its folder; returns the runs' summaries in plan order.
// `on_summary` is called with each run's summary as soon as it is written. After request.stop is
// set, the runs under way are written with the frames they have, a run with none is not written
// (and its folder removed when empty), and no further scene starts.
std::vector<RunSummary> runPlan(const BenchPlan& plan, const BenchRequest& request, const ProgressFn& on_progress,
                                const std::function<void(const RunSummary&, const PlannedRun&)>& on_summary);

}  // namespace bench
