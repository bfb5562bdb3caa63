// gaze_bridge: reads a gaze source, filters, and streams GazeSample messages to sph_server (issue 5).
// See README.md in this folder for every option.
#include <spdlog/spdlog.h>

#include <atomic>
#include <csignal>
#include <exception>

#include "bridge_options.h"
#include "gaze/gaze_recording.h"

namespace {

std::atomic<bool> g_stop{false};

extern "C" void onSignal(int) { g_stop.store(true); }

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"gaze_bridge: streams screen-space gaze (normalized 0..1, origin top-left) to sph_server"};
  gaze_bridge::BridgeOptions options;
  gaze_bridge::addBridgeOptions(app, options);
  CLI11_PARSE(app, argc, argv);

  spdlog::set_level(spdlog::level::from_str(options.log_level));
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);

  try {
    gaze_bridge::finishBridgeOptions(options);
    zmq::context_t context(1);
    gaze_bridge::GazeBridge bridge(context, gaze_bridge::makeSource(context, options), options.bridge);
    spdlog::info("gaze_bridge: source {}, sending to {} ({}){}", options.source, options.bridge.publisher.endpoint,
                 options.socket,
                 options.bridge.record_path.empty() ? "" : ", recording to " + options.bridge.record_path);
    bridge.run(g_stop, options.duration_s);
    const auto& c = bridge.counters();
    spdlog::info("gaze_bridge: stopped; {} tracker samples, {} sent, {} lost notices, {} send drops", c.tracker_samples,
                 c.sent, c.lost_sent, c.send_dropped);
  } catch (const std::exception& error) {
    spdlog::error("gaze_bridge: {}", error.what());
    return 1;
  }
  return 0;
}
