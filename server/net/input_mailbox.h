// Hand-over from the network thread to the simulation thread. The network thread writes the newest
// gaze sample, the newest camera pose per viewer and queued control requests; the simulation thread
// reads them between steps (and the gaze again just before the adaptive step). The lock guards small
// copies only, never a socket call, so neither thread can make the other wait on the network.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "net/curve_keys.h"
#include "proto/sph.pb.h"
#include "sph/camera.h"

namespace net {

using SteadyTime = std::chrono::steady_clock::time_point;

struct GazeArrival {
  double x = 0.5;
  double y = 0.5;
  float confidence = 0.0f;
  std::uint64_t sequence = 0;
  std::int64_t bridge_time_us = 0;
  std::string source_id;
  SteadyTime arrived{};  // server's steady clock when the network thread received it
};

struct PoseArrival {
  sph::ScreenCamera camera;
  std::string viewer_id;
  std::uint64_t sequence = 0;
  SteadyTime arrived{};
};

// A control request and the ROUTER envelope to answer it on.
struct ControlRequest {
  std::string identity;
  bool has_delimiter = false;                        // REQ peers put an empty frame between identity and payload
  curve::PeerRole role = curve::PeerRole::Operator;  // what the peer's key may do (curve_keys.h)
  gsph::v1::Control control;
};

class InputMailbox {
 public:
  static constexpr std::size_t kMaxViewers = 64;
  static constexpr std::size_t kMaxQueuedControls = 64;

  void putGaze(const GazeArrival& gaze);
  bool latestGaze(GazeArrival& out) const;

  void putPose(const PoseArrival& pose);
  // The pose that drives the gaze projection: the most recent from any viewer when `viewer_id` is
  // empty, else the newest from that viewer. `version` changes whenever any pose arrives.
  bool selectedPose(const std::string& viewer_id, PoseArrival& out) const;
  std::uint64_t poseVersion() const;
  std::size_t viewerCount() const;

  // False (and nothing queued) when kMaxQueuedControls requests already wait.
  bool pushControl(ControlRequest&& request);
  void takeControls(std::vector<ControlRequest>& out);

  // Sleeps until `deadline`, or until a control request or a gaze sample arrives or wake() is called.
  void waitUntil(SteadyTime deadline);
  void wake();

 private:
  mutable std::mutex mutex_;
  std::condition_variable wake_cv_;
  bool woken_ = false;
  bool has_gaze_ = false;
  GazeArrival gaze_;
  std::map<std::string, PoseArrival> poses_;
  std::string newest_viewer_;
  std::uint64_t pose_version_ = 0;
  std::deque<ControlRequest> controls_;
};

}  // namespace net
