#include "net/net_loop.h"

#include <spdlog/spdlog.h>

#include <pthread.h>

#include <chrono>
#include <cstring>

#include "net/curve_sockets.h"
#include "net/input_validation.h"

namespace net {
namespace {

// Messages taken from one socket per poll round, so a flood on one input cannot starve the others.
constexpr int kDrainBatch = 512;
constexpr std::size_t kMaxTopicBytes = 64;
constexpr auto kPollTimeout = std::chrono::milliseconds(50);
// After a drop, how long the dropped peer's unsubscriptions may take to come back before the
// refused subscriptions still held count against the others.
constexpr auto kDropSettleTime = std::chrono::seconds(1);

std::atomic<int> next_pipe_id{0};

// Receives one whole message without waiting; false when none is queued. Keeps at most `max_parts`
// parts; `overflow` tells that more arrived (they are read and dropped). The parts of a message
// arrive together, so reading the rest never waits.
bool receiveWhole(zmq::socket_t& socket, std::vector<zmq::message_t>& parts, std::size_t max_parts, bool& overflow) {
  parts.clear();
  overflow = false;
  zmq::message_t first;
  if (!socket.recv(first, zmq::recv_flags::dontwait)) return false;
  bool more = first.more();
  parts.push_back(std::move(first));
  while (more) {
    zmq::message_t next;
    if (!socket.recv(next, zmq::recv_flags::dontwait)) break;
    more = next.more();
    if (parts.size() < max_parts) {
      parts.push_back(std::move(next));
    } else {
      overflow = true;
    }
  }
  return true;
}

// A gaze or pose message is one part (the payload) or two (a topic frame, then the payload), so
// senders may use PUB topics in the Pupil style. Returns nullptr and a reason otherwise.
const zmq::message_t* payloadOf(const std::vector<zmq::message_t>& parts, bool overflow, std::string& reason) {
  if (overflow || parts.size() > 2) {
    reason = "more than two message parts";
    return nullptr;
  }
  if (parts.size() == 2 && parts[0].size() > kMaxTopicBytes) {
    reason = "topic frame longer than " + std::to_string(kMaxTopicBytes) + " bytes";
    return nullptr;
  }
  return &parts.back();
}

zmq::socket_t makeInput(zmq::context_t& context, InputSocketType type) {
  zmq::socket_t s(context, type == InputSocketType::Sub ? zmq::socket_type::sub : zmq::socket_type::pull);
  applyInputOptions(s);
  if (type == InputSocketType::Sub) s.set(zmq::sockopt::subscribe, "");
  return s;
}

}  // namespace

bool inputSocketTypeByName(const std::string& name, InputSocketType& out) {
  if (name == "sub") {
    out = InputSocketType::Sub;
  } else if (name == "pull") {
    out = InputSocketType::Pull;
  } else {
    return false;
  }
  return true;
}

NetLoop::NetLoop(zmq::context_t& context, const NetConfig& config, InputMailbox& mailbox, RejectionLog& rejections)
    : mailbox_(mailbox),
      rejections_(rejections),
      frames_(context, zmq::socket_type::xpub),
      gaze_(makeInput(context, config.gaze_type)),
      pose_(makeInput(context, config.pose_type)),
      control_(context, zmq::socket_type::router),
      frame_pipe_(context, zmq::socket_type::pair),
      reply_pipe_(context, zmq::socket_type::pair),
      subscriptions_(rejections),
      curve_(config.curve.has_value()),
      hoarder_log_(config.log_interval) {
  applyCommonOptions(frames_);
  frames_.set(zmq::sockopt::sndhwm, config.frame_hwm);
  // Subscriptions are input too (frame_subscriptions.h); VERBOSER passes every subscribe and
  // unsubscribe, also those libzmq makes for a peer that disconnects.
  frames_.set(zmq::sockopt::maxmsgsize, static_cast<int64_t>(kMaxSubscriptionBytes));
  frames_.set(zmq::sockopt::rcvhwm, kSubscriptionQueue);
  frames_.set(zmq::sockopt::xpub_verboser, 1);
  applyInputOptions(control_);
  // Replies to a peer whose queue is full or who has gone are dropped rather than waited on.
  control_.set(zmq::sockopt::router_mandatory, 0);
  control_.set(zmq::sockopt::sndhwm, kInputReceiveHwm);

  const std::pair<zmq::socket_t*, const char*> sockets[] = {
      {&frames_, "frames"}, {&gaze_, "gaze"}, {&pose_, "camera pose"}, {&control_, "control"}};
  for (const auto& [socket, role] : sockets) {
    if (config.curve) curve::makeCurveServer(*socket, *config.curve, role);
    // Before bind, so no connection goes unseen.
    monitors_.push_back(std::make_unique<ConnectionMonitor>(context, *socket, role, config.max_peers, config.fd_limit,
                                                            config.log_interval));
  }
  bound_.frames = bindResolved(frames_, config.endpoints.frames, "frames");
  bound_.gaze = bindResolved(gaze_, config.endpoints.gaze, "gaze");
  bound_.pose = bindResolved(pose_, config.endpoints.pose, "camera pose");
  bound_.control = bindResolved(control_, config.endpoints.control, "control");
  frames_inproc_ = bound_.frames.rfind("inproc://", 0) == 0;

  const int id = next_pipe_id.fetch_add(1);
  frame_pipe_endpoint_ = "inproc://sph-frames-" + std::to_string(id);
  reply_pipe_endpoint_ = "inproc://sph-replies-" + std::to_string(id);
  frame_pipe_.set(zmq::sockopt::linger, 0);
  frame_pipe_.set(zmq::sockopt::rcvhwm, 2);
  reply_pipe_.set(zmq::sockopt::linger, 0);
  frame_pipe_.bind(frame_pipe_endpoint_);
  reply_pipe_.bind(reply_pipe_endpoint_);
}

NetLoop::~NetLoop() { stop(); }

void NetLoop::start() {
  stop_ = false;
  thread_ = std::thread([this] { run(); });
}

void NetLoop::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void NetLoop::run() {
  pthread_setname_np(pthread_self(), "sph-net");  // visible in top -H and the benchmark's CPU count
  std::vector<zmq::pollitem_t> items = {
      {frames_.handle(), 0, ZMQ_POLLIN, 0},     {gaze_.handle(), 0, ZMQ_POLLIN, 0},
      {pose_.handle(), 0, ZMQ_POLLIN, 0},       {control_.handle(), 0, ZMQ_POLLIN, 0},
      {frame_pipe_.handle(), 0, ZMQ_POLLIN, 0}, {reply_pipe_.handle(), 0, ZMQ_POLLIN, 0},
  };
  for (const auto& monitor : monitors_) items.push_back({monitor->events().handle(), 0, ZMQ_POLLIN, 0});
  while (!stop_.load(std::memory_order_relaxed)) {
    try {
      zmq::poll(items, kPollTimeout);
      bool monitor_events = false;
      for (std::size_t i = 6; i < items.size(); ++i) monitor_events |= (items[i].revents & ZMQ_POLLIN) != 0;
      if (monitor_events) drainMonitors();
      // Frames first: they are what the latency budget is spent on.
      if (items[4].revents & ZMQ_POLLIN) forwardFrames();
      if (items[1].revents & ZMQ_POLLIN) drainGaze();
      if (items[2].revents & ZMQ_POLLIN) drainPoses();
      if (items[3].revents & ZMQ_POLLIN) drainControl();
      if (items[5].revents & ZMQ_POLLIN) forwardReplies();
      if (items[0].revents & ZMQ_POLLIN) drainSubscriptions();
    } catch (const zmq::error_t& e) {
      if (e.num() == ETERM) break;
      spdlog::error("network loop: {}", e.what());
    }
  }
}

void NetLoop::forwardFrames() {
  for (int n = 0; n < kDrainBatch; ++n) {
    zmq::message_t frame;
    if (!frame_pipe_.recv(frame, zmq::recv_flags::dontwait)) return;
    // XPUB drops for a subscriber at its high-water mark instead of blocking.
    if (frames_.send(frame, zmq::send_flags::dontwait)) counters_.frames_sent.fetch_add(1);
  }
}

void NetLoop::forwardReplies() {
  bool overflow = false;
  for (int n = 0; n < kDrainBatch; ++n) {
    if (!receiveWhole(reply_pipe_, parts_, 3, overflow)) return;
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const bool last = i + 1 == parts_.size();
      (void)control_.send(parts_[i],
                          last ? zmq::send_flags::dontwait : zmq::send_flags::dontwait | zmq::send_flags::sndmore);
    }
  }
}

