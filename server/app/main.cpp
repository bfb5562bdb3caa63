// sph_server: loads a scene, runs an SPH method in real time (or free-run), publishes frames and takes
// gaze, camera poses and control requests over ZeroMQ. See server/app/README.md.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <exception>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "app/server.h"
#include "cli/cli_conventions.h"
#include "net/curve_cli.h"
#include "net/fd_limit.h"
#include "process/omp_wait.h"
#include "process/stop_signals.h"
#include "scene/scene_loader.h"
#include "sph/param_table.h"

namespace {

struct CliOptions {
  app::ServerOptions server;
  std::string method;                  // empty: the scene's default method
  std::string realtime = "on";         // --realtime on|off
  std::map<std::string, double> gaze;  // --gaze-* options given
  std::vector<std::string> adaptive;   // --adaptive key=value
  std::vector<std::string> params;     // --param key=value
  int levels = 0;                      // --levels N: --param levels=N
  std::string gaze_socket = "sub";
  std::string pose_socket = "sub";
  std::string log_level = "info";
  curve::ServerFiles curve;
  int max_peers = net::kDefaultMaxPeers;
};

// --publish-hz takes what set_parameters takes: one check for both (app::publishHzError).
CLI::Validator publishHzValidator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double hz = 0.0;
        try {
          hz = std::stod(text);
        } catch (const std::exception&) {
          return "expected a number, got '" + text + "'";
        }
        return app::publishHzError(hz);
      },
      fmt::format("HZ in [{}, {}]", app::kMinPublishHz, app::kMaxPublishHz));
}

