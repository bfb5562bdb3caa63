#include "network_client.h"

#include <gtest/gtest.h>

#include <thread>
#include <zmq.hpp>

#include "test_frames.h"
#include "test_publisher.h"

using namespace std::chrono_literals;
using viewer_test::FrameSpec;
using viewer_test::makeFrame;

namespace {
constexpr auto kWait = 10s;

template <typename Predicate>
bool eventually(Predicate predicate) {
  const auto deadline = std::chrono::steady_clock::now() + kWait;
  while (std::chrono::steady_clock::now() < deadline) {
    if (predicate()) return true;
    std::this_thread::sleep_for(5ms);
  }
  return false;
}

viewer::Endpoints endpointsOf(const viewer_test::TestServer& server) {
  return {server.framesEndpoint(), server.gazeEndpoint(), server.poseEndpoint(), server.controlEndpoint(),
          std::nullopt};
}
}  // namespace

TEST(NetworkClient, KeepsOnlyTheNewestFrame) {
  zmq::context_t context;
  zmq::socket_t pub(context, zmq::socket_type::xpub);
  pub.set(zmq::sockopt::linger, 0);
  pub.bind("tcp://127.0.0.1:*");
  viewer::Endpoints endpoints;
  endpoints.frames = pub.get(zmq::sockopt::last_endpoint);
  viewer::NetworkClient client(endpoints, "newest");
  client.start();
  zmq::message_t subscription;
  ASSERT_TRUE(pub.recv(subscription));  // blocks until the client's SUB has joined
  FrameSpec spec;
  spec.particles = viewer_test::particleCloud(50, 0.0f, 1.0f);
  std::string bytes;
  for (std::uint64_t seq = 1; seq <= 200; ++seq) {
    makeFrame(spec, seq).SerializeToString(&bytes);
    pub.send(zmq::buffer(bytes));
  }
  std::shared_ptr<const viewer::DecodedFrame> newest;
  ASSERT_TRUE(eventually([&] {
    if (auto f = client.takeNewestFrame()) newest = f;
    return newest && newest->sequence == 200;
  }));
  EXPECT_EQ(client.takeNewestFrame(), nullptr);  // nothing older is left queued
  const auto stats = client.stats();
  // every sequence from the first one seen to 200 is either received or counted as skipped
  EXPECT_GE(stats.frames_received, 1u);
  EXPECT_LE(stats.frames_received + stats.frames_skipped, 200u);
  EXPECT_EQ(stats.frames_rejected, 0u);
  EXPECT_EQ(newest->particleCount(), 50u);
}

TEST(NetworkClient, RejectsBadFramesAndKeepsGoing) {
  zmq::context_t context;
  zmq::socket_t pub(context, zmq::socket_type::xpub);
  pub.set(zmq::sockopt::linger, 0);
  pub.bind("tcp://127.0.0.1:*");
  viewer::Endpoints endpoints;
  endpoints.frames = pub.get(zmq::sockopt::last_endpoint);
  viewer::NetworkClient client(endpoints, "bad");
  client.start();
  zmq::message_t subscription;
  ASSERT_TRUE(pub.recv(subscription));
  pub.send(zmq::str_buffer("garbage that is not a frame"));
  ASSERT_TRUE(eventually([&] { return client.stats().frames_rejected == 1; }));
  EXPECT_EQ(client.takeNewestFrame(), nullptr);
  EXPECT_FALSE(client.stats().last_error.empty());
  std::string bytes;
  makeFrame(FrameSpec{}, 5).SerializeToString(&bytes);
  pub.send(zmq::buffer(bytes));
  std::shared_ptr<const viewer::DecodedFrame> frame;
  ASSERT_TRUE(eventually([&] { return (frame = client.takeNewestFrame()) != nullptr; }));
  EXPECT_EQ(frame->sequence, 5u);
}

TEST(NetworkClient, ControlRequestGetsItsReply) {
  viewer_test::TestServer server(makeFrame(FrameSpec{}, 1));
  viewer::NetworkClient client(endpointsOf(server), "control");
  client.start();
  std::optional<gsph::v1::ControlReply> reply;
  std::uint64_t id = 0;
  // The DEALER refuses to queue while not yet connected (IMMEDIATE): retry until it is.
  ASSERT_TRUE(eventually([&] {
    if (id == 0) {
      gsph::v1::Control request;
      request.mutable_reset();
      id = client.sendControl(request);
    }
    reply = client.takeReply();
    if (reply && !reply->ok()) id = 0;
    return reply && reply->ok();
  }));
  EXPECT_EQ(reply->request_id(), id);
  bool reset_seen = false;
  for (const auto& c : server.controlsReceived()) reset_seen |= c.has_reset() && c.protocol_version() == 1;
  EXPECT_TRUE(reset_seen);
  // The periodic status poll fills the server status (scenes for the panel).
  EXPECT_TRUE(eventually([&] { return client.latestStatus().has_value(); }));
}

TEST(NetworkClient, PoseIsSentOnChangeAndRepeated) {
  viewer_test::TestServer server(makeFrame(FrameSpec{}, 1));
  viewer::NetworkClient client(endpointsOf(server), "pose");
  client.start();
  viewer::PoseData pose;
  pose.view[0] = 1.0f;
  pose.viewport_width = 640;
  pose.viewport_height = 480;
  client.setPose(pose);
  EXPECT_TRUE(server.waitForPose([](const auto& p) { return p.viewport_width() == 640 && p.sequence() >= 3; }, kWait));
  pose.viewport_width = 800;
  client.setPose(pose);
  gsph::v1::CameraPose got;
  EXPECT_TRUE(server.waitForPose([](const auto& p) { return p.viewport_width() == 800; }, kWait, &got));
  EXPECT_EQ(got.viewer_id(), "pose");
  EXPECT_EQ(got.view_size(), 16);
}

TEST(NetworkClient, MalformedEndpointThrowsBeforeStarting) {
  viewer::Endpoints endpoints;
  endpoints.frames = "not-a-transport://x";
  viewer::NetworkClient client(endpoints, "x");
  EXPECT_THROW(client.start(), zmq::error_t);
}
