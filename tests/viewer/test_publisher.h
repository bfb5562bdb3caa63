// A stand-in server for the viewer tests: binds the four sockets the viewer connects to on
// ephemeral loopback ports, publishes a given Frame over and over (new sequence each time, and sim
// time 10 ms a sequence number, as makeFrame sets them), and collects the CameraPoses and
// GazeSamples that arrive.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>
#include <zmq.hpp>

#include "proto/sph.pb.h"

namespace viewer_test {

class TestServer {
 public:
  // `frames_endpoint` empty: bind tcp://127.0.0.1:*; otherwise bind exactly there (restart tests).
  // Publishes at most `max_frames` frames in all.
  explicit TestServer(gsph::v1::Frame frame, const std::string& frames_endpoint = "", std::uint64_t first_sequence = 1,
                      std::chrono::milliseconds publish_period = std::chrono::milliseconds(20),
                      std::uint64_t max_frames = UINT64_MAX);
  ~TestServer();

  std::string framesEndpoint() const { return frames_endpoint_; }
  std::string poseEndpoint() const { return pose_endpoint_; }
  std::string gazeEndpoint() const { return gaze_endpoint_; }
  std::string controlEndpoint() const { return control_endpoint_; }
  // The viewer's arguments for all four endpoints.
  std::vector<std::string> endpointArgs() const;

  // Waits (polling, bounded) until `predicate` holds for the received messages.
  bool waitForPose(const std::function<bool(const gsph::v1::CameraPose&)>& predicate, std::chrono::milliseconds timeout,
                   gsph::v1::CameraPose* out = nullptr);
  bool waitForGaze(const std::function<bool(const gsph::v1::GazeSample&)>& predicate, std::chrono::milliseconds timeout,
                   gsph::v1::GazeSample* out = nullptr);
  bool subscribed() const { return subscribed_; }
  std::size_t posesReceived() const;
  void replaceFrame(gsph::v1::Frame frame);
  std::vector<gsph::v1::Control> controlsReceived() const;

 private:
  void run();
  zmq::context_t context_{1};
  zmq::socket_t frames_{context_, zmq::socket_type::xpub};
  zmq::socket_t pose_{context_, zmq::socket_type::sub};
  zmq::socket_t gaze_{context_, zmq::socket_type::sub};
  zmq::socket_t control_{context_, zmq::socket_type::router};
  std::string frames_endpoint_, pose_endpoint_, gaze_endpoint_, control_endpoint_;
  std::atomic<bool> running_{true};
  std::atomic<bool> subscribed_{false};
  mutable std::mutex mutex_;
  gsph::v1::Frame frame_;
  std::uint64_t sequence_;
  std::chrono::milliseconds publish_period_;
  std::uint64_t frames_left_;
  std::vector<gsph::v1::CameraPose> poses_;
  std::vector<gsph::v1::GazeSample> gaze_samples_;
  std::vector<gsph::v1::Control> controls_;
  std::thread thread_;
};

}  // namespace viewer_test
