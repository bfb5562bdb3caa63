// A scene run to a state the benchmarks time their passes on: the dam break after enough frames
// that the column has fallen and the water sloshes, so neighbour counts and memory order are a
// real run's. Gaze-driven methods replay the scene's own recording.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "bench/bench_run.h"
#include "gaze/gaze_recording.h"
#include "scene/scene_loader.h"

namespace bench {

// `scene` run with `method` for `frames` frames on 2 threads (`preset`: as scene::loadScene takes
// it, empty for the scene file's own).
inline std::unique_ptr<SceneRun> warmRun(const std::string& scene_name, const std::string& preset,
                                         const std::string& method, int frames) {
  const sph::Scene scene = scene::loadScene(scene_name, scene::defaultSceneDir(), preset);
  // The run keeps a pointer to its recording: one per recording file, for the process's life.
  static std::map<std::string, gaze::GazeRecording> recordings;
  auto found = recordings.find(scene.gaze_recording);
  if (found == recordings.end()) {
    found = recordings.emplace(scene.gaze_recording, gaze::readGazeRecording(scene.gaze_recording)).first;
  }
  RunOptions options;
  options.frames = frames;
  options.threads = 2;
  options.gaze = &found->second;
  auto run = std::make_unique<SceneRun>(scene, method, options);
  while (!run->done()) run->stepFrame();
  return run;
}

}  // namespace bench
