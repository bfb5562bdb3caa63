// Pupil Capture through its network API: ask Pupil Remote (REQ, default port 50020) for "SUB_PORT",
// subscribe to "surfaces.<surface>" on that port, decode each message's gaze_on_surfaces
// (pupil_decode.h). When Capture stops answering or the stream falls silent for tracker_timeout_s, the
// source asks Pupil Remote again (Capture may come back on another SUB port), with back-off.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <zmq.hpp>

#include "gaze_source.h"

namespace gaze_bridge {

struct PupilParams {
  std::string host = "127.0.0.1";
  int remote_port = 50020;
  std::string surface = "screen";
  double tracker_timeout_s = 2.0;
};

class PupilSource : public GazeSource {
 public:
  PupilSource(zmq::context_t& context, const PupilParams& params);
  std::string id() const override { return "pupil"; }
  void poll(std::vector<TrackerSample>& out, int timeout_ms) override;
  bool connected() const override { return state_ == State::kStreaming && receiving_; }

  std::uint64_t subscriptions() const { return subscriptions_; }
  std::uint64_t malformed() const { return malformed_; }

 private:
  enum class State { kIdle, kAwaitingPort, kStreaming };
  void askPort();
  void awaitPort(int timeout_ms);
  void receive(std::vector<TrackerSample>& out, int timeout_ms);
  void restart(const std::string& why);

  zmq::context_t& context_;
  PupilParams params_;
  std::string topic_;
  State state_ = State::kIdle;
  std::unique_ptr<zmq::socket_t> remote_;  // REQ, recreated per attempt (a REQ wedges on a lost reply)
  std::unique_ptr<zmq::socket_t> sub_;
  std::int64_t next_attempt_ns_ = 0;
  std::int64_t backoff_ns_ = 100'000'000;
  std::int64_t request_sent_ns_ = 0;
  std::int64_t last_data_ns_ = 0;
  bool receiving_ = false;
  bool logged_unreachable_ = false;
  std::uint64_t subscriptions_ = 0;
  std::uint64_t malformed_ = 0;
};

}  // namespace gaze_bridge