void NetLoop::drainSubscriptions() {
  for (int n = 0; n < kDrainBatch; ++n) {
    zmq::message_t m;
    if (!frames_.recv(m, zmq::recv_flags::dontwait)) break;
    bool more = m.more();
    subscriptions_.onMessage(m.data(), m.size(), more);
    while (more) {
      zmq::message_t rest;
      if (!frames_.recv(rest, zmq::recv_flags::dontwait)) break;
      more = rest.more();
    }
    // At once, not after the batch: libzmq has filed every message read so far into its trie.
    if (subscriptions_.overLimit()) dropSubscriptionHoarders();
  }
  drainMonitors();
}

void NetLoop::dropSubscriptionHoarders() {
  const auto now = std::chrono::steady_clock::now();
  ConnectionMonitor& frames = *monitors_[0];
  const int dropped = frames.dropPeersOver(kSubscriberAllowanceBytes, kSubscriberAllowanceBytesPerSecond);
  if (dropped > 0) {
    // A peer that reconnects and repeats its subscriptions (an XSUB does) is dropped each time.
    if (const std::uint64_t n = hoarder_log_.note()) {
      spdlog::warn("dropped {} frames peer(s) for sending refused subscriptions ({} bytes held at the latest)", n,
                   subscriptions_.heldRefusedBytes());
    }
    escalate_after_ = now + kDropSettleTime;
    return;
  }
  if (now < escalate_after_) return;  // the last drop's unsubscriptions are still on their way
  // No peer stands out (the refused subscriptions came slowly, or from many peers): drop every frames
  // peer; the subscribers reconnect by themselves within their reconnect interval.
  if (hoarder_log_.note()) {
    spdlog::warn("{} bytes of refused subscriptions held and no single sender: dropping all {} frames peers",
                 subscriptions_.heldRefusedBytes(), frames.peers());
  }
  frames.dropAll();
  subscriptions_.forgetRefused();
  escalate_after_ = now + kDropSettleTime;
}

