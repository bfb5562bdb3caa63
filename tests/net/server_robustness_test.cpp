// Misbehaving peers: a flood of garbage, truncated, oversized and malformed messages on every input
// socket, a raw TCP peer that never speaks ZMTP, and a subscriber that stops reading. The server must
// keep stepping and keep serving the well-behaved clients.
#include <gtest/gtest.h>
#include <unistd.h>

#include <random>

#include "net/input_validation.h"
#include "net_test_util.h"

namespace {

using net_test::ControlClient;
using net_test::FrameSubscriber;
using net_test::Publisher;

// A TCP peer that connects, writes junk that is not a ZMTP greeting, and then just sits there.
int rawJunkConnection(const std::string& endpoint) {
  const int fd = net_test::idleTcpConnection(endpoint);
  const char junk[] = "GET / HTTP/1.1\r\n\r\n\xff\x00\x01";
  if (fd >= 0) (void)::write(fd, junk, sizeof junk);
  return fd;
}

std::vector<std::string> badPayloads(const std::string& good) {
  std::mt19937 rng(1234);
  std::vector<std::string> out;
  for (int i = 0; i < 50; ++i) {
    std::string junk(1 + rng() % 300, '\0');
    for (char& c : junk) c = static_cast<char>(rng());
    out.push_back(junk);
  }
  for (std::size_t cut = 1; cut < good.size(); cut += 3) out.push_back(good.substr(0, cut));
  out.push_back(std::string(100 * 1024, 'x'));  // over the 64 KiB limit: libzmq drops the peer
  return out;
}

TEST(ServerRobustness, FloodOnEveryInputLeavesOthersServed) {
  auto server = net_test::startServer(net_test::testOptions(sph::Method::Gaze));
  const net::Endpoints& ep = server->endpoints();
  zmq::context_t ctx;
  FrameSubscriber good_sub(ctx, ep.frames);
  ControlClient good_control(ctx, ep.control);
  auto before = good_sub.next();
  ASSERT_TRUE(before);

  // Bad gaze: wrong version, NaN, out of range, and three-part messages, plus junk.
  gsph::v1::GazeSample nan_gaze = net_test::gazeSample(0.5, 0.5, 1);
  nan_gaze.set_x(std::numeric_limits<float>::quiet_NaN());
  gsph::v1::GazeSample far_gaze = net_test::gazeSample(4.0, 0.5, 2);
  gsph::v1::GazeSample old_gaze = net_test::gazeSample(0.5, 0.5, 3);
  old_gaze.set_protocol_version(99);
  gsph::v1::CameraPose bad_pose;
  net::fromScreenCamera(sph::ScreenCamera{}, bad_pose);
  bad_pose.set_viewport_width(0);

  zmq::socket_t xsub(ctx, zmq::socket_type::xsub);
  xsub.set(zmq::sockopt::linger, 0);
  xsub.connect(ep.frames);
  Publisher gaze(ctx, ep.gaze);
  Publisher pose(ctx, ep.pose);
  zmq::socket_t control(ctx, zmq::socket_type::dealer);
  control.set(zmq::sockopt::linger, 0);
  control.connect(ep.control);
  const int raw_fds[] = {rawJunkConnection(ep.frames), rawJunkConnection(ep.gaze), rawJunkConnection(ep.pose),
                         rawJunkConnection(ep.control)};

  const std::string good_gaze = net_test::gazeSample(0.5, 0.5, 4).SerializeAsString();
  const auto junk = badPayloads(good_gaze);
  // Keep flooding until every socket has counted rejections (the PUB/SUB links join asynchronously).
  const auto deadline = std::chrono::steady_clock::now() + net_test::kTimeout;
  const auto& rej = server->rejections();
  while (std::chrono::steady_clock::now() < deadline &&
         (rej.count(net::InputSocket::Gaze) == 0 || rej.count(net::InputSocket::Pose) == 0 ||
          rej.count(net::InputSocket::Control) == 0 || rej.count(net::InputSocket::Subscriptions) == 0)) {
    for (const std::string& bytes : junk) {
      gaze.sendBytes(bytes);
      pose.sendBytes(bytes);
      (void)control.send(zmq::buffer(bytes), zmq::send_flags::dontwait);
      // XPUB input that is not a subscription (first byte 0 or 1 means unsubscribe / subscribe).
      (void)xsub.send(zmq::buffer("\x07" + bytes), zmq::send_flags::dontwait);
    }
    gaze.send(nan_gaze);
    gaze.send(far_gaze);
    gaze.send(old_gaze);
    pose.send(bad_pose);
    (void)control.send(zmq::str_buffer("a"), zmq::send_flags::sndmore | zmq::send_flags::dontwait);
    (void)control.send(zmq::str_buffer("b"), zmq::send_flags::sndmore | zmq::send_flags::dontwait);
    (void)control.send(zmq::str_buffer("c"), zmq::send_flags::dontwait);
    // Is anyone still served? A status request round trip and fresh frames, during the flood.
    auto status = good_control.send(net_test::statusRequest());
    ASSERT_TRUE(status);
    EXPECT_TRUE(status->ok());
  }
  EXPECT_GT(rej.count(net::InputSocket::Gaze), 0u);
  EXPECT_GT(rej.count(net::InputSocket::Pose), 0u);
  EXPECT_GT(rej.count(net::InputSocket::Control), 0u);
  EXPECT_GT(rej.count(net::InputSocket::Subscriptions), 0u);

  // Still stepping, and a well-formed gaze sample still gets through.
  std::uint64_t seq = 100;
  Publisher good_gaze_pub(ctx, ep.gaze);
  auto after = good_sub.waitFor(
      [&](const gsph::v1::Frame& f) {
        return f.step() > before->step() + 10 && f.gaze().source_id() == "test" && f.gaze().sample_sequence() > 100;
      },
      [&] { good_gaze_pub.send(net_test::gazeSample(0.5, 0.5, ++seq)); });
  ASSERT_TRUE(after);
  auto status = good_control.send(net_test::statusRequest());
  ASSERT_TRUE(status);
  EXPECT_GT(status->status().inputs_rejected(), 0u);
  for (int fd : raw_fds) ::close(fd);
}

TEST(ServerRobustness, StalledSubscriberDoesNotHoldTheStep) {
  constexpr int kSteps = 60;  // 60+ frames of 26 KB: far more than the stalled peers' queues and socket buffers hold
  auto options = net_test::testOptions(sph::Method::Regular);
  options.sim.settings.free_run = true;
  options.sim.settings.publish_hz = app::kMaxPublishHz;
  options.sim.max_steps = kSteps;
  zmq::context_t ctx;
  // Subscribers that never read: the smallest queues, so they fill at once.
  std::vector<std::unique_ptr<FrameSubscriber>> stalled;
  auto server = std::make_unique<app::Server>(options);
  for (int i = 0; i < 3; ++i) {
    stalled.push_back(std::make_unique<FrameSubscriber>(ctx, server->endpoints().frames, false, 1));
  }
  const int silent_fd = rawJunkConnection(server->endpoints().frames);
  FrameSubscriber reader(ctx, server->endpoints().frames);
  // Everyone is connected before the first step (the subscription count says so).
  server->start();
  const auto end = std::chrono::steady_clock::now() + net_test::kTimeout;
  while (server->netCounters().subscriptions.load() < 4 && std::chrono::steady_clock::now() < end) {
    reader.next(std::chrono::milliseconds(20));
  }
  // The simulation runs all its steps although three subscribers hold full queues and one peer
  // never completed its handshake, and the reading subscriber sees the end.
  auto last = reader.waitFor([&](const gsph::v1::Frame& f) { return f.step() == kSteps; });
  ASSERT_TRUE(last);
  // The final frame goes out just before the loop marks itself finished.
  const auto finish_end = std::chrono::steady_clock::now() + net_test::kTimeout;
  while (!server->finished() && std::chrono::steady_clock::now() < finish_end)
    reader.next(std::chrono::milliseconds(20));
  EXPECT_TRUE(server->finished());
  // The finished server keeps publishing its last state: newer frames still reach the reader, so
  // the network thread did not stop behind the full peers.
  const std::uint64_t seen = last->sequence();
  auto later = reader.waitFor([&](const gsph::v1::Frame& f) { return f.sequence() > seen + 10; });
  ASSERT_TRUE(later);
  EXPECT_EQ(later->step(), kSteps);
  ::close(silent_fd);
}

}  // namespace
