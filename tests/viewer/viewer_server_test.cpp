// Round trips with the real sph_server: the viewer's pose becomes the server's projection, the
// viewer's mouse gaze moves the refined (L0) region, and fluid mode draws the server's water.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <thread>
#include <zmq.hpp>

#include "camera_reference.h"
#include "decoded_frame.h"
#include "viewer_process.h"
#include "x11_input.h"

using namespace viewer_test;
using namespace std::chrono_literals;

namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 360;
constexpr auto kWait = 40s;

struct ServerEndpoints {
  std::string frames, gaze, pose, control;
};

// sph_server on free loopback ports; it logs the endpoints it bound.
class ServerProcess {
 public:
  // `scene_dir` empty: the shipped scenes. `extra`: more server options.
  ServerProcess(const std::string& dir, const std::string& scene, const std::string& scene_dir = "",
                const std::vector<std::string>& extra = {})
      : log_(dir + "/server.log") {
    std::vector<std::string> args{SPH_SERVER_PATH,
                                  "--scene",
                                  scene,
                                  "--method",
                                  "gaze",
                                  "--frames-endpoint",
                                  "tcp://127.0.0.1:*",
                                  "--gaze-endpoint",
                                  "tcp://127.0.0.1:*",
                                  "--pose-endpoint",
                                  "tcp://127.0.0.1:*",
                                  "--control-endpoint",
                                  "tcp://127.0.0.1:*",
                                  "--threads",
                                  "1",
                                  "--status-interval",
                                  "0",
                                  "--preset",  // sph_test::kCheapPreset (tests/support/server_args.h)
                                  "thesis"};
    if (!scene_dir.empty()) {
      args.push_back("--scene-dir");
      args.push_back(scene_dir);
    }
    args.insert(args.end(), extra.begin(), extra.end());
    process_ = std::make_unique<ChildProcess>(args, log_);
    const auto deadline = std::chrono::steady_clock::now() + kWait;
    while (std::chrono::steady_clock::now() < deadline && endpoints_.control.empty()) {
      const std::string text = readFile(log_);
      endpoints_.frames = find(text, "endpoint frames ");
      endpoints_.gaze = find(text, "endpoint gaze ");
      endpoints_.pose = find(text, "endpoint pose ");
      endpoints_.control = find(text, "endpoint control ");
      std::this_thread::sleep_for(20ms);
    }
    if (endpoints_.control.empty()) throw std::runtime_error("sph_server did not start: " + readFile(log_));
  }
  ~ServerProcess() {
    process_->terminate();
    process_->waitExit(10s);
  }
  const ServerEndpoints& endpoints() const { return endpoints_; }
  std::vector<std::string> viewerArgs() const {
    return {"--frames-endpoint", endpoints_.frames, "--gaze-endpoint",    endpoints_.gaze,
            "--pose-endpoint",   endpoints_.pose,   "--control-endpoint", endpoints_.control};
  }
  std::string log() const { return readFile(log_); }

 private:
  static std::string find(const std::string& text, const std::string& key) {
    const auto at = text.find(key);
    if (at == std::string::npos) return {};
    const auto start = at + key.size();
    const auto end = text.find_first_of(" \n", start);
    return end == std::string::npos ? std::string() : text.substr(start, end - start);
  }
  std::string log_;
  std::unique_ptr<ChildProcess> process_;
  ServerEndpoints endpoints_;
};

// Reads the server's frames until `predicate` holds (newest frame only, like the viewer).
class FrameWatcher {
 public:
  explicit FrameWatcher(const std::string& endpoint) {
    sub_.set(zmq::sockopt::conflate, 1);
    sub_.set(zmq::sockopt::linger, 0);
    sub_.set(zmq::sockopt::subscribe, "");
    sub_.connect(endpoint);
  }
  template <typename Predicate>
  bool waitFor(Predicate predicate, gsph::v1::Frame* out = nullptr) {
    const auto deadline = std::chrono::steady_clock::now() + kWait;
    while (std::chrono::steady_clock::now() < deadline) {
      zmq::pollitem_t item{sub_.handle(), 0, ZMQ_POLLIN, 0};
      zmq::poll(&item, 1, 100ms);
      zmq::message_t m;
      if (!(item.revents & ZMQ_POLLIN) || !sub_.recv(m, zmq::recv_flags::dontwait)) continue;
      gsph::v1::Frame frame;
      if (!frame.ParseFromArray(m.data(), static_cast<int>(m.size()))) continue;
      if (predicate(frame)) {
        if (out != nullptr) *out = frame;
        return true;
      }
    }
    return false;
  }

