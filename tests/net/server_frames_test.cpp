// sph_server in-process over real loopback sockets: frames carry the library's state, a gaze sample
// moves the refined region, and a camera pose from a client changes the projection.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <functional>
#include <optional>

#include "net/frame_encoder.h"
#include "net/input_validation.h"
#include "net_test_util.h"
#include "scene/scene_loader.h"
#include "sph/simulation.h"

namespace {

using net_test::FrameSubscriber;
using net_test::Publisher;

// Runs `steps` steps of the regular method in the test thread the way the server does (one thread).
sph::Simulation referenceRun(int steps) {
  omp_set_num_threads(1);
  sph::Simulation sim(scene::loadScene("tiny_pool", SPH_NET_TEST_SCENE_DIR), sph::Level{0});
  for (int i = 0; i < steps; ++i) sim.step();
  return sim;
}

// The frame of step `steps` from a server running the regular method free, its options first
// changed by `configure`.
std::optional<gsph::v1::Frame> frameOfStep(int steps, const std::function<void(app::ServerOptions&)>& configure) {
  auto options = net_test::testOptions(sph::Method::Regular);
  options.sim.settings.free_run = true;
  options.sim.max_steps = steps;
  configure(options);
  auto server = net_test::startServer(options);
  zmq::context_t ctx;
  FrameSubscriber sub(ctx, server->endpoints().frames);
  // After max_steps the server keeps publishing the final state, so a late joiner still sees it.
  return sub.waitFor([&](const gsph::v1::Frame& f) { return f.step() == steps; });
}

void expectFrameMatches(bool quantized) {
  constexpr int kSteps = 5;
  auto frame = frameOfStep(kSteps, [&](app::ServerOptions& o) { o.sim.settings.quantized = quantized; });
  ASSERT_TRUE(frame);
  const sph::Simulation ref = referenceRun(kSteps);
  const sph::ParticleSet& p = ref.particles();
  ASSERT_EQ(frame->particle_count(), p.size());
  ASSERT_GE(frame->level_counts_size(), 2);
  EXPECT_EQ(frame->level_counts(0), p.size());
  EXPECT_EQ(frame->scene(), "tiny_pool");
  EXPECT_EQ(frame->method(), gsph::v1::METHOD_REGULAR);
  EXPECT_DOUBLE_EQ(frame->sim_time(), ref.time());
  const std::vector<float> xyz = net::decodePositions(*frame);
  ASSERT_EQ(xyz.size(), 3 * p.size());
  const sph::BoxState box = ref.boxNow();
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      if (quantized) {
        ASSERT_NEAR(xyz[3 * i + a], p.position[i][a], (box.max[a] - box.min[a]) / 65535.0 + 1e-6);
      } else {
        ASSERT_EQ(xyz[3 * i + a], p.position[i][a]) << "particle " << i;
      }
    }
  }
}

TEST(ServerFrames, Float32FramesMatchTheLibraryState) { expectFrameMatches(false); }

TEST(ServerFrames, QuantizedFramesMatchTheLibraryState) { expectFrameMatches(true); }

// The regular method splits and merges nothing, so the counts are exactly the library's.
TEST(ServerFrames, NeighborCountsOnlyWhenAsked) {
  constexpr int kSteps = 3;
  for (const bool asked : {false, true}) {
    auto frame = frameOfStep(kSteps, [&](app::ServerOptions& o) { o.sim.neighbor_counts = asked; });
    ASSERT_TRUE(frame);
    if (!asked) {
      EXPECT_TRUE(frame->neighbor_counts().empty());
      continue;
    }
    const sph::Simulation ref = referenceRun(kSteps);
    ASSERT_EQ(frame->neighbor_counts().size(), ref.particles().size());
    for (std::size_t i = 0; i < ref.particles().size(); ++i) {
      ASSERT_EQ(static_cast<std::uint8_t>(frame->neighbor_counts()[i]),
                std::min<std::uint32_t>(ref.grid().neighborCount(i), 255u))
          << "particle " << i;
    }
  }
}