void NetLoop::drainMonitors() {
  std::uint64_t dropped = 0;
  std::uint64_t accept_failures = 0;
  std::uint64_t handshake_failures = 0;
  for (const auto& monitor : monitors_) {
    monitor->drain();
    dropped += monitor->dropped();
    accept_failures += monitor->acceptFailures();
    handshake_failures += monitor->handshakeFailures();
  }
  counters_.peers_dropped.store(dropped);
  counters_.accept_failures.store(accept_failures);
  counters_.handshake_failures.store(handshake_failures);
  // A peer that subscribes twice is counted once: never more subscribers than connections (which an
  // inproc endpoint does not report).
  const std::int64_t subscribed = subscriptions_.subscribed();
  counters_.subscriptions.store(frames_inproc_ ? subscribed
                                               : std::min<std::int64_t>(subscribed, monitors_[0]->peers()));
}

curve::PeerRole NetLoop::roleOf(const zmq::message_t& message) const {
  if (!curve_) return curve::PeerRole::Operator;
  // With CURVE every connection passed the ZAP handler, which set the role; without one, the least.
  return curve::roleOf(message).value_or(curve::PeerRole::Viewer);
}

void NetLoop::drainGaze() {
  bool overflow = false;
  bool have = false;
  GazeArrival newest;
  for (int n = 0; n < kDrainBatch; ++n) {
    if (!receiveWhole(gaze_, parts_, 2, overflow)) break;
    std::string reason;
    const zmq::message_t* payload = payloadOf(parts_, overflow, reason);
    if (payload != nullptr) reason = parseGazeSample(payload->data(), payload->size(), gaze_msg_);
    if (payload != nullptr && reason.empty() && roleOf(*payload) != curve::PeerRole::Operator) {
      reason = "gaze from a viewer key (operators only)";
    }
    if (!reason.empty()) {
      rejections_.reject(InputSocket::Gaze, reason);
      continue;
    }
    if (!gaze_msg_.valid() || gaze_msg_.lost()) {
      // No point in this sample: the last one keeps ageing and the controller's hold / fallback
      // policy decides what to do with it.
      counters_.gaze_no_point.fetch_add(1);
      continue;
    }
    counters_.gaze_samples.fetch_add(1);
    // The freshest wins: only the newest usable sample of a burst goes to the simulation.
    newest.x = gaze_msg_.x();
    newest.y = gaze_msg_.y();
    newest.confidence = gaze_msg_.confidence();
    newest.sequence = gaze_msg_.sequence();
    newest.bridge_time_us = gaze_msg_.bridge_time_us();
    newest.source_id = gaze_msg_.source_id();
    newest.arrived = std::chrono::steady_clock::now();
    have = true;
  }
  if (have) mailbox_.putGaze(newest);
}