 private:
  zmq::context_t context_;
  zmq::socket_t sub_{context_, zmq::socket_type::sub};
};

bool viewNear(const gsph::v1::CameraPose& pose, const Mat4d& expected, double tolerance) {
  if (pose.view_size() != 16) return false;
  for (int i = 0; i < 16; ++i) {
    if (std::abs(pose.view(i) - expected[static_cast<std::size_t>(i)]) > tolerance) return false;
  }
  return true;
}

// Screen position (normalized, origin top left) of every L0 particle, through the frame's camera.
std::vector<std::array<double, 2>> smallOnScreen(const gsph::v1::Frame& frame) {
  viewer::DecodedFrame decoded;
  std::string error;
  std::vector<std::array<double, 2>> out;
  if (!viewer::decodeFrame(frame, decoded, error) || frame.camera().view_size() != 16) return out;
  for (std::size_t i = 0; i < decoded.particleCount(); ++i) {
    if (decoded.classes[i] != viewer::kClassSmall) continue;
    const auto& p = decoded.positions[i];
    const auto px =
        projectToPixel(frame.camera().view().data(), frame.camera().projection().data(), {p.x, p.y, p.z}, 1, 1);
    out.push_back(px);
  }
  return out;
}

// Most L0 particles lie within `reach` (fraction of width) of the gaze point (x, y).
bool refinedAround(const gsph::v1::Frame& frame, double x, double y, double reach) {
  if (frame.gaze().mode() != gsph::v1::GAZE_MODE_TRACKING) return false;
  if (std::abs(frame.gaze().x() - x) > 0.02 || std::abs(frame.gaze().y() - y) > 0.02) return false;
  const auto small = smallOnScreen(frame);
  if (small.size() < 4) return false;
  const double aspect = static_cast<double>(frame.camera().viewport_width()) / frame.camera().viewport_height();
  std::size_t near = 0;
  for (const auto& s : small) {
    const double dx = s[0] - x, dy = (s[1] - y) / aspect;  // in widths
    near += std::sqrt(dx * dx + dy * dy) <= reach;
  }
  return near >= small.size() * 8 / 10;
}

}  // namespace

TEST(ViewerServerRoundTrip, ServerProjectsWithTheViewersPose) {
  const std::string dir = scratchDir();
  ServerProcess server(dir, "small_box");
  FrameWatcher frames(server.endpoints().frames);
  auto args = server.viewerArgs();
  for (const char* a : {"--eye", "0.9", "1.1", "1.6", "--target", "0.3", "0.1", "0.3", "--viewer-id", "rt-pose",
                        "--width", "640", "--height", "360", "--no-panel"}) {
    args.push_back(a);
  }
  auto viewer = startViewer(args, dir + "/viewer.log");
  const Mat4d expected = referenceLookAt({0.9, 1.1, 1.6}, {0.3, 0.1, 0.3});
  gsph::v1::Frame frame;
  EXPECT_TRUE(frames.waitFor(
      [&](const gsph::v1::Frame& f) {
        return f.camera().viewer_id() == "rt-pose" && viewNear(f.camera(), expected, 1e-4);
      },
      &frame))
      << "viewer:\n"
      << readFile(dir + "/viewer.log") << "server:\n"
      << server.log();
  EXPECT_EQ(frame.camera().viewport_width(), static_cast<unsigned>(kWidth));
  EXPECT_EQ(frame.camera().viewport_height(), static_cast<unsigned>(kHeight));
  viewer->terminate();
  EXPECT_TRUE(viewer->waitExit(20s).has_value());
}

