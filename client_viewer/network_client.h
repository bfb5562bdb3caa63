// All of the viewer's sockets, owned by one network thread so rendering never blocks on I/O:
//   frames  SUB with a short queue drained to its newest frame (only that one is decoded), here;
//   pose    PUB, the latest CameraPose, sent on every change and re-sent every kPoseResend;
//   gaze    PUB, mouse gaze samples when --mouse-gaze is on;
//   control DEALER, Control requests with replies (ROUTER on the server).
// Every socket connects (the server binds), so ZeroMQ reconnects by itself after a server restart.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "decoded_frame.h"
#include "net/curve_sockets.h"
#include "proto/sph.pb.h"

namespace viewer {

struct Endpoints {
  std::string frames = "tcp://127.0.0.1:5555";
  std::string gaze = "tcp://127.0.0.1:5556";
  std::string pose = "tcp://127.0.0.1:5557";
  std::string control = "tcp://127.0.0.1:5558";
  // CURVE keys for every socket (--curve-secret, --curve-server); none: plaintext.
  std::optional<curve::ClientKeys> curve;
};

struct PoseData {
  std::array<float, 16> view{};        // column-major
  std::array<float, 16> projection{};  // column-major
  std::uint32_t viewport_width = 0;
  std::uint32_t viewport_height = 0;
  bool operator==(const PoseData&) const = default;
};

struct NetworkStats {
  std::uint64_t frames_received = 0;  // decoded successfully
  std::uint64_t frames_skipped = 0;   // sequence gaps: dropped by PUB or passed over for a newer one
  std::uint64_t frames_rejected = 0;  // did not parse or decode
  std::uint64_t server_restarts = 0;  // sequence went backwards
  std::uint64_t poses_sent = 0;
  std::uint64_t gaze_sent = 0;
  std::uint64_t control_timeouts = 0;
  std::string last_error;  // the latest rejected frame's reason
  std::optional<std::chrono::steady_clock::time_point> last_frame_arrival;
};

class NetworkClient {
 public:
  static constexpr auto kPoseResend = std::chrono::milliseconds(50);  // >= 10 Hz with margin
  static constexpr auto kControlTimeout = std::chrono::seconds(3);
  static constexpr auto kStatusInterval = std::chrono::seconds(2);

  NetworkClient(Endpoints endpoints, std::string viewer_id);
  ~NetworkClient();
  NetworkClient(const NetworkClient&) = delete;
  NetworkClient& operator=(const NetworkClient&) = delete;

  // Throws zmq::error_t when an endpoint is malformed (before any thread starts).
  void start();
  void stop();

  // Render thread -> network thread. Latest value wins; nothing queues up.
  void setPose(const PoseData& pose);
  void setGaze(float x, float y, bool valid);
  // How long a request waits for its reply before it fails (kControlTimeout unless set): a study
  // waits out scene restarts, which take seconds for a big scene.
  void setControlTimeout(std::chrono::milliseconds timeout);
  // Queues a request (at most a few; the oldest is dropped); returns the request_id it was given.
  std::uint64_t sendControl(gsph::v1::Control request);

  // Network thread -> render thread.
  std::shared_ptr<const DecodedFrame> takeNewestFrame();  // nullptr when nothing new arrived
  std::optional<gsph::v1::ControlReply> takeReply();
  std::optional<gsph::v1::ServerStatus> latestStatus() const;
  NetworkStats stats() const;

 private:
  void run();
  struct Sockets;
  void receiveFrames(Sockets& sockets);
  void receiveReplies(Sockets& sockets);
  void sendOutgoing(Sockets& sockets, std::chrono::steady_clock::time_point now);

  Endpoints endpoints_;
  std::string viewer_id_;
  std::unique_ptr<Sockets> sockets_;
  std::thread thread_;
  std::atomic<bool> running_{false};

  mutable std::mutex mutex_;  // guards everything below
  std::shared_ptr<const DecodedFrame> newest_frame_;
  std::optional<PoseData> pose_;
  bool pose_dirty_ = false;
  struct GazeState {
    float x = 0.0f;
    float y = 0.0f;
    bool valid = false;
  };
  std::optional<GazeState> gaze_;
  std::deque<gsph::v1::Control> outgoing_control_;
  std::deque<gsph::v1::ControlReply> replies_;
  std::optional<gsph::v1::ServerStatus> status_;
  NetworkStats stats_;
  std::uint64_t next_request_id_ = 1;
  std::chrono::milliseconds control_timeout_{kControlTimeout};
};

}  // namespace viewer
