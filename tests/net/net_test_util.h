// Shared pieces of the sph_server tests: an in-process server on ephemeral loopback ports with the
// small test scenes, and clients for each socket (frame subscriber, gaze and pose publishers, control
// DEALER). Every wait is a poll with a generous deadline, never a sleep that decides the outcome.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>
#include <zmq.hpp>

#include "app/server.h"
#include "net/curve_sockets.h"
#include "proto/sph.pb.h"
#include "sph/camera.h"

namespace net_test {

// How long a test waits for something that must happen: generous, so that a machine three times
// slower, or a busy one, still gets there (a passing test never waits it out).
inline constexpr auto kTimeout = std::chrono::seconds(30);

inline app::ServerOptions testOptions(sph::Method method, const std::string& scene = "tiny_pool") {
  app::ServerOptions o;
  o.net.endpoints = {"tcp://127.0.0.1:*", "tcp://127.0.0.1:*", "tcp://127.0.0.1:*", "tcp://127.0.0.1:*"};
  o.sim.scene = scene;
  o.sim.scene_dir = SPH_NET_TEST_SCENE_DIR;
  o.sim.method = method;
  o.sim.threads = 1;
  o.sim.status_interval_s = 0.0;
  o.sim.settings.publish_hz = 60.0;
  // The test pool is small on screen: a wider gaze circle refines enough particles to see.
  o.sim.adaptive_overrides = {{"gaze_radius", 0.12}, {"gaze_ring_radius", 0.16}};
  return o;
}

inline std::unique_ptr<app::Server> startServer(const app::ServerOptions& options) {
  auto server = std::make_unique<app::Server>(options);
  server->start();
  return server;
}

// The server's status line once `done` holds for it, or as it stands at the deadline.
inline std::string statusLineOnce(const app::Server& server, const std::function<bool(const std::string&)>& done) {
  const auto end = std::chrono::steady_clock::now() + kTimeout;
  std::string line = server.statusLine();
  while (!done(line) && std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    line = server.statusLine();
  }
  return line;
}

inline std::int64_t nowUs() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// A client's CURVE keys (none: plaintext), set on a socket before it connects.
using Keys = std::optional<curve::ClientKeys>;
inline void applyKeys(zmq::socket_t& socket, const Keys& keys) {
  if (keys) curve::makeCurveClient(socket, *keys);
}

class FrameSubscriber {
 public:
  FrameSubscriber(zmq::context_t& ctx, const std::string& endpoint, bool conflate = false, int receive_hwm = 0,
                  const Keys& keys = std::nullopt)
      : socket_(ctx, zmq::socket_type::sub) {
    socket_.set(zmq::sockopt::linger, 0);
    applyKeys(socket_, keys);
    if (receive_hwm > 0) socket_.set(zmq::sockopt::rcvhwm, receive_hwm);
    if (receive_hwm > 0) socket_.set(zmq::sockopt::rcvbuf, 4096);
    if (conflate) socket_.set(zmq::sockopt::conflate, 1);
    socket_.set(zmq::sockopt::subscribe, "");
    socket_.connect(endpoint);
  }
  // The next frame, or nothing after `timeout`.
  std::optional<gsph::v1::Frame> next(std::chrono::milliseconds timeout = kTimeout) {
    zmq::pollitem_t item{socket_.handle(), 0, ZMQ_POLLIN, 0};
    if (zmq::poll(&item, 1, timeout) <= 0) return std::nullopt;
    zmq::message_t msg;
    if (!socket_.recv(msg)) return std::nullopt;
    gsph::v1::Frame frame;
    if (!frame.ParseFromArray(msg.data(), static_cast<int>(msg.size()))) return std::nullopt;
    return frame;
  }
  // Frames until one satisfies `accept`; `on_wait` runs between receives (to resend a gaze sample,
  // for example). Fails the test after the deadline.
  std::optional<gsph::v1::Frame> waitFor(const std::function<bool(const gsph::v1::Frame&)>& accept,
                                         const std::function<void()>& on_wait = {},
                                         std::chrono::seconds deadline = kTimeout) {
    const auto end = std::chrono::steady_clock::now() + deadline;
    while (std::chrono::steady_clock::now() < end) {
      if (on_wait) on_wait();
      auto frame = next(std::chrono::milliseconds(100));
      if (frame && accept(*frame)) return frame;
    }
    ADD_FAILURE() << "no frame satisfied the condition within the deadline";
    return std::nullopt;
  }
  zmq::socket_t& socket() { return socket_; }