void addOptions(CLI::App& cli, CliOptions& o) {
  app::SimLoopOptions& sim = o.server.sim;
  net::Endpoints& ep = o.server.net.endpoints;
  sim.scene_dir = scene::defaultSceneDir();
  cli.option_defaults()->group("Scene and physics");
  cli.add_option("--scene", sim.scene, "scene name in --scene-dir, or a path to a scene file")->capture_default_str();
  cli.add_option("--scene-dir", sim.scene_dir, "folder of scene files ($SPH_SCENE_DIR)")->capture_default_str();
  cli.add_option("--method", o.method, "regular, surface, gaze, hybrid or foveated (default: the scene's method)")
      ->check(CLI::IsMember(sph::methodNames()));
  sim.preset = "pbf";
  cli.add_option("--preset", sim.preset,
                 "fluid: pbf (incompressible, position based), dfsph (divergence-free, experimental: docs/fluids.md), "
                 "thesis (the thesis's compressible SPH, k = 3), or scene (the scene file's own preset)")
      ->check(CLI::IsMember(sph::presetOrSceneNames()))
      ->capture_default_str();
  cli.option_defaults()->group("Run and frames");
  cli.add_option("--load-state", sim.load_state,
                 "continue from this checkpoint (written by --save-state with the same scene, preset and method)")
      ->check(CLI::ExistingFile);
  cli.add_option("--save-state", sim.save_state, "write a checkpoint here when the server stops");
  cli.add_flag("--free-run", sim.settings.free_run, "step as fast as possible (default: sim time follows wall time)");
  cli.add_option("--realtime", o.realtime,
                 "on: the foveated method trades its periphery gain to keep sim time in step with wall time "
                 "(the periphery coarsens, the gaze point keeps its level); off: the gain stays as configured")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cli.add_option("--publish-hz", sim.settings.publish_hz, "frames published per second")
      ->check(publishHzValidator())
      ->capture_default_str();
  cli.add_flag("--quantized", sim.settings.quantized, "16-bit positions relative to the box (6 bytes per particle)");
  cli.add_flag("--velocities", sim.velocities, "add velocities (3 float32) to every frame");
  cli.add_flag("--neighbor-counts", sim.neighbor_counts,
               "add each particle's neighbour count (1 byte) to every frame (sph_viewer draws spray by it)");
  cli.add_option("--threads", sim.threads, "OpenMP threads for the step")
      ->check(cli::range(1, 256))
      ->capture_default_str();
  cli.add_option("--max-steps", sim.max_steps, "stop after this many steps (0: run until SIGINT/SIGTERM)")
      ->check(cli::nonNegative())
      ->capture_default_str();
  cli.add_option("--slow-step-ms", sim.slow_step_ms,
                 "tests and demos: wait this long in every step, as a slower machine would (0: off)")
      ->check(cli::range(0.0, 10000.0))
      ->capture_default_str();
  cli.option_defaults()->group("Network");
  cli.add_option("--frames-endpoint", ep.frames, "XPUB: frames out")->capture_default_str();
  cli.add_option("--gaze-endpoint", ep.gaze, "GazeSample in")->capture_default_str();
  cli.add_option("--pose-endpoint", ep.pose, "CameraPose in")->capture_default_str();
  cli.add_option("--control-endpoint", ep.control, "ROUTER: Control in, ControlReply out")->capture_default_str();
  cli.add_option("--gaze-socket", o.gaze_socket, "sub (senders connect PUB) or pull (senders connect PUSH)")
      ->check(CLI::IsMember({"sub", "pull"}))
      ->capture_default_str();
  cli.add_option("--pose-socket", o.pose_socket, "sub or pull, as --gaze-socket")
      ->check(CLI::IsMember({"sub", "pull"}))
      ->capture_default_str();
  cli.option_defaults()->group("Gaze and adaptivity");
  cli.add_option("--camera-source", sim.camera_source,
                 "viewer_id whose camera pose drives the gaze projection (default: the most recent pose)");
  // Adaptive settings override the scene's "adaptive" block (defaults shown are the library's); the
  // settings table gives each --gaze-* option its help.
  const sph::AdaptiveConfig defaults;
  const auto gaze_option = [&](const char* flag, const char* key) {
    const sph::ParamSpec& spec = *sph::findParameter(key);
    cli.add_option_function<double>(
           flag, [&o, key](double v) { o.gaze[key] = v; }, fmt::format("{} ({})", spec.description, spec.unit))
        ->default_str(fmt::format("{}", spec.get(defaults)));
  };
  gaze_option("--gaze-radius", "gaze_radius");
  gaze_option("--gaze-ring-radius", "gaze_ring_radius");
  gaze_option("--gaze-stale-s", "gaze_stale_s");
  gaze_option("--gaze-hold-s", "gaze_hold_s");
  cli.add_option("--adaptive", o.adaptive,
                 "KEY=VALUE, an adaptive setting over the scene file's (listed below); repeatable");
  cli.option_defaults()->group("Scene and physics");
  cli.add_option("--levels", o.levels,
                 "size levels (the parameter 'levels': L0 the finest to L(N - 1)); the same as --param levels=N")
      ->check(cli::range(sph::kMinLevels, sph::kMaxLevels));
  cli.add_option("--param", o.params,
                 "KEY=VALUE, a simulation parameter over the preset's and the scene file's (listed below); "
                 "repeatable");
  cli.footer(
      "Simulation parameters (--param KEY=VALUE, set_parameters; defaults by preset: sph_bench "
      "--parameter-table):\n" +
      sph::parameterHelpText(false) +
      "\nAdaptive settings (--adaptive KEY=VALUE, set_parameters; a scene file's \"adaptive\"; defaults: sph_bench "
      "--parameter-table):\n" +
      sph::parameterHelpText(true) + "\n" + cli.get_footer());
  cli.option_defaults()->group("Security");
  curve::addServerOptions(cli, o.curve);
  cli.option_defaults()->group("Network");
  cli.add_option("--max-peers", o.max_peers,
                 "connections each socket takes at a time (fewer when the descriptor limit asks)")
      ->check(cli::range(1, 100000))
      ->capture_default_str();
  cli.option_defaults()->group("Logging");
  cli.add_option("--status-interval", sim.status_interval_s, "seconds between status lines (0: off)")
      ->check(cli::range(0, 86400))
      ->capture_default_str();
  cli.add_option("--log-level", o.log_level, "trace, debug, info, warn, error")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}))
      ->capture_default_str();
}

}  // namespace