// Every frame offered gets the next number; one the pipe drops (a descheduled network thread)
// shows as a gap, so the test allows gaps but never a repeat or a step back, and needs some two
// frames in a row one apart.
TEST(ServerFrames, SequenceNumbersIncreaseByOne) {
  auto server = net_test::startServer(net_test::testOptions(sph::Method::Regular));
  zmq::context_t ctx;
  FrameSubscriber sub(ctx, server->endpoints().frames);
  auto previous = sub.next();
  ASSERT_TRUE(previous);
  EXPECT_EQ(previous->camera().viewer_id(), "scene");
  EXPECT_GT(previous->send_time_us(), 0);
  auto adjacent = sub.waitFor([&](const gsph::v1::Frame& f) {
    EXPECT_GT(f.sequence(), previous->sequence()) << "a repeat or a step back";
    const bool by_one = f.sequence() == previous->sequence() + 1;
    previous = f;
    return by_one;
  });
  ASSERT_TRUE(adjacent);
  server->stop();
  const auto& counters = server->simCounters();
  EXPECT_LT(previous->sequence(), counters.frames_published.load() + counters.frames_dropped.load());
}

struct GazeRun {
  std::unique_ptr<app::Server> server;
  zmq::context_t ctx;
  std::unique_ptr<FrameSubscriber> sub;
  std::unique_ptr<Publisher> gaze;
  std::uint64_t sequence = 0;

  explicit GazeRun(const app::ServerOptions& options) : server(net_test::startServer(options)) {
    sub = std::make_unique<FrameSubscriber>(ctx, server->endpoints().frames);
    gaze = std::make_unique<Publisher>(ctx, server->endpoints().gaze);
  }
  // Sends the gaze point (again each wait, as a tracker streams) until a frame refined by it has
  // L0 particles near it on the screen of `camera` and hardly any near the opposite corner. (Before
  // the first sample the lost-gaze policy refines the surface everywhere; those merge back once
  // tracking, except a few stragglers that find no merge partner.)
  // Waits for a frame refined at (x, y) (and meeting `also`, when given): the step count at which
  // the refinement settles depends on the machine, so every condition a test checks on the frame
  // is part of the wait.
  std::optional<gsph::v1::Frame> lookAt(double x, double y, const sph::ScreenCamera& camera,
                                        const std::string& viewer = "scene",
                                        const std::function<bool(const gsph::v1::Frame&)>& also = {}) {
    return sub->waitFor(
        [&](const gsph::v1::Frame& f) {
          if (f.gaze().mode() != gsph::v1::GAZE_MODE_TRACKING || std::abs(f.gaze().x() - x) > 1e-6 ||
              std::abs(f.gaze().y() - y) > 1e-6 || f.camera().viewer_id() != viewer) {
            return false;
          }
          const auto small = net_test::smallOnScreen(f, camera);
          const int near = net_test::countNear(small, camera, x, y, 0.2);
          return near > 10 && net_test::countNear(small, camera, 1.0 - x, 1.0 - y, 0.2) * 20 < near &&
                 (!also || also(f));
        },
        [&] { gaze->send(net_test::gazeSample(x, y, ++sequence)); });
  }
};

TEST(ServerFrames, GazeSampleMovesTheRefinedRegion) {
  GazeRun run(net_test::testOptions(sph::Method::Gaze));
  const sph::ScreenCamera camera = sph::cameraFromSpec(scene::loadScene("tiny_pool", SPH_NET_TEST_SCENE_DIR).camera);

  auto at_a = run.lookAt(0.25, 0.25, camera);
  ASSERT_TRUE(at_a);
  const auto small_a = net_test::smallOnScreen(*at_a, camera);
  const int near_a = net_test::countNear(small_a, camera, 0.25, 0.25, 0.2);
  EXPECT_GT(near_a, 10);
  EXPECT_LT(net_test::countNear(small_a, camera, 0.75, 0.75, 0.2) * 20, near_a);
  ASSERT_GE(at_a->level_counts_size(), 2);
  EXPECT_GT(at_a->level_counts(1), 0u);
  // The frame echoes the sample it used, for latency measurement.
  EXPECT_EQ(at_a->gaze().source_id(), "test");
  EXPECT_GT(at_a->gaze().sample_sequence(), 0u);
  EXPECT_GT(at_a->gaze().sample_bridge_time_us(), 0);
  EXPECT_GE(at_a->gaze().age_ms(), 0.0f);
  EXPECT_FLOAT_EQ(at_a->gaze().radius(), 0.12f);

  // Looking at the opposite corner refines there and merges the old region back.
  auto at_c = run.sub->waitFor(
      [&](const gsph::v1::Frame& f) {
        if (f.gaze().mode() != gsph::v1::GAZE_MODE_TRACKING || std::abs(f.gaze().x() - 0.75) > 1e-6) return false;
        const auto small = net_test::smallOnScreen(f, camera);
        return net_test::countNear(small, camera, 0.75, 0.75, 0.2) > 10 &&
               net_test::countNear(small, camera, 0.25, 0.25, 0.2) <= near_a / 2;
      },
      [&] { run.gaze->send(net_test::gazeSample(0.75, 0.75, ++run.sequence)); });
  ASSERT_TRUE(at_c);
}

