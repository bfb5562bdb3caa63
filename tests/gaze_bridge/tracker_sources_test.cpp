// The real tracker protocols against their emulators on loopback, through the whole bridge.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "bridge_harness.h"
#include "emulators.h"
#include "gazepoint_source.h"
#include "pupil_source.h"
#include "support/reserved_port.h"

using namespace gaze_bridge_test;
using namespace std::chrono_literals;

namespace {

bool near(float a, double b) { return std::abs(static_cast<double>(a) - b) < 1e-6; }

// Publishes the same message every 20 ms until the receiver sees a sample `match` accepts
// (a new SUB connection misses what was published before it joined).
std::optional<gsph::v1::GazeSample> publishUntil(PupilEmulator& pupil, const std::string& topic,
                                                 const std::string& payload, GazeReceiver& receiver,
                                                 const std::function<bool(const gsph::v1::GazeSample&)>& match) {
  const auto end = std::chrono::steady_clock::now() + kWait;
  while (std::chrono::steady_clock::now() < end) {
    pupil.publish(topic, payload);
    if (auto s = receiver.receiveUntil(match, 20ms)) return s;
  }
  return std::nullopt;
}

// Sends records until one comes through the bridge, so the bridge-to-receiver PUB/SUB connection is up
// (PUB drops what it sends before the subscription arrives) before a test's own records.
bool warmUp(GazepointEmulator& tracker, GazeReceiver& receiver) {
  for (int k = 0; k < 500; ++k) {
    tracker.send(gazepointRecord(100.0 + k, 0.5, 0.5, true));
    if (receiver.receiveUntil([](const auto& s) { return s.valid() && s.tracker_time_s() >= 100.0; }, 20ms)) {
      // Drain whatever else of the warm-up is still in flight.
      while (receiver.receiveUntil([](const auto& s) { return s.valid() && s.tracker_time_s() >= 100.0; }, 100ms)) {
      }
      return true;
    }
  }
  return false;
}

}  // namespace

TEST(PupilSource, BridgeTurnsSurfaceGazeIntoTopLeftPoints) {
  zmq::context_t context;
  PupilEmulator pupil(context);
  GazeReceiver receiver(context);
  gaze_bridge::PupilParams params;
  params.remote_port = pupil.remotePort();
  params.surface = "screen";
  BridgeThread bridge(context, std::make_unique<gaze_bridge::PupilSource>(context, params),
                      rawParams(receiver.endpoint()));

  // Several samples per message: valid, low confidence (dropped), off surface (dropped), valid.
  const std::string payload = packSurfaceMessage("screen", {{0.2, 0.9, 0.95, true, 50.0},
                                                            {0.4, 0.4, 0.3, true, 50.004},
                                                            {0.6, 0.6, 0.99, false, 50.008},
                                                            {0.8, 0.3, 0.9, true, 50.012}});
  auto first = publishUntil(pupil, "surfaces.screen", payload, receiver,
                            [](const auto& s) { return s.valid() && s.tracker_time_s() == 50.0; });
  ASSERT_TRUE(first);
  EXPECT_TRUE(near(first->x(), 0.2));
  EXPECT_TRUE(near(first->y(), 0.1));  // y flipped
  EXPECT_EQ(first->source_id(), "pupil");
  EXPECT_EQ(first->protocol_version(), 1u);
  // The next sample out of the same message is the fourth one: the two between were dropped.
  auto next = receiver.receiveUntil([](const auto& s) { return s.valid(); });
  ASSERT_TRUE(next);
  EXPECT_EQ(next->tracker_time_s(), 50.012);
  EXPECT_TRUE(near(next->x(), 0.8));
  EXPECT_TRUE(near(next->y(), 0.7));
  EXPECT_EQ(next->sequence(), first->sequence() + 1);

  // Another surface and a topic that only shares the prefix are ignored.
  bridge.stop();
  EXPECT_GE(bridge.bridge().processorCounters().dropped_confidence, 1u);
  EXPECT_GE(bridge.bridge().processorCounters().dropped_invalid, 1u);
}