void NetLoop::drainPoses() {
  bool overflow = false;
  for (int n = 0; n < kDrainBatch; ++n) {
    if (!receiveWhole(pose_, parts_, 2, overflow)) return;
    std::string reason;
    const zmq::message_t* payload = payloadOf(parts_, overflow, reason);
    if (payload != nullptr) reason = parseCameraPose(payload->data(), payload->size(), pose_msg_);
    if (!reason.empty()) {
      rejections_.reject(InputSocket::Pose, reason);
      continue;
    }
    counters_.poses.fetch_add(1);
    PoseArrival pose;
    pose.camera = toScreenCamera(pose_msg_);
    pose.viewer_id = pose_msg_.viewer_id();
    pose.sequence = pose_msg_.sequence();
    pose.arrived = std::chrono::steady_clock::now();
    mailbox_.putPose(pose);
  }
}

void NetLoop::drainControl() {
  bool overflow = false;
  for (int n = 0; n < kDrainBatch; ++n) {
    if (!receiveWhole(control_, parts_, 3, overflow)) return;
    // ROUTER prepends the peer identity; DEALER peers send [payload], REQ peers [empty, payload].
    std::string identity = parts_[0].to_string();
    const bool delimiter = parts_.size() == 3 && parts_[1].size() == 0;
    if (overflow || parts_.size() < 2 || (parts_.size() == 3 && !delimiter)) {
      rejections_.reject(InputSocket::Control, "unexpected message parts");
      replyError(identity, delimiter, 0, gsph::v1::ERROR_CODE_BAD_REQUEST,
                 "expected one payload part (DEALER) or an empty delimiter and a payload (REQ)");
      continue;
    }
    ControlRequest request;
    request.identity = std::move(identity);
    request.has_delimiter = delimiter;
    const zmq::message_t& payload = parts_.back();
    const std::string reason = parseControl(payload.data(), payload.size(), request.control);
    if (!reason.empty()) {
      rejections_.reject(InputSocket::Control, reason);
      replyError(request.identity, delimiter, request.control.request_id(), gsph::v1::ERROR_CODE_BAD_REQUEST, reason);
      continue;
    }
    request.role = roleOf(payload);
    if (request.role != curve::PeerRole::Operator && request.control.command_case() != gsph::v1::Control::kStatus) {
      // Answered here: a forbidden request never reaches the simulation thread.
      rejections_.reject(InputSocket::Control, "a viewer key asked for more than status");
      replyError(request.identity, delimiter, request.control.request_id(), gsph::v1::ERROR_CODE_FORBIDDEN,
                 "forbidden: a viewer key may only ask for status (operator keys may do more)");
      continue;
    }
    counters_.control_requests.fetch_add(1);
    const std::uint64_t request_id = request.control.request_id();
    std::string id_copy = request.identity;
    if (!mailbox_.pushControl(std::move(request))) {
      replyError(id_copy, delimiter, request_id, gsph::v1::ERROR_CODE_INTERNAL,
                 "server busy: too many control requests queued");
    }
  }
}

void NetLoop::replyError(const std::string& identity, bool delimiter, std::uint64_t request_id,
                         gsph::v1::ErrorCode code, const std::string& error) {
  gsph::v1::ControlReply reply;
  reply.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
  reply.set_request_id(request_id);
  reply.set_ok(false);
  reply.set_error_code(code);
  reply.set_error(error);
  const std::string bytes = reply.SerializeAsString();
  (void)control_.send(zmq::buffer(identity), zmq::send_flags::dontwait | zmq::send_flags::sndmore);
  if (delimiter) (void)control_.send(zmq::message_t(), zmq::send_flags::dontwait | zmq::send_flags::sndmore);
  (void)control_.send(zmq::buffer(bytes), zmq::send_flags::dontwait);
}

}  // namespace net
