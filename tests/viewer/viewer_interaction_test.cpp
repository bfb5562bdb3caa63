// The viewer talking back: camera pose, mouse drag, mouse gaze, keys to Control, reconnects.
#include <gtest/gtest.h>

#include <cmath>

#include "camera_reference.h"
#include "test_frames.h"
#include "test_publisher.h"
#include "viewer_process.h"
#include "x11_input.h"

using namespace viewer_test;
using namespace std::chrono_literals;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr auto kWait = 30s;
constexpr double kOrbitRadiansPerPixel = 0.006;  // client_viewer/orbit_camera.cpp

FrameSpec oneParticle(std::uint8_t size_class) {
  FrameSpec spec;
  spec.particles = {{0.0f, 0.0f, 0.0f, size_class}};
  spec.radius_small = spec.radius_large = 0.1f;
  return spec;
}

std::vector<std::string> viewerArgs(const TestServer& server, const std::string& id, std::vector<std::string> more) {
  std::vector<std::string> args = {
      "--width", std::to_string(kWidth), "--height", std::to_string(kHeight), "--viewer-id", id, "--no-panel"};
  const auto endpoints = server.endpointArgs();
  args.insert(args.end(), endpoints.begin(), endpoints.end());
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

bool matrixNear(const google::protobuf::RepeatedField<float>& m, const Mat4d& expected, double tolerance) {
  if (m.size() != 16) return false;
  for (int i = 0; i < 16; ++i) {
    if (std::abs(m[i] - expected[static_cast<std::size_t>(i)]) > tolerance) return false;
  }
  return true;
}

std::pair<int, int> waitForWindow(X11Input& x, const std::string& title) {
  const auto deadline = std::chrono::steady_clock::now() + kWait;
  while (std::chrono::steady_clock::now() < deadline) {
    if (auto origin = x.windowOrigin(title)) return *origin;
    std::this_thread::sleep_for(20ms);
  }
  throw std::runtime_error("viewer window " + title + " did not appear");
}

}  // namespace

TEST(ViewerPose, MatchesTheCameraOptionsAndKeepsComing) {
  const std::string dir = scratchDir();
  TestServer server(makeFrame(oneParticle(0), 1));
  auto viewer = startViewer(
      viewerArgs(server, "pose-test", {"--eye", "1", "1.3", "2.7", "--target", "1", "0.15", "0.4", "--fov", "50"}),
      dir + "/viewer.log");
  gsph::v1::CameraPose first, later;
  ASSERT_TRUE(server.waitForPose([](const auto& p) { return p.viewer_id() == "pose-test"; }, kWait, &first))
      << readFile(dir + "/viewer.log");
  EXPECT_EQ(first.protocol_version(), 1u);
  EXPECT_EQ(first.viewport_width(), static_cast<unsigned>(kWidth));
  EXPECT_EQ(first.viewport_height(), static_cast<unsigned>(kHeight));
  EXPECT_TRUE(matrixNear(first.view(), referenceLookAt({1, 1.3, 2.7}, {1, 0.15, 0.4}), 1e-4));
  // near/far are the viewer's own choice; the parts gaze projection uses (x, y, w rows) must match
  const Mat4d p = referencePerspective(50.0, static_cast<double>(kWidth) / kHeight, 0.02, 100.0);
  EXPECT_NEAR(first.projection(0), p[0], 1e-4);
  EXPECT_NEAR(first.projection(5), p[5], 1e-4);
  EXPECT_NEAR(first.projection(11), -1.0, 1e-6);
  // Re-sent without any change (the server may start after the viewer).
  const auto seq = first.sequence();
  EXPECT_TRUE(server.waitForPose([seq](const auto& pose) { return pose.sequence() >= seq + 3; }, kWait, &later));
  viewer->terminate();
  EXPECT_TRUE(viewer->waitExit(kWait).has_value());
}