TEST(ViewerServerRoundTrip, MouseGazeMovesTheRefinedRegion) {
  const std::string dir = scratchDir();
  // A pool at rest (the dam break's water would move away between picking the targets and the
  // refinement reaching them, by how much depending on the machine's speed).
  ServerProcess server(dir, "tiny_pool", SPH_NET_TEST_SCENE_DIR);
  FrameWatcher frames(server.endpoints().frames);
  auto args = server.viewerArgs();
  // Close to the pool so that it fills much of the screen.
  for (const char* a : {"--mouse-gaze", "--viewer-id", "rt-gaze", "--width", "640", "--height", "360", "--no-panel",
                        "--eye", "0.2", "0.45", "0.55", "--target", "0.2", "0.05", "0.2"}) {
    args.push_back(a);
  }
  auto viewer = startViewer(args, dir + "/viewer.log");
  X11Input x;
  std::optional<std::pair<int, int>> origin;
  const auto deadline = std::chrono::steady_clock::now() + kWait;
  while (!(origin = x.windowOrigin("sph_viewer rt-gaze")) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(20ms);
  }
  ASSERT_TRUE(origin.has_value()) << readFile(dir + "/viewer.log");
  // The water on screen, through the camera the server now uses (the viewer's).
  gsph::v1::Frame frame;
  ASSERT_TRUE(frames.waitFor([](const gsph::v1::Frame& f) { return f.camera().viewer_id() == "rt-gaze"; }, &frame))
      << server.log();
  viewer::DecodedFrame decoded;
  std::string error;
  ASSERT_TRUE(viewer::decodeFrame(frame, decoded, error)) << error;
  std::vector<std::array<double, 2>> water;
  for (const auto& p : decoded.positions) {
    water.push_back(
        projectToPixel(frame.camera().view().data(), frame.camera().projection().data(), {p.x, p.y, p.z}, 1, 1));
  }
  std::sort(water.begin(), water.end());
  // Two gaze points on the water, left and right, far enough apart that their rings do not touch.
  const auto a = water[water.size() / 5], b = water[water.size() * 4 / 5];
  ASSERT_GT(b[0] - a[0], 0.2) << "the water spans too little of the screen for this test";
  for (const auto& target : {a, b}) {
    x.movePointer(origin->first + static_cast<int>(target[0] * kWidth),
                  origin->second + static_cast<int>(target[1] * kHeight));
    const double gx = std::floor(target[0] * kWidth) / kWidth, gy = std::floor(target[1] * kHeight) / kHeight;
    // Inside the ring (0.08 W) plus a particle radius of slack.
    EXPECT_TRUE(frames.waitFor([&](const gsph::v1::Frame& f) { return refinedAround(f, gx, gy, 0.1); }))
        << "no refinement around " << gx << "," << gy << "\n"
        << server.log();
  }
  viewer->terminate();
  EXPECT_TRUE(viewer->waitExit(20s).has_value());
}

TEST(ViewerServerRoundTrip, FluidModeDrawsTheServersWaterWithItsNeighbourCounts) {
  const std::string dir = scratchDir();
  ServerProcess server(dir, "tiny_pool", SPH_NET_TEST_SCENE_DIR, {"--neighbor-counts"});
  FrameWatcher frames(server.endpoints().frames);
  gsph::v1::Frame frame;
  ASSERT_TRUE(frames.waitFor([](const gsph::v1::Frame& f) { return f.particle_count() > 0; }, &frame)) << server.log();
  EXPECT_EQ(frame.neighbor_counts().size(), frame.particle_count());
  auto args = server.viewerArgs();
  for (const char* a :
       {"--viewer-id", "rt-fluid", "--width", "640",       "--height", "360",  "--no-panel", "--eye",
        "0.2",         "0.45",     "0.55",    "--target",  "0.2",      "0.05", "0.2",        "--render-debug",
        "depth",       "--frames", "3",       "--timeout", "150"}) {
    args.push_back(a);
  }
  args.push_back("--snapshot");
  args.push_back(dir + "/fluid.png");
  auto viewer = startViewer(args, dir + "/viewer.log");
  const auto code = viewer->waitExit(200s);
  ASSERT_TRUE(code.has_value() && *code == 0) << readFile(dir + "/viewer.log");
  viewer::RgbaImage image;
  std::string error;
  ASSERT_TRUE(viewer::readPng(dir + "/fluid.png", image, error)) << error;
  // The pool is there as a surface (depth pixels are not the white of "no water").
  int water = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) water += pixel(image, x, y).b != 255 || pixel(image, x, y).r != 255;
  }
  EXPECT_GT(water, image.width * image.height / 10);
}
