// The network thread: one poll loop owns every external socket (zguide style) and two inproc pipes
// from the simulation thread.
//
// Why this split: the simulation thread must never wait on the network, and ZeroMQ sockets must not be
// shared between threads. So the simulation thread owns only two inproc PAIR sockets and sends on them
// without blocking (a full pipe drops the frame and counts it); this thread owns the frame XPUB, the
// gaze and camera pose inputs and the control ROUTER. Inputs reach the simulation through the
// InputMailbox (newest gaze, newest pose per viewer, a bounded control queue), frames and control
// replies come back through the pipes. A slow, stalled or vanished peer can at worst fill its own
// bounded libzmq queue; PUB drops at the high-water mark and ROUTER drops unroutable replies, so
// nothing here blocks either.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>
#include <zmq.hpp>

#include "net/connection_monitor.h"
#include "net/curve_keys.h"
#include "net/frame_subscriptions.h"
#include "net/input_mailbox.h"
#include "net/rejection_log.h"
#include "net/socket_setup.h"

namespace net {

struct Endpoints {
  std::string frames = "tcp://127.0.0.1:5555";   // XPUB: frames out, subscriptions in
  std::string gaze = "tcp://127.0.0.1:5556";     // SUB or PULL: GazeSample in
  std::string pose = "tcp://127.0.0.1:5557";     // SUB or PULL: CameraPose in
  std::string control = "tcp://127.0.0.1:5558";  // ROUTER: Control in, ControlReply out
};

// Senders connect PUB (SUB here, subscribed to everything) or PUSH (PULL here).
enum class InputSocketType { Sub, Pull };
bool inputSocketTypeByName(const std::string& name, InputSocketType& out);

struct NetConfig {
  Endpoints endpoints;
  InputSocketType gaze_type = InputSocketType::Sub;
  InputSocketType pose_type = InputSocketType::Sub;
  int frame_hwm = kFrameSendHwm;
  // CURVE on every socket: the server's certificate, secret key included. The ZAP handler
  // that judges client keys belongs to the context's owner (app::Server). None: plaintext, and every
  // peer may do everything, as on a server that only loopback reaches.
  std::optional<curve::Certificate> curve;
  // Connections each bound socket takes at a time (connection_monitor.h); more are dropped as they
  // come, so peers cannot use up the process's descriptors. `fd_limit` is quoted when accepting fails.
  int max_peers = kDefaultMaxPeers;
  int fd_limit = 0;
  std::chrono::milliseconds log_interval{1000};  // refused connections and handshakes
};

struct NetCounters {
  // Frame subscribers: subscriptions to "" held, at most the connections the frames socket has.
  std::atomic<std::int64_t> subscriptions{0};
  std::atomic<std::uint64_t> frames_sent{0};
  std::atomic<std::uint64_t> gaze_samples{0};   // usable samples received
  std::atomic<std::uint64_t> gaze_no_point{0};  // valid = false or lost: the last point ages
  std::atomic<std::uint64_t> poses{0};
  std::atomic<std::uint64_t> control_requests{0};
  std::atomic<std::uint64_t> peers_dropped{0};       // over a socket's limit, or holding refused subscriptions
  std::atomic<std::uint64_t> accept_failures{0};     // accept(2) failed (EMFILE: no descriptors left)
  std::atomic<std::uint64_t> handshake_failures{0};  // no CURVE, a refused key, not ZeroMQ
};

class NetLoop {
 public:
  // Creates and binds every socket in the calling thread (so a bind error surfaces here); the loop
  // takes them over in start().
  NetLoop(zmq::context_t& context, const NetConfig& config, InputMailbox& mailbox, RejectionLog& rejections);
  ~NetLoop();
  NetLoop(const NetLoop&) = delete;
  NetLoop& operator=(const NetLoop&) = delete;

  const Endpoints& bound() const { return bound_; }
  // The simulation thread connects a PAIR to each and sends frames / control replies.
  const std::string& framePipe() const { return frame_pipe_endpoint_; }
  const std::string& replyPipe() const { return reply_pipe_endpoint_; }
  const NetCounters& counters() const { return counters_; }

  void start();
  void stop();  // joins; the sockets close with linger 0

 private:
  void run();
  void drainSubscriptions();
  void drainGaze();
  void drainPoses();
  void drainControl();
  void forwardFrames();
  void forwardReplies();
  void replyError(const std::string& identity, bool delimiter, std::uint64_t request_id, gsph::v1::ErrorCode code,
                  const std::string& error);
  void drainMonitors();
  void dropSubscriptionHoarders();
  // The role of the peer `message` came from: its key's role with CURVE, else operator.
  curve::PeerRole roleOf(const zmq::message_t& message) const;

  InputMailbox& mailbox_;
  RejectionLog& rejections_;
  NetCounters counters_;
  Endpoints bound_;
  std::string frame_pipe_endpoint_;
  std::string reply_pipe_endpoint_;
  zmq::socket_t frames_;
  zmq::socket_t gaze_;
  zmq::socket_t pose_;
  zmq::socket_t control_;
  zmq::socket_t frame_pipe_;
  zmq::socket_t reply_pipe_;
  // Declared after the sockets they watch, so they stop before those sockets close.
  std::vector<std::unique_ptr<ConnectionMonitor>> monitors_;  // frames, gaze, pose, control
  FrameSubscriptions subscriptions_;
  bool curve_ = false;
  bool frames_inproc_ = false;
  std::chrono::steady_clock::time_point escalate_after_{};
  LogThrottle hoarder_log_;
  std::vector<zmq::message_t> parts_;  // scratch for multipart receives
  gsph::v1::GazeSample gaze_msg_;
  gsph::v1::CameraPose pose_msg_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace net
