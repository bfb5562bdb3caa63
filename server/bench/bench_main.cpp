// sph_bench: headless runs of scenes x methods with no sockets; prints and writes the thesis's
// measurements (4.1): mean ms per phase, steps per second, particle counts, plus health checks.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "bench/bench_compare.h"
#include "bench/bench_output.h"
#include "bench/bench_run.h"
#include "scene/scene_loader.h"
#include "sph/omp_wait.h"

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

}  // namespace

int main(int argc, char** argv) {
  sph::applyDefaultOmpWaitPolicy(argv);  // first: it may re-execute the program
  CLI::App app{"sph_bench: run SPH scenes headless and report the thesis's measurements"};
  std::string scene_arg = "dambreak";
  std::string method_arg;
  std::string gaze_path;
  std::string out_dir = "bench_out";
  std::string scene_dir = scene::defaultSceneDir();
  std::string export_format = "vtk";
  int frames = 0;
  int threads = 2;
  int export_every = 0;
  int interleave = 10;
  app.add_option("--scene", scene_arg, "scene name, path to a .json file, comma list, or 'all'")->capture_default_str();
  app.add_option("--method", method_arg,
                 "regular, surface, gaze, hybrid, a comma list, or 'all' (default: each scene's own)");
  app.add_option("--gaze", gaze_path,
                 "gaze recording (CSV: time_s,x,y,valid) replayed for gaze and hybrid, instead of "
                 "the scene's own")
      ->check(CLI::ExistingFile);
  app.add_option("--frames", frames, "frames (steps) to run; 0 = the scene's own count")->check(CLI::NonNegativeNumber);
  app.add_option("--threads", threads, "OpenMP threads")->check(CLI::Range(1, 256))->capture_default_str();
  app.add_option("--out", out_dir, "output folder (one subfolder per scene/method when several)")
      ->capture_default_str();
  app.add_option("--scene-dir", scene_dir, "folder of named scenes")->capture_default_str();
  app.add_option("--interleave", interleave,
                 "frames each method of a scene runs before the next takes its turn, so all see the "
                 "same machine load (0 = each method start to end, one after another)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--export-every", export_every, "write a particle snapshot every K frames (0 = never)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--export-format", export_format, "snapshot format")
      ->check(CLI::IsMember({"csv", "vtk"}))
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    std::vector<std::string> scenes = splitList(scene_arg);
    if (scene_arg == "all") scenes = scene::listScenes(scene_dir);
    std::vector<std::string> methods = splitList(method_arg);
    if (method_arg == "all") methods = bench::knownMethods();
    if (scenes.empty()) throw std::invalid_argument("no scene named (--scene)");
    for (const auto& m : methods) bench::requireKnownMethod(m);
    // Load every scene and recording before running any, so a typo fails fast and writes nothing.
    std::vector<sph::Scene> loaded;
    for (const auto& s : scenes) loaded.push_back(scene::loadScene(s, scene_dir));
    const auto methodsFor = [&](const sph::Scene& sc) {
      return methods.empty() ? std::vector<std::string>{sc.method} : methods;
    };
    std::shared_ptr<gaze::GazeRecording> override_gaze;
    if (!gaze_path.empty()) {
      override_gaze = std::make_shared<gaze::GazeRecording>(gaze::readGazeRecording(gaze_path));
    }
    std::map<std::string, std::shared_ptr<gaze::GazeRecording>> scene_gaze;
    std::size_t runs = 0;
    for (const sph::Scene& sc : loaded) {
      for (const auto& m : methodsFor(sc)) {
        ++runs;
        if (bench::methodNeedsGaze(m) && !override_gaze && !scene_gaze.contains(sc.name)) {
          if (sc.gaze_recording.empty()) {
            throw std::invalid_argument("scene '" + sc.name + "' names no gaze_recording for method '" + m +
                                        "': pass --gaze FILE");
          }
          scene_gaze[sc.name] = std::make_shared<gaze::GazeRecording>(gaze::readGazeRecording(sc.gaze_recording));
        }
      }
    }

    const bool matrix = runs > 1;
    std::vector<bench::RunSummary> summaries;
    const auto format = export_format == "csv" ? bench::SnapshotFormat::Csv : bench::SnapshotFormat::Vtk;
    // One scene at a time; its methods take turns of `interleave` frames, so that a slow spell
    // of the machine falls on all of them alike and their ratios hold.
    struct Slot {
      std::string method;
      std::filesystem::path dir;
      double total_ms = 0.0;
      std::chrono::steady_clock::time_point last_print;
      std::unique_ptr<bench::SceneRun> run;
    };
    for (const sph::Scene& sc : loaded) {
      const int total_frames = frames > 0 ? frames : sc.frames;
      std::vector<std::unique_ptr<Slot>> slots;
      for (const std::string& method : methodsFor(sc)) {
        auto slot = std::make_unique<Slot>();
        Slot& sl = *slot;
        sl.method = method;
        sl.dir = matrix ? std::filesystem::path(out_dir) / sc.name / method : std::filesystem::path(out_dir);
        std::filesystem::create_directories(sl.dir);
        bench::RunOptions options;
        options.frames = frames;
        options.threads = threads;
        if (bench::methodNeedsGaze(method)) {
          options.gaze = override_gaze ? override_gaze.get() : scene_gaze.at(sc.name).get();
        }
        sl.last_print = std::chrono::steady_clock::now();
        options.on_frame = [&sl, &sc, &export_format, format, export_every, total_frames](const sph::Simulation& sim,
                                                                                          const bench::FrameRecord& r) {
          sl.total_ms += r.ms.total_ms;
          if (export_every > 0 && r.frame % export_every == 0) {
            char name[64];
            std::snprintf(name, sizeof name, "particles_%05d.%s", r.frame, export_format.c_str());
            bench::writeSnapshot(sim.particles(), format, (sl.dir / name).string());
          }
          const auto now = std::chrono::steady_clock::now();
          if (now - sl.last_print > std::chrono::seconds(1) || r.frame == total_frames) {
            sl.last_print = now;
            std::fprintf(stderr, "[%s/%s] frame %d/%d  t=%.2fs  mean step %.3f ms  particles %zu\n", sc.name.c_str(),
                         sl.method.c_str(), r.frame, total_frames, r.sim_time, sl.total_ms / r.frame,
                         r.n_large + r.n_small);
          }
        };
        sl.run = std::make_unique<bench::SceneRun>(sc, method, options);
        slots.push_back(std::move(slot));
      }
      const int turn = interleave > 0 ? interleave : total_frames;
      for (bool left = true; left;) {
        left = false;
        for (auto& sl : slots) {
          for (int k = 0; k < turn && !sl->run->done(); ++k) sl->run->stepFrame();
          left = left || !sl->run->done();
        }
      }
      for (auto& sl : slots) {
        const bench::RunResult run = sl->run->result();
        sl->run.reset();  // free the simulation before the next scene's runs are made
        const bench::Summary summary = bench::summarize(run);
        bench::writeSummaryJson(run, summary, (sl->dir / "summary.json").string());
        bench::writeFramesCsv(run, (sl->dir / "frames.csv").string());
        std::printf("%s\n  -> %s\n", bench::summaryText(run, summary).c_str(), sl->dir.string().c_str());
        std::fflush(stdout);
        summaries.push_back({run, summary});
      }
    }
    if (matrix) {
      const std::filesystem::path table = std::filesystem::path(out_dir) / "comparison.md";
      std::ofstream(table) << bench::comparisonMarkdown(summaries);
      std::printf("comparison table -> %s\n", table.string().c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph_bench: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
