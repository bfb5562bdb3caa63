#include "bench/bench_plan.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "bench/vtu_export.h"
#include "scene/scene_loader.h"
#include "scene/scene_method.h"
#include "sph/adaptive/method.h"

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

const char* extensionOf(SnapshotFormat format) {
  switch (format) {
    case SnapshotFormat::Csv:
      return "csv";
    case SnapshotFormat::Vtk:
      return "vtk";
    case SnapshotFormat::Vtu:
      break;
  }
  return "vtu";
}

// A run's particle snapshots: particles_NNNNN.EXT every export_every frames, frame 0 included; for
// VTU also particles.pvd, rewritten with each file so it is complete wherever the run stops.
class SnapshotSeries {
 public:
  SnapshotSeries(const std::filesystem::path& dir, SnapshotFormat format)
      : dir_(dir), format_(format), index_((dir / "particles.pvd").string()) {}
  void write(const sph::ParticleSet& particles, int frame, double time) {
    char name[64];
    std::snprintf(name, sizeof name, "particles_%05d.%s", frame, extensionOf(format_));
    const std::string path = (dir_ / name).string();
    if (format_ != SnapshotFormat::Vtu) {
      writeSnapshot(particles, format_, path);
      return;
    }
    writeVtu(particles, time, path);
    index_.add(time, name);
    index_.write();
  }

 private:
  std::filesystem::path dir_;
  SnapshotFormat format_;
  PvdIndex index_;
};

// Whether the scene's solver runs the method's levels (scene::solverHasLevelsOf); a name no
// method has is left to fail when its run starts.
bool solverHasLevelsOf(const sph::Scene& scene, const std::string& method) {
  sph::Method m;
  return !sph::methodByName(method, m) || scene::solverHasLevelsOf(scene, m);
}

}  // namespace

std::string firstRepeated(const std::vector<std::string>& items) {
  for (auto it = items.begin(); it != items.end(); ++it) {
    if (std::find(items.begin(), it, *it) != it) return *it;
  }
  return {};
}

BenchPlan planBench(const BenchRequest& request) {
  BenchPlan plan;
  std::vector<std::string> scene_names =
      request.scenes == "all" ? scene::listScenes(request.scene_dir) : splitList(request.scenes);
  std::vector<std::string> methods = request.methods == "all" ? knownMethods() : splitList(request.methods);
  if (scene_names.empty()) throw std::invalid_argument("no scene named (--scene)");
  for (const auto& m : methods) requireKnownMethod(m);
  if (const std::string twice = firstRepeated(request.presets); !twice.empty()) {
    throw std::invalid_argument("preset '" + twice + "' named twice (--preset)");
  }
  // Empty: the scene's own preset.
  const std::vector<std::string> presets = request.presets.empty() ? std::vector<std::string>{""} : request.presets;
  plan.scenes.reserve(scene_names.size() * presets.size());  // the runs point into it
  for (const auto& s : scene_names) {
    for (const auto& preset : presets) {
      sph::Scene& loaded = plan.scenes.emplace_back(scene::loadScene(s, request.scene_dir, preset));
      if (request.levels != 0) {
        loaded.params.levels = request.levels;
        loaded.params.validate();
      }
    }
  }

  const gaze::GazeRecording* override_gaze = nullptr;
  if (!request.gaze_path.empty()) {
    plan.recordings.push_back(std::make_unique<gaze::GazeRecording>(gaze::readGazeRecording(request.gaze_path)));
    override_gaze = plan.recordings.back().get();
  }
  plan.matrix = plan.scenes.size() * std::max<std::size_t>(methods.size(), 1) > 1;
  const bool per_preset = presets.size() > 1;
  if (plan.matrix && !(request.load_state.empty() && request.save_state.empty())) {
    throw std::invalid_argument("--load-state and --save-state need one scene, one method and one preset");
  }

  std::map<std::string, const gaze::GazeRecording*> scene_gaze;
  for (std::size_t k = 0; k < plan.scenes.size(); ++k) {
    const sph::Scene& sc = plan.scenes[k];
    // A scene's presets go into one group, so that they take turns too.
    std::vector<PlannedRun>& runs = k % presets.size() == 0 ? plan.runs.emplace_back() : plan.runs.back();
    // Each scene's own method, as the server runs it (scene::ownMethod).
    const std::string own = sph::methodName(scene::ownMethod(sc));
    for (const std::string& method : methods.empty() ? std::vector<std::string>{own} : methods) {
      // 'all' leaves out the methods whose levels the preset's solver does not have (foveated on the
      // thesis's); named, such a method is an error when its run starts.
      if (request.methods == "all" && !solverHasLevelsOf(sc, method)) continue;
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
      std::filesystem::path dir(request.out_dir);
      if (plan.matrix) dir = per_preset ? dir / sc.name / sc.params.preset / method : dir / sc.name / method;
      runs.push_back({&sc, method, dir, gaze});
    }
  }
  return plan;
}

void runInTurns(std::span<SceneRun* const> runs, int turn, const std::atomic<bool>* stop) {
  const auto stopped = [stop] { return stop != nullptr && stop->load(); };
  for (bool left = true; left && !stopped();) {
    left = false;
    for (SceneRun* run : runs) {
      for (int k = 0; (turn <= 0 || k < turn) && !run->done() && !stopped(); ++k) run->stepFrame();
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
    std::vector<std::unique_ptr<SnapshotSeries>> series(scene_runs.size());
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
      if (request.export_every > 0) series[r] = std::make_unique<SnapshotSeries>(planned.dir, request.export_format);
      options.on_frame = [&, r, frames](const sph::Simulation& sim, const FrameRecord& record) {
        total_ms[r] += record.ms.total_ms;
        if (series[r] && record.frame % request.export_every == 0) {
          series[r]->write(sim.particles(), record.frame, record.sim_time);
        }
        if (on_progress) on_progress(scene_runs[r], record, frames, total_ms[r] / record.frame);
      };
      runs.push_back(std::make_unique<SceneRun>(*planned.scene, planned.method, options));
      // Frame 0: the state the run starts from, so a time series begins where the scene does.
      if (series[r]) series[r]->write(runs.back()->simulation().particles(), 0, runs.back()->simulation().time());
    }
    std::vector<SceneRun*> order;
    for (auto& run : runs) order.push_back(run.get());
    runInTurns(order, request.interleave, request.stop);
    const bool stopped = request.stop != nullptr && request.stop->load();
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const RunResult result = runs[r]->result();
      runs[r].reset();               // free the simulation before the next scene's runs are made
      if (result.records.empty()) {  // interrupted before its first frame: nothing to keep
        std::error_code ec;
        std::filesystem::remove(scene_runs[r].dir, ec);  // only when empty
        continue;
      }
      RunSummary summary{result, summarize(result)};
      writeSummaryJson(summary.run, summary.summary, (scene_runs[r].dir / "summary.json").string());
      writeFramesCsv(summary.run, (scene_runs[r].dir / "frames.csv").string());
      if (on_summary) on_summary(summary, scene_runs[r]);
      summaries.push_back(std::move(summary));
    }
    if (stopped) break;
  }
  return summaries;
}

}  // namespace bench
