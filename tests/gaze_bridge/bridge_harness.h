// Test plumbing: a receiver standing in for sph_server's gaze socket (binds tcp://127.0.0.1:*), and a
// bridge running its loop on its own thread.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <thread>
#include <zmq.hpp>

#include "bridge.h"
#include "proto/sph.pb.h"

namespace gaze_bridge_test {

// How long a test waits for something that must happen: generous, so that a machine three times
// slower, or a busy one, still gets there (a passing test never waits it out).
inline constexpr std::chrono::seconds kWait{30};

class GazeReceiver {
 public:
  GazeReceiver(zmq::context_t& context, zmq::socket_type type = zmq::socket_type::sub) : socket_(context, type) {
    socket_.set(zmq::sockopt::linger, 0);
    if (type == zmq::socket_type::sub) socket_.set(zmq::sockopt::subscribe, "");
    socket_.bind("tcp://127.0.0.1:*");
    endpoint_ = socket_.get(zmq::sockopt::last_endpoint);
  }
  const std::string& endpoint() const { return endpoint_; }

  // The next sample within timeout, parsed; nullopt on timeout.
  std::optional<gsph::v1::GazeSample> receive(std::chrono::milliseconds timeout = kWait) {
    zmq::pollitem_t item{socket_.handle(), 0, ZMQ_POLLIN, 0};
    zmq::poll(&item, 1, timeout);
    if (!(item.revents & ZMQ_POLLIN)) return std::nullopt;
    zmq::message_t message;
    if (!socket_.recv(message, zmq::recv_flags::dontwait)) return std::nullopt;
    gsph::v1::GazeSample sample;
    if (!sample.ParseFromArray(message.data(), static_cast<int>(message.size()))) return std::nullopt;
    return sample;
  }

  // Receives until `match` accepts a sample or timeout passes overall.
  std::optional<gsph::v1::GazeSample> receiveUntil(const std::function<bool(const gsph::v1::GazeSample&)>& match,
                                                   std::chrono::milliseconds timeout = kWait) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      auto sample = receive(std::max(left, std::chrono::milliseconds(1)));
      if (sample && match(*sample)) return sample;
    }
    return std::nullopt;
  }

 private:
  zmq::socket_t socket_;
  std::string endpoint_;
};

class BridgeThread {
 public:
  BridgeThread(zmq::context_t& context, std::unique_ptr<gaze_bridge::GazeSource> source,
               const gaze_bridge::BridgeParams& params)
      : bridge_(context, std::move(source), params) {
    thread_ = std::thread([this] { bridge_.run(stop_); });
  }
  ~BridgeThread() { stop(); }
  void stop() {
    stop_.store(true);
    if (thread_.joinable()) thread_.join();
  }
  // Read only after stop().
  const gaze_bridge::GazeBridge& bridge() const { return bridge_; }

 private:
  gaze_bridge::GazeBridge bridge_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// Unfiltered, so received points equal the tracker's (as float); lost notices far apart.
inline gaze_bridge::BridgeParams rawParams(const std::string& endpoint) {
  gaze_bridge::BridgeParams params;
  params.publisher.endpoint = endpoint;
  params.processor.filter = false;
  params.processor.max_gap_s = 0.5;
  params.processor.lost_repeat_s = 5.0;
  return params;
}

}  // namespace gaze_bridge_test