TEST(ServerFrames, CameraPoseFromAClientChangesTheProjection) {
  GazeRun run(net_test::testOptions(sph::Method::Gaze));
  const sph::Scene scene = scene::loadScene("tiny_pool", SPH_NET_TEST_SCENE_DIR);
  const sph::ScreenCamera scene_camera = sph::cameraFromSpec(scene.camera);
  // The scene camera has the screen's top left over the pool's low-x, low-z corner.
  auto before = run.lookAt(0.25, 0.25, scene_camera, "scene", [](const gsph::v1::Frame& f) {
    const Eigen::Vector2d xz = net_test::smallMeanXZ(f);
    return xz.x() < 0.2 && xz.y() < 0.2;
  });
  ASSERT_TRUE(before);

  // The same view turned half around (up +z instead of -z): the screen's top left now lies over the
  // opposite corner of the pool.
  sph::CameraSpec turned = scene.camera;
  turned.up = Eigen::Vector3d(0, 0, 1);
  const sph::ScreenCamera client_camera = sph::cameraFromSpec(turned);
  gsph::v1::CameraPose pose;
  net::fromScreenCamera(client_camera, pose);
  pose.set_viewer_id("test-viewer");
  Publisher poses(run.ctx, run.server->endpoints().pose);
  auto after = run.sub->waitFor(
      [&](const gsph::v1::Frame& f) {
        return f.camera().viewer_id() == "test-viewer" && f.gaze().mode() == gsph::v1::GAZE_MODE_TRACKING &&
               net_test::smallMeanXZ(f).x() > 0.2 && net_test::smallMeanXZ(f).y() > 0.2 &&
               net_test::countNear(net_test::smallOnScreen(f, client_camera), client_camera, 0.25, 0.25, 0.2) > 10;
      },
      [&] {
        poses.send(pose);
        run.gaze->send(net_test::gazeSample(0.25, 0.25, ++run.sequence));
      });
  ASSERT_TRUE(after);
  const sph::ScreenCamera echoed = net::toScreenCamera(after->camera());
  EXPECT_LT(net_test::maxAbsDiff(echoed.view, client_camera.view), 1e-5);
}

TEST(ServerFrames, GazeOverPushPullIsTakenToo) {
  auto options = net_test::testOptions(sph::Method::Gaze);
  options.net.gaze_type = net::InputSocketType::Pull;
  auto server = net_test::startServer(options);
  zmq::context_t ctx;
  FrameSubscriber sub(ctx, server->endpoints().frames);
  zmq::socket_t push(ctx, zmq::socket_type::push);
  push.set(zmq::sockopt::linger, 0);
  push.connect(server->endpoints().gaze);
  std::uint64_t sequence = 0;
  // Two-part messages (a topic, then the payload) are accepted as well.
  auto frame = sub.waitFor(
      [](const gsph::v1::Frame& f) { return f.gaze().source_id() == "test" && f.gaze().sample_sequence() > 0; },
      [&] {
        (void)push.send(zmq::str_buffer("gaze"), zmq::send_flags::sndmore | zmq::send_flags::dontwait);
        (void)push.send(zmq::buffer(net_test::gazeSample(0.4, 0.6, ++sequence).SerializeAsString()),
                        zmq::send_flags::dontwait);
      });
  ASSERT_TRUE(frame);
  EXPECT_NEAR(frame->gaze().x(), 0.4, 1e-6);
}

TEST(ServerFrames, CameraSourceIgnoresOtherViewers) {
  auto options = net_test::testOptions(sph::Method::Gaze);
  options.sim.camera_source = "main";
  GazeRun run(options);
  gsph::v1::CameraPose other;
  sph::CameraSpec spec = scene::loadScene("tiny_pool", SPH_NET_TEST_SCENE_DIR).camera;
  net::fromScreenCamera(sph::cameraFromSpec(spec), other);
  other.set_viewer_id("other");
  gsph::v1::CameraPose main_pose = other;
  main_pose.set_viewer_id("main");
  Publisher poses(run.ctx, run.server->endpoints().pose);
  // Only the configured viewer's pose is taken; "other" keeps arriving first and never shows.
  auto frame = run.sub->waitFor(
      [&](const gsph::v1::Frame& f) {
        EXPECT_NE(f.camera().viewer_id(), "other");
        return f.camera().viewer_id() == "main";
      },
      [&] {
        poses.send(other);
        poses.send(main_pose);
        poses.send(other);
      });
  ASSERT_TRUE(frame);
}

}  // namespace
