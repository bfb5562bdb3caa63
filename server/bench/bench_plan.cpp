#include "bench/bench_plan.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "scene/scene_loader.h"

namespace bench {

namespace {

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

const char* extensionOf(SnapshotFormat format) { return format == SnapshotFormat::Csv ? "csv" : "vtk"; }

}  // namespace

BenchPlan planBench(const BenchRequest& request) {
  BenchPlan plan;
  std::vector<std::string> scene_names =
      request.scenes == "all" ? scene::listScenes(request.scene_dir) : splitList(request.scenes);
  std::vector<std::string> methods = request.methods == "all" ? knownMethods() : splitList(request.methods);
  if (scene_names.empty()) throw std::invalid_argument("no scene named (--scene)");
  for (const auto& m : methods) requireKnownMethod(m);
  for (const auto& s : scene_names) plan.scenes.push_back(scene::loadScene(s, request.scene_dir, request.preset));

  const gaze::GazeRecording* override_gaze = nullptr;
  if (!request.gaze_path.empty()) {
    plan.recordings.push_back(std::make_unique<gaze::GazeRecording>(gaze::readGazeRecording(request.gaze_path)));
    override_gaze = plan.recordings.back().get();
  }
  plan.matrix = plan.scenes.size() * std::max<std::size_t>(methods.size(), 1) > 1;
  if (plan.matrix && !(request.load_state.empty() && request.save_state.empty())) {
    throw std::invalid_argument("--load-state and --save-state need one scene and one method");
  }

  std::map<std::string, const gaze::GazeRecording*> scene_gaze;
  for (const sph::Scene& sc : plan.scenes) {
    std::vector<PlannedRun>& runs = plan.runs.emplace_back();
    for (const std::string& method : methods.empty() ? std::vector<std::string>{sc.method} : methods) {
      const gaze::GazeRecording* gaze = nullptr;
      if (methodNeedsGaze(method)) {
        if (override_gaze != nullptr) {
          gaze = override_gaze;
        } else if (auto it = scene_gaze.find(sc.name); it != scene_gaze.end()) {
          gaze = it->second;
        } else {
          if (sc.gaze_recording.empty()) {
            throw std::invalid_argument("scene '" + sc.name + "' names no gaze_recording for method '" + method +
                                        "': pass --gaze FILE");
          }
          plan.recordings.push_back(std::make_unique<gaze::GazeRecording>(gaze::readGazeRecording(sc.gaze_recording)));
          gaze = scene_gaze[sc.name] = plan.recordings.back().get();
        }
      }
      const std::filesystem::path dir = plan.matrix ? std::filesystem::path(request.out_dir) / sc.name / method
                                                    : std::filesystem::path(request.out_dir);
      runs.push_back({&sc, method, dir, gaze});
    }
  }
  return plan;
}

void runInTurns(std::span<SceneRun* const> runs, int turn) {
  for (bool left = true; left;) {
    left = false;
    for (SceneRun* run : runs) {
      for (int k = 0; (turn <= 0 || k < turn) && !run->done(); ++k) run->stepFrame();
      left = left || !run->done();
    }
  }
}

std::vector<RunSummary> runPlan(const BenchPlan& plan, const BenchRequest& request, const ProgressFn& on_progress,
                                const std::function<void(const RunSummary&, const PlannedRun&)>& on_summary) {
  std::vector<RunSummary> summaries;
  for (const std::vector<PlannedRun>& scene_runs : plan.runs) {
    std::vector<std::unique_ptr<SceneRun>> runs;
    std::vector<double> total_ms(scene_runs.size(), 0.0);
    for (std::size_t r = 0; r < scene_runs.size(); ++r) {
      const PlannedRun& planned = scene_runs[r];
      std::filesystem::create_directories(planned.dir);
      RunOptions options;
      options.frames = request.frames;
      options.threads = request.threads;
      options.gaze = planned.gaze;
      options.load_state = request.load_state;
      options.save_state = request.save_state;
      const int frames = request.frames > 0 ? request.frames : planned.scene->frames;
      options.on_frame = [&, r, frames](const sph::Simulation& sim, const FrameRecord& record) {
        total_ms[r] += record.ms.total_ms;
        if (request.export_every > 0 && record.frame % request.export_every == 0) {
          char name[64];
          std::snprintf(name, sizeof name, "particles_%05d.%s", record.frame, extensionOf(request.export_format));
          writeSnapshot(sim.particles(), request.export_format, (scene_runs[r].dir / name).string());
        }
        if (on_progress) on_progress(scene_runs[r], record, frames, total_ms[r] / record.frame);
      };
      runs.push_back(std::make_unique<SceneRun>(*planned.scene, planned.method, options));
    }
    std::vector<SceneRun*> order;
    for (auto& run : runs) order.push_back(run.get());
    runInTurns(order, request.interleave);
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const RunResult result = runs[r]->result();
      runs[r].reset();  // free the simulation before the next scene's runs are made
      RunSummary summary{result, summarize(result)};
      writeSummaryJson(summary.run, summary.summary, (scene_runs[r].dir / "summary.json").string());
      writeFramesCsv(summary.run, (scene_runs[r].dir / "frames.csv").string());
      if (on_summary) on_summary(summary, scene_runs[r]);
      summaries.push_back(std::move(summary));
    }
  }
  return summaries;
}

}  // namespace bench
