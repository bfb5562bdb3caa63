#include "network_client.h"

#include <map>
#include <set>
#include <zmq.hpp>

namespace viewer {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kHeartbeatIvlMs = 1000;
constexpr int kHeartbeatTimeoutMs = 3000;
constexpr int kReconnectIvlMs = 200;
constexpr int kReconnectIvlMaxMs = 2000;
constexpr std::int64_t kMaxFrameBytes = 256ll << 20;  // ~10 M particles as float32
constexpr int kFrameQueue = 4;                        // frames the SUB socket holds while the network thread decodes
constexpr std::int64_t kMaxReplyBytes = 1ll << 20;
constexpr std::size_t kMaxQueuedControls = 8;
constexpr std::size_t kMaxQueuedReplies = 32;
constexpr auto kPollPeriod = std::chrono::milliseconds(5);  // upper bound on pose/gaze send delay

std::int64_t systemMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

void commonOptions(zmq::socket_t& s, const std::optional<curve::ClientKeys>& keys) {
  if (keys) curve::makeCurveClient(s, *keys);
  s.set(zmq::sockopt::linger, 0);
  s.set(zmq::sockopt::heartbeat_ivl, kHeartbeatIvlMs);
  s.set(zmq::sockopt::heartbeat_timeout, kHeartbeatTimeoutMs);
  s.set(zmq::sockopt::reconnect_ivl, kReconnectIvlMs);
  s.set(zmq::sockopt::reconnect_ivl_max, kReconnectIvlMaxMs);
}

}  // namespace

struct NetworkClient::Sockets {
  zmq::context_t context{1};
  zmq::socket_t frames{context, zmq::socket_type::sub};
  zmq::socket_t pose{context, zmq::socket_type::pub};
  zmq::socket_t gaze{context, zmq::socket_type::pub};
  zmq::socket_t control{context, zmq::socket_type::dealer};
  // network-thread-only state
  std::uint64_t pose_sequence = 0;
  std::uint64_t gaze_sequence = 0;
  Clock::time_point last_pose_send{};
  Clock::time_point last_status_request{};
  std::map<std::uint64_t, Clock::time_point> pending;  // request_id -> deadline
  std::set<std::uint64_t> internal_requests;           // status polls: replies update status only
  std::uint64_t last_sequence = 0;
  bool have_sequence = false;
  gsph::v1::CameraPose pose_message;  // reused: no allocation per send
  gsph::v1::GazeSample gaze_message;
};

NetworkClient::NetworkClient(Endpoints endpoints, std::string viewer_id)
    : endpoints_(std::move(endpoints)), viewer_id_(std::move(viewer_id)) {}

NetworkClient::~NetworkClient() { stop(); }

void NetworkClient::start() {
  if (running_) return;
  auto s = std::make_unique<Sockets>();
  // A short queue, drained to its newest frame on each wake-up. Not CONFLATE: libzmq's conflating
  // pipe can miss the wake-up for a frame that lands while the reader finds the pipe empty, and
  // the last frame of a burst (a paused server's) then waits for the next one.
  s->frames.set(zmq::sockopt::rcvhwm, kFrameQueue);
  s->frames.set(zmq::sockopt::maxmsgsize, kMaxFrameBytes);
  s->frames.set(zmq::sockopt::subscribe, "");
  commonOptions(s->frames, endpoints_.curve);
  s->frames.connect(endpoints_.frames);

  for (zmq::socket_t* pub : {&s->pose, &s->gaze}) {
    pub->set(zmq::sockopt::sndhwm, 4);
    commonOptions(*pub, endpoints_.curve);
  }
  s->pose.connect(endpoints_.pose);
  s->gaze.connect(endpoints_.gaze);

  // IMMEDIATE: while no server is connected a send fails at once instead of queueing a stale
  // command that would fire when the server comes back.
  s->control.set(zmq::sockopt::immediate, 1);
  s->control.set(zmq::sockopt::maxmsgsize, kMaxReplyBytes);
  s->control.set(zmq::sockopt::sndhwm, 16);
  commonOptions(s->control, endpoints_.curve);
  s->control.connect(endpoints_.control);

  sockets_ = std::move(s);
  running_ = true;
  thread_ = std::thread([this] { run(); });
}

