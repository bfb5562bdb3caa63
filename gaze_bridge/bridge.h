// The bridge's loop: poll the source, process each sample, publish, record, report lost gaze, and
// log rate, validity and latency once per stats interval. Single-threaded: one loop owns every socket.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <zmq.hpp>

#include "gaze_processor.h"
#include "gaze_publisher.h"
#include "gaze_recorder.h"
#include "gaze_source.h"

namespace gaze_bridge {

struct BridgeParams {
  ProcessorParams processor;
  PublisherParams publisher;
  std::string source_id;    // empty: the source's own id()
  std::string record_path;  // empty: no recording
  double stats_interval_s = 1.0;
};

struct BridgeCounters {
  std::uint64_t tracker_samples = 0;
  std::uint64_t sent = 0;  // includes lost samples
  std::uint64_t send_dropped = 0;
  std::uint64_t lost_sent = 0;
};

class GazeBridge {
 public:
  // Throws std::invalid_argument / std::runtime_error for bad parameters, endpoint or record path.
  GazeBridge(zmq::context_t& context, std::unique_ptr<GazeSource> source, const BridgeParams& params);

  // One turn of the loop, waiting at most max_wait_ms for the source.
  void runOnce(int max_wait_ms);
  // Turns until `stop` is set, the source is finished, or duration_s (> 0) has passed.
  void run(const std::atomic<bool>& stop, double duration_s = 0.0);

  const BridgeCounters& counters() const { return counters_; }
  const ProcessorCounters& processorCounters() const { return processor_.counters(); }
  const GazeSource& source() const { return *source_; }
  // When set, every sent tracker sample's added latency (arrival to send, ns) is appended (benchmarks).
  void setLatencyLog(std::vector<std::int64_t>* log) { latency_log_ = log; }

 private:
  void sendSample(const ProcessedSample& sample);
  void logStats(std::int64_t now_ns);

  std::unique_ptr<GazeSource> source_;
  BridgeParams params_;
  GazeProcessor processor_;
  GazePublisher publisher_;
  std::unique_ptr<GazeRecorder> recorder_;
  BridgeCounters counters_;
  std::vector<TrackerSample> incoming_;
  std::vector<std::int64_t> interval_latencies_ns_;
  std::vector<std::int64_t>* latency_log_ = nullptr;
  std::int64_t stats_started_ns_;
  BridgeCounters stats_base_;
  ProcessorCounters processor_base_;
};

}  // namespace gaze_bridge