TEST(ViewerPose, MouseDragOrbitsTheCameraAndThePoseFollows) {
  const std::string dir = scratchDir();
  TestServer server(makeFrame(oneParticle(1), 1));
  auto viewer =
      startViewer(viewerArgs(server, "drag", {"--eye", "0", "0.5", "2", "--target", "0", "0", "0", "--mouse-gaze"}),
                  dir + "/viewer.log");
  X11Input x;
  const auto [wx, wy] = waitForWindow(x, "sph_viewer drag");
  // Park the pointer and wait until the viewer has seen it there (its mouse gaze reports it).
  x.movePointer(wx + 100, wy + 120);
  ASSERT_TRUE(
      server.waitForGaze([](const auto& g) { return g.valid() && std::abs(g.x() * kWidth - 100) < 1.5; }, kWait))
      << readFile(dir + "/viewer.log");
  x.button(1, true);
  for (int step = 1; step <= 5; ++step) x.movePointer(wx + 100 + 20 * step, wy + 120);
  // Expected: yaw turned by -100 px * 0.006 rad, i.e. the eye rotated about +y through the target.
  const double theta = -100 * kOrbitRadiansPerPixel;
  const Vec3d eye = {0.0 * std::cos(theta) + 2.0 * std::sin(theta), 0.5, 2.0 * std::cos(theta) - 0.0 * std::sin(theta)};
  const Mat4d expected = referenceLookAt(eye, {0, 0, 0});
  const bool orbited = server.waitForPose([&](const auto& p) { return matrixNear(p.view(), expected, 2e-3); }, kWait);
  x.button(1, false);
  EXPECT_TRUE(orbited) << readFile(dir + "/viewer.log");
  viewer->terminate();
  EXPECT_TRUE(viewer->waitExit(kWait).has_value());
}

TEST(ViewerGaze, MouseGazeFollowsTheCursorAndGoesInvalidOutside) {
  const std::string dir = scratchDir();
  TestServer server(makeFrame(oneParticle(0), 1));
  auto viewer = startViewer(viewerArgs(server, "gaze", {"--mouse-gaze"}), dir + "/viewer.log");
  X11Input x;
  const auto [wx, wy] = waitForWindow(x, "sph_viewer gaze");
  x.movePointer(wx + 80, wy + 180);
  gsph::v1::GazeSample sample;
  ASSERT_TRUE(server.waitForGaze(
      [](const auto& g) { return g.valid() && std::abs(g.x() - 0.25) < 0.01 && std::abs(g.y() - 0.75) < 0.01; }, kWait,
      &sample))
      << readFile(dir + "/viewer.log");
  EXPECT_EQ(sample.source_id(), "mouse");
  EXPECT_EQ(sample.protocol_version(), 1u);
  x.movePointer(wx + 240, wy + 60);
  gsph::v1::GazeSample inside;
  EXPECT_TRUE(server.waitForGaze(
      [](const auto& g) { return g.valid() && std::abs(g.x() - 0.75) < 0.01 && std::abs(g.y() - 0.25) < 0.01; }, kWait,
      &inside));
  x.movePointer(wx + kWidth + 200, wy + 60);
  // Invalid after the pointer left (samples before it entered the window were invalid too).
  EXPECT_TRUE(server.waitForGaze([&](const auto& g) { return !g.valid() && g.sequence() > inside.sequence(); }, kWait));
  viewer->terminate();
  EXPECT_TRUE(viewer->waitExit(kWait).has_value());
}

TEST(ViewerControl, SpaceKeySendsPauseAndStatusIsPolled) {
  const std::string dir = scratchDir();
  TestServer server(makeFrame(oneParticle(0), 1));
  auto viewer = startViewer(viewerArgs(server, "keys", {"--mouse-gaze"}), dir + "/viewer.log");
  X11Input x;
  const auto [wx, wy] = waitForWindow(x, "sph_viewer keys");
  x.movePointer(wx + 50, wy + 50);
  ASSERT_TRUE(server.waitForGaze([](const auto& g) { return g.valid(); }, kWait)) << readFile(dir + "/viewer.log");
  x.focus("sph_viewer keys");
  auto has = [&server](bool (gsph::v1::Control::*test)() const) {
    const auto deadline = std::chrono::steady_clock::now() + kWait;
    while (std::chrono::steady_clock::now() < deadline) {
      for (const auto& c : server.controlsReceived()) {
        if ((c.*test)()) return true;
      }
      std::this_thread::sleep_for(20ms);
    }
    return false;
  };
  EXPECT_TRUE(has(&gsph::v1::Control::has_status));
  x.key("space");
  EXPECT_TRUE(has(&gsph::v1::Control::has_pause)) << readFile(dir + "/viewer.log");
  viewer->terminate();
  EXPECT_TRUE(viewer->waitExit(kWait).has_value());
}