void NetworkClient::stop() {
  running_ = false;
  if (thread_.joinable()) thread_.join();
  sockets_.reset();
}

void NetworkClient::setPose(const PoseData& pose) {
  std::lock_guard lock(mutex_);
  if (!pose_ || !(*pose_ == pose)) {
    pose_ = pose;
    pose_dirty_ = true;
  }
}

void NetworkClient::setGaze(float x, float y, bool valid) {
  std::lock_guard lock(mutex_);
  gaze_ = GazeState{x, y, valid};
}

void NetworkClient::setControlTimeout(std::chrono::milliseconds timeout) {
  std::lock_guard lock(mutex_);
  control_timeout_ = timeout;
}

std::uint64_t NetworkClient::sendControl(gsph::v1::Control request) {
  std::lock_guard lock(mutex_);
  request.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
  request.set_request_id(next_request_id_++);
  if (outgoing_control_.size() >= kMaxQueuedControls) outgoing_control_.pop_front();
  outgoing_control_.push_back(std::move(request));
  return outgoing_control_.back().request_id();
}

std::shared_ptr<const DecodedFrame> NetworkClient::takeNewestFrame() {
  std::lock_guard lock(mutex_);
  return std::exchange(newest_frame_, nullptr);
}

std::optional<gsph::v1::ControlReply> NetworkClient::takeReply() {
  std::lock_guard lock(mutex_);
  if (replies_.empty()) return std::nullopt;
  auto reply = std::move(replies_.front());
  replies_.pop_front();
  return reply;
}

std::optional<gsph::v1::ServerStatus> NetworkClient::latestStatus() const {
  std::lock_guard lock(mutex_);
  return status_;
}

NetworkStats NetworkClient::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

void NetworkClient::run() {
  Sockets& s = *sockets_;
  while (running_) {
    zmq::pollitem_t items[] = {{s.frames.handle(), 0, ZMQ_POLLIN, 0}, {s.control.handle(), 0, ZMQ_POLLIN, 0}};
    try {
      zmq::poll(items, 2, kPollPeriod);
      if (items[0].revents & ZMQ_POLLIN) receiveFrames(s);
      if (items[1].revents & ZMQ_POLLIN) receiveReplies(s);
      sendOutgoing(s, Clock::now());
    } catch (const zmq::error_t& e) {
      if (e.num() == ETERM) break;
      std::lock_guard lock(mutex_);
      stats_.last_error = std::string("network: ") + e.what();
    }
  }
}

void NetworkClient::receiveFrames(Sockets& s) {
  zmq::message_t message, newer;
  // Only the newest of the queued frames is decoded; the loop takes what lands during decode.
  while (s.frames.recv(message, zmq::recv_flags::dontwait)) {
    while (s.frames.recv(newer, zmq::recv_flags::dontwait)) message.swap(newer);
    const auto arrival = Clock::now();
    auto frame = std::make_shared<DecodedFrame>();
    std::string error;
    const bool ok = decodeFrameBytes(message.data(), message.size(), *frame, error);
    frame->arrival = arrival;
    std::lock_guard lock(mutex_);
    if (!ok) {
      ++stats_.frames_rejected;
      stats_.last_error = error;
      continue;
    }
    if (s.have_sequence) {
      if (frame->sequence > s.last_sequence) {
        stats_.frames_skipped += frame->sequence - s.last_sequence - 1;
      } else {
        ++stats_.server_restarts;  // a new server counts from 0 again
      }
    }
    s.have_sequence = true;
    s.last_sequence = frame->sequence;
    ++stats_.frames_received;
    stats_.last_frame_arrival = arrival;
    newest_frame_ = std::move(frame);
  }
}

void NetworkClient::receiveReplies(Sockets& s) {
  std::vector<zmq::message_t> parts;
  zmq::message_t part;
  while (s.control.recv(part, zmq::recv_flags::dontwait)) {
    parts.push_back(std::move(part));
    if (parts.back().more()) continue;
    // The payload is the last part (tolerates an empty delimiter frame before it).
    gsph::v1::ControlReply reply;
    const bool ok = reply.ParseFromArray(parts.back().data(), static_cast<int>(parts.back().size()));
    parts.clear();
    std::lock_guard lock(mutex_);
    if (!ok || reply.protocol_version() != gsph::v1::PROTOCOL_VERSION_CURRENT) {
      stats_.last_error = "control reply did not parse or has an unknown protocol_version";
      continue;
    }
    s.pending.erase(reply.request_id());
    if (reply.ok() && reply.has_status()) status_ = reply.status();
    if (s.internal_requests.erase(reply.request_id()) > 0) continue;
    if (replies_.size() >= kMaxQueuedReplies) replies_.pop_front();
    replies_.push_back(std::move(reply));
  }
}