TEST(PupilSource, IgnoresOtherSurfacesAndPrefixTopics) {
  zmq::context_t context;
  PupilEmulator pupil(context);
  GazeReceiver receiver(context);
  gaze_bridge::PupilParams params;
  params.remote_port = pupil.remotePort();
  BridgeThread bridge(context, std::make_unique<gaze_bridge::PupilSource>(context, params),
                      rawParams(receiver.endpoint()));
  const std::string wrong = packSurfaceMessage("screen2", {{0.9, 0.9, 1.0, true, 1.0}});
  const std::string right = packSurfaceMessage("screen", {{0.1, 0.9, 1.0, true, 2.0}});
  const auto end = std::chrono::steady_clock::now() + kWait;
  std::optional<gsph::v1::GazeSample> got;
  while (!got && std::chrono::steady_clock::now() < end) {
    pupil.publish("surfaces.screen2", wrong);
    pupil.publish("surfaces.screen", right);
    got = receiver.receiveUntil([](const auto& s) { return s.valid(); }, 20ms);
    ASSERT_FALSE(got && got->tracker_time_s() == 1.0) << "sample of surface screen2 came through";
  }
  ASSERT_TRUE(got);
  EXPECT_EQ(got->tracker_time_s(), 2.0);
}

TEST(PupilSource, ResumesAfterCaptureRestartsOnAnotherPort) {
  zmq::context_t context;
  auto pupil = std::make_unique<PupilEmulator>(context);
  const int remote_port = pupil->remotePort();
  GazeReceiver receiver(context);
  gaze_bridge::PupilParams params;
  params.remote_port = remote_port;
  params.tracker_timeout_s = 1.0;
  BridgeThread bridge(context, std::make_unique<gaze_bridge::PupilSource>(context, params),
                      rawParams(receiver.endpoint()));
  ASSERT_TRUE(publishUntil(*pupil, "surfaces.screen", packSurfaceMessage("screen", {{0.3, 0.3, 1.0, true, 1.0}}),
                           receiver, [](const auto& s) { return s.valid(); }));
  const int old_pub_port = pupil->pubPort();
  pupil.reset();  // Capture quits
  // The bridge reports the gaze lost (max gap 0.5 s) ...
  ASSERT_TRUE(receiver.receiveUntil([](const auto& s) { return s.lost(); }));
  // ... and Capture comes back: same Pupil Remote port, a new backbone port.
  pupil = std::make_unique<PupilEmulator>(context, remote_port);
  ASSERT_NE(pupil->pubPort(), old_pub_port);
  auto resumed = publishUntil(*pupil, "surfaces.screen", packSurfaceMessage("screen", {{0.7, 0.2, 1.0, true, 2.0}}),
                              receiver, [](const auto& s) { return s.valid() && s.tracker_time_s() == 2.0; });
  ASSERT_TRUE(resumed);
  EXPECT_TRUE(near(resumed->x(), 0.7));
  EXPECT_TRUE(near(resumed->y(), 0.8));
  EXPECT_GE(pupil->portRequests(), 1);
}