 private:
  zmq::socket_t socket_;
};

class ControlClient {
 public:
  ControlClient(zmq::context_t& ctx, const std::string& endpoint, const Keys& keys = std::nullopt)
      : socket_(ctx, zmq::socket_type::dealer) {
    socket_.set(zmq::sockopt::linger, 0);
    applyKeys(socket_, keys);
    socket_.connect(endpoint);
  }
  std::optional<gsph::v1::ControlReply> send(gsph::v1::Control request) {
    request.set_request_id(++last_id_);
    if (request.protocol_version() == 0) request.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
    return sendRaw(request.SerializeAsString(), last_id_);
  }
  // Sends `bytes` and returns the first reply, or with `request_id`, the first reply to that id
  // (a late reply to an earlier request that timed out is skipped, not taken for this one's).
  // `wait`: how long to wait for the reply (a test that expects none waits less than kTimeout).
  std::optional<gsph::v1::ControlReply> sendRaw(const std::string& bytes,
                                                std::optional<std::uint64_t> request_id = std::nullopt,
                                                std::chrono::milliseconds wait = kTimeout) {
    socket_.send(zmq::buffer(bytes), zmq::send_flags::none);
    const auto end = std::chrono::steady_clock::now() + wait;
    for (;;) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      zmq::pollitem_t item{socket_.handle(), 0, ZMQ_POLLIN, 0};
      if (left.count() <= 0 || zmq::poll(&item, 1, left) <= 0) return std::nullopt;
      zmq::message_t msg;
      if (!socket_.recv(msg)) return std::nullopt;
      gsph::v1::ControlReply reply;
      if (!reply.ParseFromArray(msg.data(), static_cast<int>(msg.size()))) return std::nullopt;
      if (!request_id || reply.request_id() == *request_id) return reply;
    }
  }
  // Sends `request` again every 200 ms until one is answered (the server may drop a connection, and
  // the request queued on it with it), or returns nothing after kTimeout.
  std::optional<gsph::v1::ControlReply> sendUntilAnswered(const gsph::v1::Control& request) {
    const auto end = std::chrono::steady_clock::now() + kTimeout;
    while (std::chrono::steady_clock::now() < end) {
      gsph::v1::Control copy = request;
      copy.set_request_id(++last_id_);
      copy.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
      if (auto reply = sendRaw(copy.SerializeAsString(), last_id_, std::chrono::milliseconds(200))) return reply;
    }
    return std::nullopt;
  }
  std::uint64_t lastId() const { return last_id_; }

 private:
  zmq::socket_t socket_;
  std::uint64_t last_id_ = 0;
};

// PUB connected to a server's SUB input (gaze or camera pose).
class Publisher {
 public:
  Publisher(zmq::context_t& ctx, const std::string& endpoint, const Keys& keys = std::nullopt)
      : socket_(ctx, zmq::socket_type::pub) {
    socket_.set(zmq::sockopt::linger, 0);
    applyKeys(socket_, keys);
    socket_.connect(endpoint);
  }
  void send(const google::protobuf::MessageLite& m) { sendBytes(m.SerializeAsString()); }
  void sendBytes(const std::string& bytes) { (void)socket_.send(zmq::buffer(bytes), zmq::send_flags::dontwait); }

 private:
  zmq::socket_t socket_;
};

inline gsph::v1::GazeSample gazeSample(double x, double y, std::uint64_t sequence) {
  gsph::v1::GazeSample g;
  g.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
  g.set_source_id("test");
  g.set_sequence(sequence);
  g.set_bridge_time_us(nowUs());
  g.set_x(static_cast<float>(x));
  g.set_y(static_cast<float>(y));
  g.set_valid(true);
  g.set_confidence(1.0f);
  return g;
}

inline gsph::v1::Control statusRequest() {
  gsph::v1::Control c;
  c.mutable_status();
  return c;
}

// Largest element difference (element loops: Eigen's isApprox on 4x4 trips a GCC 12 AVX-512 false
// positive under -Werror).
inline double maxAbsDiff(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b) {
  double d = 0.0;
  for (int i = 0; i < 16; ++i) d = std::max(d, std::abs(a(i % 4, i / 4) - b(i % 4, i / 4)));
  return d;
}

// A plain TCP connection to a tcp://127.0.0.1:PORT endpoint that sends nothing (a peer that never
// speaks ZMTP); -1 when this process has no descriptor left. The caller closes it.
int idleTcpConnection(const std::string& endpoint);

// Screen positions (normalized, origin top left) of the L0 particles of a frame under `camera`.
std::vector<Eigen::Vector2d> smallOnScreen(const gsph::v1::Frame& frame, const sph::ScreenCamera& camera);
// How many of `points` lie within `radius` (fraction of width, aspect-corrected as the gaze circle is) of (x, y).
int countNear(const std::vector<Eigen::Vector2d>& points, const sph::ScreenCamera& camera, double x, double y,
              double radius);
// Mean world x, z of the L0 particles.
Eigen::Vector2d smallMeanXZ(const gsph::v1::Frame& frame);

}  // namespace net_test