void NetworkClient::sendOutgoing(Sockets& s, Clock::time_point now) {
  std::optional<PoseData> pose;
  std::optional<GazeState> gaze;
  std::deque<gsph::v1::Control> controls;
  std::chrono::milliseconds control_timeout{};
  {
    std::lock_guard lock(mutex_);
    control_timeout = control_timeout_;
    if (pose_ && (pose_dirty_ || now - s.last_pose_send >= kPoseResend)) {
      pose = pose_;
      pose_dirty_ = false;
    }
    gaze = std::exchange(gaze_, std::nullopt);
    controls.swap(outgoing_control_);
    if (now - s.last_status_request >= kStatusInterval) {
      gsph::v1::Control status;
      status.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
      status.set_request_id(next_request_id_++);
      status.mutable_status();
      s.internal_requests.insert(status.request_id());
      controls.push_back(std::move(status));
      s.last_status_request = now;
    }
    // Requests that never got a reply (server gone mid-request) expire.
    for (auto it = s.pending.begin(); it != s.pending.end();) {
      if (now > it->second) {
        if (s.internal_requests.erase(it->first) == 0) {
          ++stats_.control_timeouts;
          gsph::v1::ControlReply timeout;
          timeout.set_request_id(it->first);
          timeout.set_ok(false);
          timeout.set_error("no reply from the server within " + std::to_string(control_timeout.count() / 1000) + " s");
          if (replies_.size() >= kMaxQueuedReplies) replies_.pop_front();
          replies_.push_back(std::move(timeout));
        }
        it = s.pending.erase(it);
      } else {
        ++it;
      }
    }
  }

  std::string bytes;
  if (pose) {
    auto& m = s.pose_message;
    m.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
    m.set_viewer_id(viewer_id_);
    m.set_sequence(++s.pose_sequence);
    m.set_sent_time_us(systemMicros());
    m.mutable_view()->Assign(pose->view.begin(), pose->view.end());
    m.mutable_projection()->Assign(pose->projection.begin(), pose->projection.end());
    m.set_viewport_width(pose->viewport_width);
    m.set_viewport_height(pose->viewport_height);
    m.SerializeToString(&bytes);
    if (s.pose.send(zmq::buffer(bytes), zmq::send_flags::dontwait)) {
      std::lock_guard lock(mutex_);
      ++stats_.poses_sent;
    }
    s.last_pose_send = now;
  }
  if (gaze) {
    auto& m = s.gaze_message;
    m.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
    m.set_source_id("mouse");
    m.set_sequence(++s.gaze_sequence);
    m.set_tracker_time_s(std::chrono::duration<double>(now.time_since_epoch()).count());
    m.set_bridge_time_us(systemMicros());
    m.set_x(gaze->x);
    m.set_y(gaze->y);
    m.set_valid(gaze->valid);
    m.set_confidence(gaze->valid ? 1.0f : 0.0f);
    m.SerializeToString(&bytes);
    if (s.gaze.send(zmq::buffer(bytes), zmq::send_flags::dontwait)) {
      std::lock_guard lock(mutex_);
      ++stats_.gaze_sent;
    }
  }
  for (const auto& request : controls) {
    request.SerializeToString(&bytes);
    if (s.control.send(zmq::buffer(bytes), zmq::send_flags::dontwait)) {
      s.pending[request.request_id()] = now + control_timeout;
    } else {
      // our own status poll is simply retried at the next interval
      if (s.internal_requests.erase(request.request_id()) > 0) continue;
      gsph::v1::ControlReply failed;
      failed.set_request_id(request.request_id());
      failed.set_ok(false);
      failed.set_error("not connected to the server's control socket");
      std::lock_guard lock(mutex_);
      if (replies_.size() >= kMaxQueuedReplies) replies_.pop_front();
      replies_.push_back(std::move(failed));
    }
  }
}

}  // namespace viewer
