// Gazepoint trackers through the Open Gaze API (TCP, default port 4242): connect, send the SET commands
// (open_gaze_parser.h), read REC records. Connection loss, a refused connect or a tracker that falls
// silent for tracker_timeout_s leads to a reconnect with back-off (0.1 s doubling to 2 s).
#pragma once

#include <cstdint>
#include <string>

#include "gaze_source.h"
#include "open_gaze_parser.h"

namespace gaze_bridge {

struct GazepointParams {
  std::string host = "127.0.0.1";
  int port = 4242;
  double tracker_timeout_s = 2.0;  // silence after which the connection is considered dead
};

class GazepointSource : public GazeSource {
 public:
  explicit GazepointSource(const GazepointParams& params);
  ~GazepointSource() override;
  GazepointSource(const GazepointSource&) = delete;
  GazepointSource& operator=(const GazepointSource&) = delete;

  std::string id() const override { return "gazepoint"; }
  void poll(std::vector<TrackerSample>& out, int timeout_ms) override;
  bool connected() const override { return state_ == State::kStreaming; }

  std::uint64_t connects() const { return connects_; }
  std::uint64_t malformed() const { return malformed_; }

 private:
  enum class State { kIdle, kConnecting, kStreaming };
  void startConnect();
  void finishConnect(int timeout_ms);
  void readRecords(std::vector<TrackerSample>& out, int timeout_ms);
  void disconnect(const std::string& why);
  bool sendAll(const std::string& text);

  GazepointParams params_;
  State state_ = State::kIdle;
  int fd_ = -1;
  std::int64_t next_attempt_ns_ = 0;
  std::int64_t backoff_ns_ = 100'000'000;
  std::int64_t connect_started_ns_ = 0;
  std::int64_t last_data_ns_ = 0;
  OpenGazeLineSplitter splitter_;
  OpenGazeTag tag_;
  std::string line_;
  std::uint64_t connects_ = 0;
  std::uint64_t malformed_ = 0;
  bool logged_refused_ = false;
};

}  // namespace gaze_bridge