int main(int argc, char** argv) {
  process::applyDefaultOmpWaitPolicy(argv);  // first: it may re-execute the program
  CLI::App cli{"sph_server: gaze-adaptive SPH water over ZeroMQ (frames PUB, gaze, camera pose, control)"};
  cli::prepare(cli, "sph_server");
  CliOptions o;
  addOptions(cli, o);
  if (auto code = cli::parse(cli, argc, argv)) return *code;
  spdlog::set_level(spdlog::level::from_str(o.log_level));
  cli::logToStderr();  // stdout stays free for data; every log line and error goes to stderr
  if (o.server.sim.preset == "scene") o.server.sim.preset.clear();

  o.server.sim.realtime_governor = o.realtime == "on";
  if (!o.method.empty()) {
    sph::Method m;
    sph::methodByName(o.method, m);  // checked by CLI11
    o.server.sim.method = m;
  }
  // Either option takes any setting of the table; where it goes is the table's.
  std::map<std::string, double> settings = o.gaze;
  if (o.levels != 0) settings["levels"] = o.levels;
  for (const auto& [option, given] : {std::pair{"--adaptive", &o.adaptive}, std::pair{"--param", &o.params}}) {
    for (const std::string& setting : *given) {
      std::string error;
      if (!sph::parseParameterSetting(setting, settings, error)) {
        return cli::usageError(cli, std::string(option) + " " + setting + ": " + error);
      }
    }
  }
  for (const auto& [key, value] : settings) {
    if (sph::findParameter(key)->isAdaptive()) {
      o.server.sim.adaptive_overrides[key] = value;
    } else {
      o.server.sim.sim_parameters[key] = value;
    }
  }
  net::inputSocketTypeByName(o.gaze_socket, o.server.net.gaze_type);
  net::inputSocketTypeByName(o.pose_socket, o.server.net.pose_type);

  const net::Endpoints& wanted = o.server.net.endpoints;
  try {
    curve::ServerSecurity security =
        curve::loadServerSecurity(o.curve, {wanted.frames, wanted.gaze, wanted.pose, wanted.control});
    o.server.net.curve = std::move(security.own);
    o.server.curve_clients = std::move(security.clients);
    o.server.sim.insecure = security.insecure;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return curve::exitCodeFor(e);
  }
  // Every peer holds a descriptor: take all the system allows, and leave room for the rest.
  const net::FileLimit fds = net::raiseFileLimit();
  o.server.net.fd_limit = fds.now;
  o.server.net.max_peers = net::peersPerSocket(fds.now, 4, o.max_peers);

  // Before any thread starts (libzmq's included): shutdown runs here, not in a signal handler.
  process::StopSignals stop_signals;

  try {
    app::Server server(o.server);
    const net::Endpoints& ep = server.endpoints();
    spdlog::info("endpoint frames {}", ep.frames);
    spdlog::info("endpoint gaze {}", ep.gaze);
    spdlog::info("endpoint pose {}", ep.pose);
    spdlog::info("endpoint control {}", ep.control);
    spdlog::info("file descriptors: limit {} (was {}), up to {} peers per socket", fds.now, fds.before,
                 o.server.net.max_peers);
    if (o.server.net.curve) {
      spdlog::info("CURVE on every socket: {} client keys allowed", o.server.curve_clients.size());
    } else if (o.server.sim.insecure) {
      spdlog::warn(
          "INSECURE: bound beyond loopback without CURVE (--insecure): anyone who reaches these ports "
          "may watch and control the simulation");
    }
    server.start();
    int signal = 0;
    while (!server.finished() && (signal = stop_signals.wait(std::chrono::milliseconds(100))) == 0) {
    }
    if (signal > 0) spdlog::info("{} received, shutting down", process::StopSignals::name(signal));
    server.stop();
    spdlog::info("final status: {}", server.statusLine());
    if (!server.stateSaved()) return 1;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
  return 0;
}
