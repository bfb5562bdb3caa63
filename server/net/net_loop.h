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
#include <cstdint>
#include <string>
#include <thread>
#include <vector>
#include <zmq.hpp>

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
};

struct NetCounters {
  std::atomic<std::int64_t> subscriptions{0};  // current frame subscriptions (XPUB verboser)
  std::atomic<std::uint64_t> frames_sent{0};
  std::atomic<std::uint64_t> gaze_samples{0};   // usable samples received
  std::atomic<std::uint64_t> gaze_no_point{0};  // valid = false or lost: the last point ages
  std::atomic<std::uint64_t> poses{0};
  std::atomic<std::uint64_t> control_requests{0};
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
  std::vector<zmq::message_t> parts_;  // scratch for multipart receives
  gsph::v1::GazeSample gaze_msg_;
  gsph::v1::CameraPose pose_msg_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace net
