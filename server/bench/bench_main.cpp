// sph_bench: headless runs of scenes x methods with no sockets; prints and writes the thesis's
// measurements (4.1): mean ms per phase, steps per second, particle counts, plus health checks.
#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>

#include "bench/bench_plan.h"
#include "cli/cli_conventions.h"
#include "process/omp_wait.h"
#include "scene/scene_loader.h"
#include "sph/param_table.h"

namespace {

std::atomic<bool> g_stop{false};
extern "C" void onStopSignal(int) { g_stop.store(true); }

// Parses the command line into `request`; returns an exit code when the program should stop.
std::optional<int> parseRequest(int argc, char** argv, bench::BenchRequest& request) {
  CLI::App app{"sph_bench: run SPH scenes headless and report the thesis's measurements"};
  cli::prepare(app, "sph_bench", "130 interrupted (the rows written so far are kept)");
  std::string export_format = "vtu";
  request.scene_dir = scene::defaultSceneDir();
  app.add_option("--scene", request.scenes, "scene name, path to a .json file, comma list, or 'all'")
      ->capture_default_str();
  app.add_option("--method", request.methods,
                 "regular, surface, gaze, hybrid, foveated, a comma list, or 'all' (default: each scene's own)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            if (text == "all") return {};
            std::stringstream list(text);
            for (std::string method; std::getline(list, method, ',');) {
              try {
                bench::requireKnownMethod(method);
              } catch (const std::invalid_argument& e) {
                return e.what();
              }
            }
            return {};
          },
          "METHOD[,METHOD...]"));
  app.add_option("--gaze", request.gaze_path,
                 "gaze recording (CSV: time_s,x,y,valid) replayed for gaze, hybrid and foveated, instead of "
                 "the scene's own")
      ->check(CLI::ExistingFile);
  app.add_option("--frames", request.frames, "frames (steps) to run; 0 = the scene's own count")
      ->check(cli::nonNegative());
  app.add_option("--preset", request.presets,
                 "fluid preset for every scene: pbf (the default, as in sph_server), dfsph, thesis (the thesis's "
                 "compressible SPH: its tables) or scene (each scene file's own); a comma list runs each scene "
                 "once per preset, taking turns, and compares their cost")
      ->delimiter(',')
      ->check(CLI::IsMember(sph::presetOrSceneNames()));
  app.add_option("--load-state", request.load_state,
                 "continue from this checkpoint (written by --save-state; one scene, method and preset)")
      ->check(CLI::ExistingFile);
  app.add_option("--save-state", request.save_state,
                 "write a checkpoint here after the last frame (one scene, method and preset)");
  app.add_option("--threads", request.threads, "OpenMP threads")->check(cli::range(1, 256))->capture_default_str();
  app.add_option(
         "--out", request.out_dir,
         "output folder (one subfolder per scene/method when several, scene/preset/method with several presets)")
      ->capture_default_str();
  app.add_option("--scene-dir", request.scene_dir, "folder of named scenes")->capture_default_str();
  app.add_option("--interleave", request.interleave,
                 "frames each method of a scene runs before the next takes its turn, so all see the "
                 "same machine load (0 = each method start to end, one after another)")
      ->check(cli::nonNegative())
      ->capture_default_str();
  app.add_option("--levels", request.levels,
                 "size levels for every scene (parameter 'levels': L0 the finest to L(N - 1)); default: the scene's")
      ->check(cli::range(sph::kMinLevels, sph::kMaxLevels));
  app.add_option("--export-every", request.export_every, "write a particle snapshot every K frames (0 = never)")
      ->check(cli::nonNegative());
  app.add_option("--export-format", export_format,
                 "vtu (binary, with a particles.pvd time index for ParaView), vtk (legacy ASCII) or csv")
      ->check(CLI::IsMember({"vtu", "vtk", "csv"}))
      ->capture_default_str();
  bool parameter_table = false;
  app.add_flag("--parameter-table", parameter_table,
               "print every setting with its default (in each preset) as Markdown, and exit");
  app.footer("Simulation parameters (a scene file's \"params\"; sph_server --param):\n" +
             sph::parameterHelpText(false) +
             "\nAdaptive settings (a scene file's \"adaptive\"; sph_server --adaptive):\n" +
             sph::parameterHelpText(true) + "\n" + app.get_footer());
  if (auto code = cli::parse(app, argc, argv)) return code;
  if (parameter_table) {
    std::fputs(sph::parameterTableMarkdown().c_str(), stdout);
    return 0;
  }
  if (const std::string twice = bench::firstRepeated(request.presets); !twice.empty()) {
    return cli::usageError(app, "--preset: " + twice + " named twice");
  }
  // One rule for every program: pbf unless told otherwise; "scene" is the scene file's own preset
  // (an empty name to the plan).
  if (request.presets.empty()) request.presets = {"pbf"};
  for (std::string& preset : request.presets) {
    if (preset == "scene") preset.clear();
  }
  request.export_format = export_format == "csv"   ? bench::SnapshotFormat::Csv
                          : export_format == "vtk" ? bench::SnapshotFormat::Vtk
                                                   : bench::SnapshotFormat::Vtu;
  return std::nullopt;
}

// One progress line per run at most every second, and at its last frame.
class ProgressLines {
 public:
  void operator()(const bench::PlannedRun& run, const bench::FrameRecord& record, int frames, double mean_ms) {
    const auto now = std::chrono::steady_clock::now();
    auto [it, fresh] = last_.try_emplace(run.dir.string(), now);
    if (!fresh && now - it->second <= std::chrono::seconds(1) && record.frame != frames) return;
    it->second = now;
    std::fprintf(stderr, "[%s/%s/%s] frame %d/%d  t=%.2fs  mean step %.3f ms  particles %zu\n", run.scene->name.c_str(),
                 run.scene->params.preset.c_str(), run.method.c_str(), record.frame, frames, record.sim_time, mean_ms,
                 record.particles());
  }

 private:
  std::map<std::string, std::chrono::steady_clock::time_point> last_;
};

}  // namespace

int main(int argc, char** argv) {
  process::applyDefaultOmpWaitPolicy(argv);  // first: it may re-execute the program
  bench::BenchRequest request;
  if (auto code = parseRequest(argc, argv, request)) return *code;
  // Ctrl-C (or SIGTERM) ends the runs between frames; what they recorded is still written.
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  request.stop = &g_stop;
  try {
    const bench::BenchPlan plan = bench::planBench(request);
    ProgressLines progress;
    const auto summaries =
        bench::runPlan(plan, request, std::ref(progress), [](const bench::RunSummary& s, const bench::PlannedRun& run) {
          std::printf("%s\n  -> %s\n", bench::summaryText(s.run, s.summary).c_str(), run.dir.string().c_str());
          std::fflush(stdout);
        });
    if (plan.matrix) {
      const std::filesystem::path table = std::filesystem::path(request.out_dir) / "comparison.md";
      std::ofstream(table) << bench::comparisonMarkdown(summaries);
      std::printf("comparison table -> %s\n", table.string().c_str());
    }
    if (g_stop.load()) {
      std::fprintf(stderr, "sph_bench: interrupted; the frames run so far are kept in %s (exit code 130)\n",
                   request.out_dir.c_str());
      return 130;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph_bench: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
