// Emulated tracker -> bridge (default processing: One Euro filter on) -> a socket in the test standing
// in for sph_server, plus the recording of what was sent.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "bridge_harness.h"
#include "emulators.h"
#include "gaze/gaze_recording.h"
#include "gazepoint_source.h"

using namespace gaze_bridge_test;
using namespace std::chrono_literals;

namespace {

std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "gaze_bridge_" + name + "_" + std::to_string(::getpid()) + ".csv";
}

// Streams a fixation at (x, y) from the emulated Gazepoint at about 200 Hz until the receiver has a
// filtered sample within 0.002 of it (with `want_fixation`, one I-VT marks as a fixation), or 30 s
// pass. (A stall of the machine longer than the bridge's gap limit resets its filter, and the
// next sample is the raw point, not yet a fixation: waiting for the flag keeps the test exact.)
std::optional<gsph::v1::GazeSample> fixateUntilConverged(GazepointEmulator& tracker, GazeReceiver& receiver,
                                                         double& time_s, double x, double y,
                                                         bool want_fixation = false) {
  const auto end = std::chrono::steady_clock::now() + kWait;
  while (std::chrono::steady_clock::now() < end) {
    time_s += 0.005;
    tracker.send(gazepointRecord(time_s, x, y, true));
    auto s = receiver.receiveUntil([](const auto& g) { return g.valid(); }, 5ms);
    if (s && std::abs(s->x() - x) < 0.002 && std::abs(s->y() - y) < 0.002 && (!want_fixation || s->fixation())) {
      return s;
    }
  }
  return std::nullopt;
}

void waitForAcks(GazepointEmulator& tracker) {
  const auto end = std::chrono::steady_clock::now() + kWait;
  while (tracker.acked() < 3 && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(5ms);
  ASSERT_EQ(tracker.acked(), 3);
}

}  // namespace

TEST(EndToEnd, FilteredGazeFollowsFixationsAndIsRecorded) {
  zmq::context_t context;
  GazepointEmulator tracker;
  GazeReceiver receiver(context);
  gaze_bridge::GazepointParams source;
  source.port = tracker.port();
  gaze_bridge::BridgeParams params;  // defaults: filter on, confidence 0.6, max gap 0.2 s
  params.publisher.endpoint = receiver.endpoint();
  params.processor.ivt = true;
  params.record_path = tempPath("record");
  std::uint64_t tracker_samples = 0, sent = 0;
  {
    BridgeThread bridge(context, std::make_unique<gaze_bridge::GazepointSource>(source), params);
    waitForAcks(tracker);
    double t = 0.0;
    // Two fixations: the point sent converges to each target (the filter does not stick to the old one).
    auto first = fixateUntilConverged(tracker, receiver, t, 0.2, 0.3);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->source_id(), "gazepoint");
    auto second = fixateUntilConverged(tracker, receiver, t, 0.8, 0.6, true);
    ASSERT_TRUE(second) << "no settled sample flagged a fixation (I-VT)";
    EXPECT_GT(second->sequence(), first->sequence());
    EXPECT_GT(second->bridge_time_us(), first->bridge_time_us());
    // The bridge clock is the system clock in microseconds.
    const auto now_us =
        std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
            .count();
    EXPECT_LE(second->bridge_time_us(), now_us);
    EXPECT_GT(second->bridge_time_us(), now_us - 60'000'000);
    bridge.stop();
    tracker_samples = bridge.bridge().counters().tracker_samples;
    sent = bridge.bridge().counters().sent;
  }
  // The recording holds what was sent, readable by the recording reader.
  const auto recording = gaze::readGazeRecording(params.record_path);
  EXPECT_EQ(recording.samples.size(), sent);
  EXPECT_GT(tracker_samples, 0u);
  const auto& last = recording.samples.back();
  EXPECT_NEAR(last.x, 0.8, 0.01);
  EXPECT_NEAR(last.y, 0.6, 0.01);
  std::remove(params.record_path.c_str());
}

