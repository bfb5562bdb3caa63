// Sends GazeSample messages (proto/sph.proto, single-part, no topic frame) to the server's gaze
// endpoint. The server binds; the bridge connects, so either side may restart: libzmq reconnects a
// connecting socket by itself (every 100 ms, backing off to 1 s), and heartbeats notice a dead server.
// PUB (default) pairs with a SUB bind on the server, PUSH with a PULL bind. Sending never blocks: a
// sample that cannot go out now is dropped and counted (old gaze is worthless).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <zmq.hpp>

#include "gaze_processor.h"
#include "net/curve_sockets.h"
#include "proto/sph.pb.h"

namespace gaze_bridge {

enum class PublisherSocket { kPub, kPush };

struct PublisherParams {
  std::string endpoint = "tcp://127.0.0.1:5556";
  PublisherSocket socket = PublisherSocket::kPub;
  std::optional<curve::ClientKeys> curve;  // --curve-secret, --curve-server; none: plaintext
};

class GazePublisher {
 public:
  // Throws std::runtime_error when the endpoint is malformed (zmq refuses to connect to it).
  GazePublisher(zmq::context_t& context, const PublisherParams& params, std::string source_id);

  // Stamps sequence and bridge_time_us (system clock now) and sends. Returns false when dropped.
  // bridge_time_us receives the stamp.
  bool send(const ProcessedSample& sample, std::int64_t& bridge_time_us);

  std::uint64_t sent() const { return sent_; }
  std::uint64_t dropped() const { return dropped_; }

 private:
  zmq::socket_t socket_;
  gsph::v1::GazeSample message_;  // reused: no allocation per sample
  std::string buffer_;
  std::uint64_t sequence_ = 0;
  std::uint64_t sent_ = 0;
  std::uint64_t dropped_ = 0;
};

}  // namespace gaze_bridge
