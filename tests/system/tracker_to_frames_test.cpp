// The whole gaze path on loopback, with nothing stubbed: a Gazepoint Open Gaze API emulator (TCP,
// records split across reads) -> gaze_bridge (GazepointSource, processing, PUB) -> sph_server
// (in-process, gaze method) -> frames whose L0 particles sit where the emulated eye looks.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>

#include "bridge_harness.h"
#include "emulators.h"
#include "gazepoint_source.h"
#include "net_test_util.h"
#include "scene/scene_loader.h"

namespace {

using namespace std::chrono_literals;

struct System {
  std::unique_ptr<app::Server> server;
  zmq::context_t context;
  std::unique_ptr<gaze_bridge_test::GazepointEmulator> tracker;
  std::unique_ptr<gaze_bridge_test::BridgeThread> bridge;
  std::unique_ptr<net_test::FrameSubscriber> frames;
  double tracker_time = 0.0;

  System() {
    server = net_test::startServer(net_test::testOptions(sph::Method::Gaze));
    tracker = std::make_unique<gaze_bridge_test::GazepointEmulator>();
    gaze_bridge::GazepointParams gp;
    gp.port = tracker->port();
    // Unfiltered so the point that arrives is the tracker's; the server's SUB is the bridge's target.
    bridge =
        std::make_unique<gaze_bridge_test::BridgeThread>(context, std::make_unique<gaze_bridge::GazepointSource>(gp),
                                                         gaze_bridge_test::rawParams(server->endpoints().gaze));
    frames = std::make_unique<net_test::FrameSubscriber>(context, server->endpoints().frames);
  }
  ~System() {
    bridge->stop();
    server->stop();
  }
  // Streams the point as the tracker would (60 Hz records) until a frame satisfies `accept`.
  std::optional<gsph::v1::Frame> lookAt(double x, double y, const std::function<bool(const gsph::v1::Frame&)>& accept) {
    return frames->waitFor(
        accept,
        [&] {
          tracker_time += 1.0 / 60.0;
          tracker->send(gaze_bridge_test::gazepointRecord(tracker_time, x, y, true));
        },
        20s);
  }
};

TEST(TrackerToFrames, EmulatedGazepointGazeRefinesWhereItLooks) {
  System sys;
  const sph::ScreenCamera camera = sph::cameraFromSpec(scene::loadScene("tiny_pool", SPH_NET_TEST_SCENE_DIR).camera);
  const auto refinedAt = [&](double x, double y) {
    return [&camera, x, y](const gsph::v1::Frame& f) {
      if (f.gaze().mode() != gsph::v1::GAZE_MODE_TRACKING) return false;
      if (std::abs(f.gaze().x() - x) > 1e-4 || std::abs(f.gaze().y() - y) > 1e-4) return false;
      if (f.gaze().source_id() != "gazepoint") return false;
      const auto small = net_test::smallOnScreen(f, camera);
      const int near = net_test::countNear(small, camera, x, y, 0.2);
      return near > 10 && net_test::countNear(small, camera, 1.0 - x, 1.0 - y, 0.2) * 20 < near;
    };
  };
  const auto first = sys.lookAt(0.25, 0.3, refinedAt(0.25, 0.3));
  ASSERT_TRUE(first) << "the tracker's gaze never refined the pool where it looked";
  EXPECT_GT(first->gaze().sample_bridge_time_us(), 0);
  EXPECT_GT(sys.tracker->acked(), 0) << "the bridge enabled the tracker's data stream";
  // The eye moves to the other side: the refined region follows.
  const auto second = sys.lookAt(0.75, 0.7, refinedAt(0.75, 0.7));
  ASSERT_TRUE(second) << "the refined region did not follow the gaze";
  EXPECT_GT(second->sequence(), first->sequence());
}

TEST(TrackerToFrames, InvalidTrackerRecordsNeverMoveTheGaze) {
  System sys;
  const auto tracking = sys.lookAt(0.3, 0.3, [](const gsph::v1::Frame& f) {
    return f.gaze().mode() == gsph::v1::GAZE_MODE_TRACKING && std::abs(f.gaze().x() - 0.3) < 1e-4;
  });
  ASSERT_TRUE(tracking);
  // Records flagged invalid (BPOGV = 0) at another point: the server keeps the last valid point,
  // holding it and then falling back to surface refinement, and never uses the invalid one.
  const auto fell_back = sys.frames->waitFor(
      [](const gsph::v1::Frame& f) {
        EXPECT_GT(std::abs(f.gaze().x() - 0.9), 1e-3) << "an invalid sample was used";
        return f.gaze().mode() == gsph::v1::GAZE_MODE_FALLBACK;
      },
      [&] {
        sys.tracker_time += 1.0 / 60.0;
        sys.tracker->send(gaze_bridge_test::gazepointRecord(sys.tracker_time, 0.9, 0.9, false));
      },
      20s);
  ASSERT_TRUE(fell_back);
}

}  // namespace