TEST(ViewerNet, ReconnectsAfterAServerRestartAndShowsTheNewFrames) {
  const std::string dir = scratchDir();
  // Server A: an L1 (red) particle, carrying the camera the viewer should adopt; it sends 5
  // frames in all, so it cannot supply the 40 the snapshot waits for however fast it runs.
  FrameSpec red = oneParticle(1);
  auto frame_a = makeFrame(red, 100);
  const Mat4d view = referenceLookAt({0.3, 0.4, 2.0}, {0, 0, 0});
  const Mat4d projection = referencePerspective(45.0, static_cast<double>(kWidth) / kHeight, 0.05, 20.0);
  frame_a.mutable_camera()->mutable_view()->Assign(view.begin(), view.end());
  frame_a.mutable_camera()->mutable_projection()->Assign(projection.begin(), projection.end());
  auto server_a = std::make_unique<TestServer>(frame_a, "", 100, 20ms, 5);
  const std::string endpoint = server_a->framesEndpoint();
  auto viewer = startViewer(
      viewerArgs(*server_a, "restart",
                 {"--snapshot", dir + "/after.png", "--frames", "40", "--timeout", "150", "--render", "particles"}),
      dir + "/viewer.log");
  // The viewer adopted A's camera: it has drawn A's frame.
  ASSERT_TRUE(server_a->waitForPose([&](const auto& p) { return matrixNear(p.view(), view, 1e-4); }, kWait))
      << readFile(dir + "/viewer.log");
  server_a.reset();
  // Server B on the same frames endpoint, counting from 1 again, an L0 particle.
  // (Pose, gaze and control of B are on new ports; only the frame stream is tested here.)
  TestServer server_b(makeFrame(oneParticle(0), 1), endpoint, 1);
  const auto deadline = std::chrono::steady_clock::now() + kWait;
  while (!server_b.subscribed() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(10ms);
  ASSERT_TRUE(server_b.subscribed()) << "viewer did not reconnect";
  const auto code = viewer->waitExit(180s);
  ASSERT_TRUE(code.has_value() && *code == 0) << readFile(dir + "/viewer.log");
  viewer::RgbaImage image;
  std::string error;
  ASSERT_TRUE(viewer::readPng(dir + "/after.png", image, error)) << error;
  const auto centre =
      projectToPixel(std::vector<float>(view.begin(), view.end()).data(),
                     std::vector<float>(projection.begin(), projection.end()).data(), {0, 0, 0}, kWidth, kHeight);
  const Colour c = pixel(image, static_cast<int>(centre[0]), static_cast<int>(centre[1]));
  EXPECT_TRUE(isL0(c)) << c.r << " " << c.g << " " << c.b;
}

TEST(ViewerGaze, FixedGazePointIsSent) {
  const std::string dir = scratchDir();
  TestServer server(makeFrame(oneParticle(0), 1));
  auto viewer = startViewer(viewerArgs(server, "gaze-at", {"--gaze-at", "0.2", "0.7"}), dir + "/viewer.log");
  EXPECT_TRUE(server.waitForGaze(
      [](const auto& g) { return g.valid() && std::abs(g.x() - 0.2) < 1e-6 && std::abs(g.y() - 0.7) < 1e-6; }, kWait))
      << readFile(dir + "/viewer.log");
  viewer->terminate();
  EXPECT_TRUE(viewer->waitExit(kWait).has_value());
}