TEST(EndToEnd, PushSocketToPullServer) {
  zmq::context_t context;
  GazepointEmulator tracker;
  GazeReceiver receiver(context, zmq::socket_type::pull);
  gaze_bridge::GazepointParams source;
  source.port = tracker.port();
  auto params = rawParams(receiver.endpoint());
  params.publisher.socket = gaze_bridge::PublisherSocket::kPush;
  params.source_id = "lab-gazepoint";
  BridgeThread bridge(context, std::make_unique<gaze_bridge::GazepointSource>(source), params);
  waitForAcks(tracker);
  // PUSH drops what it cannot hand to a connected peer (the bridge never blocks on a slow server),
  // and on a loaded machine the connect may still be under way: resend until one arrives.
  std::optional<gsph::v1::GazeSample> s;
  double t = 7.0;
  const auto end = std::chrono::steady_clock::now() + kWait;
  while (!s && std::chrono::steady_clock::now() < end) {
    tracker.send(gazepointRecord(t += 0.005, 0.33, 0.66, true));
    s = receiver.receiveUntil([](const auto& g) { return g.valid(); }, 10ms);
  }
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->x(), 0.33, 1e-6);
  EXPECT_NEAR(s->y(), 0.66, 1e-6);
  EXPECT_EQ(s->source_id(), "lab-gazepoint");
}

TEST(EndToEnd, ServerRestartIsReconnected) {
  zmq::context_t context;
  GazepointEmulator tracker;
  auto receiver = std::make_unique<GazeReceiver>(context);
  const std::string endpoint = receiver->endpoint();
  gaze_bridge::GazepointParams source;
  source.port = tracker.port();
  BridgeThread bridge(context, std::make_unique<gaze_bridge::GazepointSource>(source), rawParams(endpoint));
  waitForAcks(tracker);
  double t = 0;
  const auto stream_until_seen = [&](GazeReceiver& r) {
    const auto end = std::chrono::steady_clock::now() + kWait;
    while (std::chrono::steady_clock::now() < end) {
      tracker.send(gazepointRecord(t += 0.005, 0.4, 0.4, true));
      if (r.receiveUntil([](const auto& g) { return g.valid(); }, 10ms)) return true;
    }
    return false;
  };
  ASSERT_TRUE(stream_until_seen(*receiver));
  receiver.reset();                   // the server goes away ...
  std::this_thread::sleep_for(50ms);  // (not a pass/fail decision: lets the bridge send into the void)
  // ... and comes back on the same endpoint (retrying the bind while the old listener closes).
  std::unique_ptr<zmq::socket_t> server;
  const auto bind_end = std::chrono::steady_clock::now() + kWait;
  while (!server && std::chrono::steady_clock::now() < bind_end) {
    try {
      server = std::make_unique<zmq::socket_t>(context, zmq::socket_type::sub);
      server->set(zmq::sockopt::linger, 0);
      server->set(zmq::sockopt::subscribe, "");
      server->bind(endpoint);
    } catch (const zmq::error_t&) {
      server.reset();
      std::this_thread::sleep_for(20ms);
    }
  }
  ASSERT_TRUE(server);
  const auto end = std::chrono::steady_clock::now() + kWait;
  bool seen = false;
  while (!seen && std::chrono::steady_clock::now() < end) {
    tracker.send(gazepointRecord(t += 0.005, 0.4, 0.4, true));
    zmq::pollitem_t item{server->handle(), 0, ZMQ_POLLIN, 0};
    zmq::poll(&item, 1, 10ms);
    zmq::message_t message;
    if ((item.revents & ZMQ_POLLIN) && server->recv(message, zmq::recv_flags::dontwait)) {
      gsph::v1::GazeSample sample;
      seen = sample.ParseFromArray(message.data(), static_cast<int>(message.size())) && sample.valid();
    }
  }
  EXPECT_TRUE(seen);
}