TEST(GazepointSource, BridgeSendsCommandsAndTurnsSplitRecordsIntoPoints) {
  zmq::context_t context;
  GazepointEmulator tracker;
  GazeReceiver receiver(context);
  gaze_bridge::GazepointParams params;
  params.port = tracker.port();
  BridgeThread bridge(context, std::make_unique<gaze_bridge::GazepointSource>(params), rawParams(receiver.endpoint()));

  const auto end = std::chrono::steady_clock::now() + kWait;
  while (tracker.acked() < 3 && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(5ms);
  ASSERT_EQ(tracker.acked(), 3);
  EXPECT_EQ(tracker.commandsReceived(),
            "<SET ID=\"ENABLE_SEND_POG_BEST\" STATE=\"1\" />\n<SET ID=\"ENABLE_SEND_TIME\" STATE=\"1\" />\n"
            "<SET ID=\"ENABLE_SEND_DATA\" STATE=\"1\" />\n");
  ASSERT_TRUE(warmUp(tracker, receiver));
  // Two records merged into one write, an invalid one, a malformed line, then one more; every write
  // leaves in pieces of 1..13 bytes.
  tracker.send(gazepointRecord(1.000, 0.125, 0.875, true) + gazepointRecord(1.016, 0.25, 0.5, true));
  tracker.send(gazepointRecord(1.032, 0.9, 0.9, false));
  tracker.send("<REC TIME=\"1.040\" BPOGX=\"oops\" />\r\n");
  tracker.send(gazepointRecord(1.048, 0.75, 0.0625, true));
  std::vector<gsph::v1::GazeSample> got;
  while (got.size() < 3) {
    // Warm-up records (tracker time 100 s and later) still in flight are not this test's.
    auto s = receiver.receiveUntil([](const auto& g) { return g.valid() && g.tracker_time_s() < 100.0; });
    ASSERT_TRUE(s) << "got " << got.size();
    got.push_back(*s);
  }
  EXPECT_EQ(got[0].tracker_time_s(), 1.0);
  EXPECT_TRUE(near(got[0].x(), 0.125));
  EXPECT_TRUE(near(got[0].y(), 0.875));  // Gazepoint is already top-left
  EXPECT_EQ(got[1].tracker_time_s(), 1.016);
  EXPECT_EQ(got[2].tracker_time_s(), 1.048);  // the invalid record and the malformed line never show
  EXPECT_TRUE(near(got[2].x(), 0.75));
  EXPECT_EQ(got[0].source_id(), "gazepoint");
  EXPECT_EQ(got[0].confidence(), 1.0f);
}

TEST(GazepointSource, ResumesAfterTrackerDropsConnection) {
  zmq::context_t context;
  GazepointEmulator tracker;
  GazeReceiver receiver(context);
  gaze_bridge::GazepointParams params;
  params.port = tracker.port();
  // Silence is not what this tests: a stalled machine must not make the bridge reconnect (the
  // emulator then forgets what it was about to send).
  params.tracker_timeout_s = 30.0;
  BridgeThread bridge(context, std::make_unique<gaze_bridge::GazepointSource>(params), rawParams(receiver.endpoint()));
  const auto wait_for = [&](auto condition) {
    const auto end = std::chrono::steady_clock::now() + kWait;
    while (!condition() && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(5ms);
    return condition();
  };
  ASSERT_TRUE(wait_for([&] { return tracker.acked() == 3; }));
  ASSERT_TRUE(warmUp(tracker, receiver));

  tracker.dropClient();
  ASSERT_TRUE(wait_for([&] { return tracker.connections() == 2 && tracker.acked() == 3; }));
  tracker.send(gazepointRecord(0.5, 0.6, 0.4, true));  // the tracker's clock restarted too
  auto resumed = receiver.receiveUntil([](const auto& s) { return s.valid() && s.tracker_time_s() == 0.5; });
  ASSERT_TRUE(resumed);
  EXPECT_TRUE(near(resumed->x(), 0.6));
  EXPECT_TRUE(near(resumed->y(), 0.4));
}

TEST(GazepointSource, ResumesWhenTrackerStartsAfterTheBridge) {
  zmq::context_t context;
  // A port held bound but not listening: the bridge's connections are refused, as with no tracker
  // there, and no other test can take the port before the tracker does.
  auto reserved = std::make_unique<sph_test::ReservedPort>();
  const int port = reserved->port();
  GazeReceiver receiver(context);
  gaze_bridge::GazepointParams params;
  params.port = port;
  params.tracker_timeout_s = 30.0;  // as above: silence is not what this tests
  auto raw = rawParams(receiver.endpoint());
  raw.processor.lost_repeat_s = 0.5;  // a "lost" the receiver's late subscription missed comes again soon
  BridgeThread bridge(context, std::make_unique<gaze_bridge::GazepointSource>(params), raw);
  // Nobody listens: the bridge says "lost" and keeps trying.
  ASSERT_TRUE(receiver.receiveUntil([](const auto& s) { return s.lost(); }));
  reserved.reset();
  GazepointEmulator tracker(port);
  const auto end = std::chrono::steady_clock::now() + kWait;
  while (tracker.acked() < 3 && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(5ms);
  ASSERT_EQ(tracker.acked(), 3);
  tracker.send(gazepointRecord(3.0, 0.5, 0.5, true));
  EXPECT_TRUE(receiver.receiveUntil([](const auto& s) { return s.valid() && s.tracker_time_s() == 3.0; }));
}
