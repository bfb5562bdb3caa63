#include "bridge_options.h"

#include <stdexcept>

#include "cli/cli_conventions.h"
#include "net/curve_cli.h"
#include "paced_source.h"

namespace gaze_bridge {

void addBridgeOptions(CLI::App& app, BridgeOptions& o) {
  app.add_option("--source", o.source, "Gaze source: synthetic (default), replay, pupil, gazepoint, tobii")
      ->check(CLI::IsMember({"synthetic", "replay", "pupil", "gazepoint", "tobii"}))
      ->capture_default_str();
  app.add_option("--endpoint", o.bridge.publisher.endpoint, "Server gaze endpoint to connect to")
      ->capture_default_str();
  app.add_option("--socket", o.socket, "pub (server binds SUB) or push (server binds PULL)")
      ->check(CLI::IsMember({"pub", "push"}))
      ->capture_default_str();
  app.add_option("--source-id", o.bridge.source_id, "source_id in every GazeSample (default: the source name)");
  curve::addClientOptions(app, o.curve);

  app.add_option("--pupil-host", o.pupil.host, "Pupil Capture host")->capture_default_str();
  app.add_option("--pupil-port", o.pupil.remote_port, "Pupil Remote port")
      ->check(cli::range(1, 65535))
      ->capture_default_str();
  app.add_option("--pupil-surface", o.pupil.surface, "Surface name (topic surfaces.<name>)")->capture_default_str();
  app.add_option("--gazepoint-host", o.gazepoint.host, "Gazepoint Control host")->capture_default_str();
  app.add_option("--gazepoint-port", o.gazepoint.port, "Open Gaze API port")
      ->check(cli::range(1, 65535))
      ->capture_default_str();
  app.add_option("--tracker-timeout", o.tracker_timeout_s, "Seconds of tracker silence before reconnecting")
      ->check(cli::positive())
      ->capture_default_str();

  app.add_option("--replay", o.replay_path, "Gaze recording to replay (with --source replay)");
  app.add_option("--replay-speed", o.replay_speed, "Replay speed factor (1 = as recorded)")
      ->check(cli::positive())
      ->capture_default_str();
  app.add_flag("--replay-once", o.replay_once, "Stop at the end of the recording instead of looping");

  app.add_option("--synthetic-seed", o.synthetic.seed, "Seed of the synthetic fixation/saccade model")
      ->capture_default_str();
  app.add_option("--synthetic-rate", o.synthetic.rate_hz, "Synthetic samples per second")
      ->check(cli::positive())
      ->capture_default_str();
  app.add_option("--synthetic-blink", o.synthetic.blink_probability, "Chance per fixation of a blink")
      ->check(cli::range(0, 1))
      ->capture_default_str();

  auto& p = o.bridge.processor;
  app.add_option("--min-confidence", p.min_confidence, "Drop samples below this confidence")
      ->check(cli::range(0, 1))
      ->capture_default_str();
  app.add_option("--max-gap", p.max_gap_s, "Gaps up to this many seconds are bridged; longer ones send 'lost'")
      ->check(cli::positive())
      ->capture_default_str();
  app.add_option("--lost-repeat", p.lost_repeat_s, "Re-send 'lost' every this many seconds while it lasts")
      ->check(cli::positive())
      ->capture_default_str();
  app.add_flag("--no-filter", o.no_filter, "Send raw points (no One Euro filter)");
  app.add_option("--mincutoff", p.one_euro.min_cutoff_hz, "One Euro minimum cutoff, Hz")
      ->check(cli::positive())
      ->capture_default_str();
  app.add_option("--beta", p.one_euro.beta, "One Euro speed coefficient, per screen unit/s")
      ->check(cli::nonNegative())
      ->capture_default_str();
  app.add_option("--dcutoff", p.one_euro.d_cutoff_hz, "One Euro derivative cutoff, Hz")
      ->check(cli::positive())
      ->capture_default_str();
  app.add_flag("--ivt", p.ivt, "Compute the I-VT fixation flag");
  app.add_option("--ivt-threshold", p.ivt_threshold, "I-VT speed threshold, screen widths/s")
      ->check(cli::positive())
      ->capture_default_str();
  app.add_option("--screen-aspect", p.screen_aspect, "Screen width / height (for I-VT speeds)")
      ->check(cli::positive())
      ->capture_default_str();

  app.add_option("--record", o.bridge.record_path, "Write every sent sample to this gaze recording (CSV)");
  app.add_option("--stats-interval", o.bridge.stats_interval_s, "Seconds between status lines")
      ->check(cli::positive())
      ->capture_default_str();
  app.add_option("--duration", o.duration_s, "Stop after this many seconds (0: run until SIGINT/SIGTERM)")
      ->check(cli::nonNegative())
      ->capture_default_str();
  app.add_option("--log-level", o.log_level, "trace, debug, info, warn, error, off")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}))
      ->capture_default_str();
}

void finishBridgeOptions(BridgeOptions& o) {
  o.bridge.publisher.socket = o.socket == "push" ? PublisherSocket::kPush : PublisherSocket::kPub;
  o.bridge.processor.filter = !o.no_filter;
  o.pupil.tracker_timeout_s = o.tracker_timeout_s;
  o.gazepoint.tracker_timeout_s = o.tracker_timeout_s;
  if (o.source == "replay" && o.replay_path.empty()) throw std::invalid_argument("--source replay needs --replay FILE");
  if (o.source != "replay" && !o.replay_path.empty()) {
    throw std::invalid_argument("--replay FILE is only used with --source replay");
  }
  o.bridge.publisher.curve = curve::loadClientFiles(o.curve);  // throws for a missing or bad file
  validateProcessorParams(o.bridge.processor);
  gaze::validateFixationModelParams(o.synthetic);
}

std::unique_ptr<GazeSource> makeSource(zmq::context_t& context, const BridgeOptions& o) {
  if (o.source == "synthetic") return std::make_unique<SyntheticSource>(o.synthetic);
  if (o.source == "replay") return std::make_unique<ReplaySource>(o.replay_path, o.replay_speed, !o.replay_once);
  if (o.source == "pupil") return std::make_unique<PupilSource>(context, o.pupil);
  if (o.source == "gazepoint") return std::make_unique<GazepointSource>(o.gazepoint);
  if (o.source == "tobii") {
    throw std::invalid_argument(
        "--source tobii: this build has no Tobii Stream Engine adapter (proprietary SDK); see "
        "gaze_bridge/tobii_source.h for the extension point");
  }
  throw std::invalid_argument("unknown source '" + o.source + "'");
}

}  // namespace gaze_bridge
