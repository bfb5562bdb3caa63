// gaze_bridge: reads a gaze source, filters, and streams GazeSample messages to sph_server.
// See README.md in this folder for every option.
#include <spdlog/spdlog.h>

#include <atomic>
#include <csignal>
#include <exception>

#include "bridge_options.h"
#include "cli/cli_conventions.h"
#include "gaze/gaze_recording.h"
#include "net/curve_cli.h"

namespace {

std::atomic<bool> g_stop{false};

extern "C" void onSignal(int) { g_stop.store(true); }

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"gaze_bridge: streams screen-space gaze (normalized 0..1, origin top-left) to sph_server"};
  gaze_bridge::BridgeOptions options;
  cli::prepare(app, "gaze_bridge", "3 a tracker (--source pupil or gazepoint) never sent a sample");
  gaze_bridge::addBridgeOptions(app, options);
  if (auto code = cli::parse(app, argc, argv)) return *code;

  spdlog::set_level(spdlog::level::from_str(options.log_level));
  cli::logToStderr();  // stdout stays free for data; logs and errors go to stderr
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);

  try {
    gaze_bridge::finishBridgeOptions(options);
  } catch (const std::exception& error) {
    // A key file it cannot use is a failed run; anything else here is options that do not go together.
    if (curve::exitCodeFor(error) == cli::kExitFailure) {
      spdlog::error("gaze_bridge: {}", error.what());
      return cli::kExitFailure;
    }
    return cli::usageError(app, error.what());
  }
  try {
    zmq::context_t context(1);
    gaze_bridge::GazeBridge bridge(context, gaze_bridge::makeSource(context, options), options.bridge);
    spdlog::info("gaze_bridge: source {}, sending to {} ({}){}", options.source, options.bridge.publisher.endpoint,
                 options.socket,
                 options.bridge.record_path.empty() ? "" : ", recording to " + options.bridge.record_path);
    bridge.run(g_stop, options.duration_s);
    const auto& c = bridge.counters();
    spdlog::info("gaze_bridge: stopped; {} tracker samples, {} sent, {} lost notices, {} send drops", c.tracker_samples,
                 c.sent, c.lost_sent, c.send_dropped);
    // A named tracker that never delivered is a failed run, not a quiet one (run_main.sh reports it).
    if (c.tracker_samples == 0 && (options.source == "pupil" || options.source == "gazepoint")) {
      spdlog::error("gaze_bridge: the {} tracker never sent a sample (never connected); exit code 3", options.source);
      return 3;
    }
  } catch (const std::exception& error) {
    spdlog::error("gaze_bridge: {}", error.what());
    return 1;
  }
  return 0;
}
