#include "bridge.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gaze_bridge {

namespace {

// The loop wakes at least this often to notice a stop request.
constexpr int kMaxWaitMs = 50;

std::int64_t percentile(std::vector<std::int64_t>& values, double p) {
  if (values.empty()) return 0;
  const auto k = static_cast<std::size_t>(std::ceil(p * static_cast<double>(values.size()))) - (p > 0 ? 1 : 0);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

GazeBridge::GazeBridge(zmq::context_t& context, std::unique_ptr<GazeSource> source, const BridgeParams& params)
    : source_(std::move(source)),
      params_(params),
      processor_(params.processor, steadyNowNs()),
      publisher_(context, params.publisher, params.source_id.empty() ? source_->id() : params.source_id),
      stats_started_ns_(steadyNowNs()) {
  if (!(std::isfinite(params_.stats_interval_s) && params_.stats_interval_s > 0.0)) {
    throw std::invalid_argument("stats interval must be > 0 s");
  }
  if (!params_.record_path.empty()) recorder_ = std::make_unique<GazeRecorder>(params_.record_path);
  incoming_.reserve(256);
  interval_latencies_ns_.reserve(4096);
}

void GazeBridge::sendSample(const ProcessedSample& sample) {
  std::int64_t bridge_time_us = 0;
  const bool sent = publisher_.send(sample, bridge_time_us);
  const std::int64_t sent_ns = steadyNowNs();
  if (sent) {
    ++counters_.sent;
  } else {
    ++counters_.send_dropped;
  }
  if (sample.lost) ++counters_.lost_sent;
  if (sample.valid && sample.arrival_ns != 0) {
    interval_latencies_ns_.push_back(sent_ns - sample.arrival_ns);
    if (latency_log_ != nullptr) latency_log_->push_back(sent_ns - sample.arrival_ns);
  }
  if (recorder_) recorder_->write(sample, sent_ns);
}

void GazeBridge::runOnce(int max_wait_ms) {
  const std::int64_t now = steadyNowNs();
  const std::int64_t to_deadline_ms = (processor_.nextDeadlineNs() - now) / 1'000'000 + 1;
  const int wait = static_cast<int>(std::clamp<std::int64_t>(to_deadline_ms, 0, std::min(max_wait_ms, kMaxWaitMs)));
  incoming_.clear();
  try {
    source_->poll(incoming_, wait);
  } catch (const zmq::error_t& error) {
    if (error.num() != EINTR) throw;  // a signal interrupted the wait: the caller checks its stop flag
  }
  ProcessedSample processed;
  for (const TrackerSample& sample : incoming_) {
    ++counters_.tracker_samples;
    if (processor_.accept(sample, processed)) sendSample(processed);
  }
  const std::int64_t after = steadyNowNs();
  if (processor_.checkLost(after, processed)) sendSample(processed);
  if (after - stats_started_ns_ >= static_cast<std::int64_t>(params_.stats_interval_s * 1e9)) logStats(after);
}

void GazeBridge::logStats(std::int64_t now_ns) {
  const double seconds = static_cast<double>(now_ns - stats_started_ns_) * 1e-9;
  const ProcessorCounters& p = processor_.counters();
  const auto in = p.received - processor_base_.received;
  const auto accepted = p.accepted - processor_base_.accepted;
  const auto sent = counters_.sent - stats_base_.sent;
  const auto dropped = counters_.send_dropped - stats_base_.send_dropped;
  const double valid_percent = in > 0 ? 100.0 * static_cast<double>(accepted) / static_cast<double>(in) : 0.0;
  const std::int64_t p50 = percentile(interval_latencies_ns_, 0.5);
  const std::int64_t p99 = percentile(interval_latencies_ns_, 0.99);
  spdlog::info("{}: {} | in {:.0f}/s, valid {:.0f}%, out {:.0f}/s{}{} | added latency p50 {:.0f} us, p99 {:.0f} us",
               source_->id(), source_->connected() ? "connected" : "NOT connected", static_cast<double>(in) / seconds,
               valid_percent, static_cast<double>(sent) / seconds,
               dropped > 0 ? fmt::format(", {} send drops", dropped) : "", processor_.lost() ? ", gaze LOST" : "",
               static_cast<double>(p50) * 1e-3, static_cast<double>(p99) * 1e-3);
  interval_latencies_ns_.clear();
  stats_started_ns_ = now_ns;
  stats_base_ = counters_;
  processor_base_ = p;
  if (recorder_) recorder_->flush();
}

void GazeBridge::run(const std::atomic<bool>& stop, double duration_s) {
  const std::int64_t end_ns = duration_s > 0.0 ? steadyNowNs() + static_cast<std::int64_t>(duration_s * 1e9) : 0;
  while (!stop.load() && !source_->finished()) {
    if (end_ns != 0 && steadyNowNs() >= end_ns) break;
    runOnce(kMaxWaitMs);
  }
  if (recorder_) recorder_->flush();
}

}  // namespace gaze_bridge
