// What held before the connection limits and CURVE and must keep holding: 8 subscribers, 2 gaze
// publishers at about 200 Hz and a camera pose publisher at about 60 Hz all served at once (every
// subscriber keeps getting frames with finite positions, both gaze sources and the pose are used);
// and rejected input on every socket logs one line per socket per interval, whatever the flood.
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "log_capture.h"
#include "net/frame_encoder.h"
#include "net/input_validation.h"
#include "net_test_util.h"
#include "scene/scene_loader.h"

namespace {

using net_test::FrameSubscriber;
using net_test::Publisher;

TEST(ServerLoad, EightSubscribersTwoGazeSourcesAndAPoseAreServedTogether) {
  constexpr int kSubscribers = 8;
  auto server = net_test::startServer(net_test::testOptions(sph::Method::Gaze));
  const net::Endpoints& ep = server->endpoints();
  zmq::context_t ctx;
  std::vector<std::unique_ptr<FrameSubscriber>> subs;
  for (int i = 0; i < kSubscribers; ++i) subs.push_back(std::make_unique<FrameSubscriber>(ctx, ep.frames));

  // The senders run on their own thread at their own pace, as a tracker and a viewer would.
  std::atomic<bool> stop{false};
  std::thread senders([&] {
    zmq::context_t sender_ctx;
    Publisher gaze_a(sender_ctx, ep.gaze), gaze_b(sender_ctx, ep.gaze), pose(sender_ctx, ep.pose);
    gsph::v1::CameraPose pose_msg;
    net::fromScreenCamera(sph::cameraFromSpec(scene::loadScene("tiny_pool", SPH_NET_TEST_SCENE_DIR).camera), pose_msg);
    pose_msg.set_viewer_id("load-viewer");
    for (std::uint64_t n = 1; !stop.load(); ++n) {
      gsph::v1::GazeSample a = net_test::gazeSample(0.3, 0.3, n);
      a.set_source_id("tracker-a");
      gsph::v1::GazeSample b = net_test::gazeSample(0.7, 0.7, n);
      b.set_source_id("tracker-b");
      // Either may be the newest of a burst (the one the server keeps): alternate the order.
      (n % 2 ? gaze_a : gaze_b).send(n % 2 ? a : b);
      (n % 2 ? gaze_b : gaze_a).send(n % 2 ? b : a);
      if (n % 3 == 0) pose.send(pose_msg);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });

  std::vector<int> frames(kSubscribers, 0);
  bool saw_a = false, saw_b = false, saw_pose = false;
  const auto end = std::chrono::steady_clock::now() + net_test::kTimeout;
  const auto done = [&] { return saw_a && saw_b && saw_pose && *std::min_element(frames.begin(), frames.end()) >= 60; };
  while (!done() && std::chrono::steady_clock::now() < end) {
    std::vector<zmq::pollitem_t> items;
    for (auto& s : subs) items.push_back({s->socket().handle(), 0, ZMQ_POLLIN, 0});
    zmq::poll(items, std::chrono::milliseconds(50));
    for (int i = 0; i < kSubscribers; ++i) {
      if (!(items[i].revents & ZMQ_POLLIN)) continue;
      auto frame = subs[i]->next(std::chrono::milliseconds(0));
      if (!frame) continue;
      ++frames[i];
      saw_a |= frame->gaze().source_id() == "tracker-a";
      saw_b |= frame->gaze().source_id() == "tracker-b";
      saw_pose |= frame->camera().viewer_id() == "load-viewer";
      for (float v : net::decodePositions(*frame)) ASSERT_TRUE(std::isfinite(v));
    }
  }
  stop = true;
  senders.join();
  EXPECT_TRUE(saw_a && saw_b) << "a gaze source was never used";
  EXPECT_TRUE(saw_pose) << "the camera pose was never used";
  for (int i = 0; i < kSubscribers; ++i) EXPECT_GE(frames[i], 60) << "subscriber " << i;
  EXPECT_EQ(server->rejections().total(), 0u);
}

TEST(ServerLoad, RejectedInputLogsALinePerSocketPerInterval) {
  net_test::LogCapture log;
  net::RejectionLog rejections(std::chrono::hours(1));
  for (int i = 0; i < 10000; ++i) {
    for (net::InputSocket s :
         {net::InputSocket::Gaze, net::InputSocket::Pose, net::InputSocket::Control, net::InputSocket::Subscriptions}) {
      rejections.reject(s, "junk");
    }
  }
  EXPECT_EQ(rejections.total(), 40000u);
  EXPECT_EQ(log.lines("rejected"), 4) << log.text();
  for (const char* socket : {"gaze", "camera pose", "control", "frame subscriptions"}) {
    EXPECT_EQ(log.lines(std::string("on the ") + socket + " socket"), 1) << socket;
  }
}

}  // namespace
