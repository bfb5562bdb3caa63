// The real viewer under a real (virtual) X display: pictures, poses, gaze, reconnects.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

#include "camera_reference.h"
#include "level_colours.h"
#include "support/reserved_port.h"
#include "test_frames.h"
#include "test_publisher.h"
#include "viewer_process.h"

using namespace viewer_test;
using namespace std::chrono_literals;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr auto kWait = 20s;

// Two L0 and two L1 particles well apart, in front of a camera at (0, 0, 2.5).
FrameSpec fourParticles() {
  FrameSpec spec;
  spec.particles = {{-0.5f, 0.3f, 0.0f, 0}, {0.5f, -0.3f, 0.2f, 0}, {0.5f, 0.3f, -0.2f, 1}, {-0.5f, -0.3f, 0.0f, 1}};
  spec.radius_small = 0.06f;
  spec.radius_large = 0.08f;
  spec.box_lo = -0.8f;
  spec.box_hi = 0.8f;
  return spec;
}

// Particles mode: these tests look at the size-class colours.
std::vector<std::string> cameraArgs() {
  return {"--eye",      "0",
          "0",          "2.5",
          "--target",   "0",
          "0",          "0",
          "--fov",      "45",
          "--width",    std::to_string(kWidth),
          "--height",   std::to_string(kHeight),
          "--no-panel", "--render",
          "particles"};
}

std::vector<std::string> join(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

viewer::RgbaImage loadPng(const std::string& path) {
  viewer::RgbaImage image;
  std::string error;
  EXPECT_TRUE(viewer::readPng(path, image, error)) << error;
  return image;
}

// What a pixel shows: background, an L0 or L1 particle, or an outline (grey), by the nearest
// chromaticity (shading scales a colour and keeps it). Shades along a sphere's rim change with
// sub-pixel shifts, so pictures are compared by this.
int pixelKind(Colour c) {
  // The background is at most 26 bright; an L0 sphere's darkest shade (30 % of its colour) 41.
  const int brightest = std::max({c.r, c.g, c.b});
  if (brightest < 35) return 0;
  const double sum = c.r + c.g + c.b;
  const auto distance = [&](double r, double g, double b) {
    const double s = r + g + b;
    return std::hypot(c.r / sum - r / s, c.g / sum - g / s, c.b / sum - b / s);
  };
  const viewer::LevelRgb l0 = viewer::levelColour(0, 2), l1 = viewer::levelColour(1, 2);
  const double d[3] = {distance(l0.r, l0.g, l0.b), distance(l1.r, l1.g, l1.b), distance(1, 1, 1)};
  return 1 + static_cast<int>(std::min_element(d, d + 3) - d);
}

// Every pixel of `a` has a pixel of the same kind in `b` at most one pixel away.
bool sameWithinOnePixel(const viewer::RgbaImage& a, const viewer::RgbaImage& b, std::string& where) {
  if (a.width != b.width || a.height != b.height) return false;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const int kind = pixelKind(pixel(a, x, y));
      bool matched = false;
      for (int dy = -1; dy <= 1 && !matched; ++dy) {
        for (int dx = -1; dx <= 1 && !matched; ++dx) {
          if (x + dx < 0 || y + dy < 0 || x + dx >= b.width || y + dy >= b.height) continue;
          matched = pixelKind(pixel(b, x + dx, y + dy)) == kind;
        }
      }
      if (!matched) {
        where = std::to_string(x) + "," + std::to_string(y);
        return false;
      }
    }
  }
  return true;
}

// 400 particles scattered in a box a little larger than their cloud.
FrameSpec cloudInABox() {
  FrameSpec spec;
  spec.particles = particleCloud(400, -0.6f, 0.6f);
  spec.box_lo = -0.8f;
  spec.box_hi = 0.8f;
  return spec;
}

}  // namespace

TEST(ViewerWindow, ParticlesAppearInTheirLevelsColourWhereProjected) {
  const std::string dir = scratchDir();
  FrameSpec spec = fourParticles();
  spec.with_gaze = true;  // circle of 0.1 W around the screen centre
  TestServer server(makeFrame(spec, 1));
  auto viewer = startViewer(
      join(join(cameraArgs(), server.endpointArgs()), {"--snapshot", dir + "/window.png", "--frames", "3", "--visible",
                                                       "--viewer-id", "pixels", "--timeout", "120"}),
      dir + "/viewer.log");
  const auto code = viewer->waitExit(150s);
  ASSERT_TRUE(code.has_value()) << readFile(dir + "/viewer.log");
  ASSERT_EQ(*code, 0) << readFile(dir + "/viewer.log");
  gsph::v1::CameraPose pose;
  ASSERT_TRUE(server.waitForPose([](const auto& p) { return p.viewer_id() == "pixels"; }, kWait, &pose));
  const auto image = loadPng(dir + "/window.png");
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  for (const auto& p : spec.particles) {
    const auto px = projectToPixel(pose.view().data(), pose.projection().data(), {p.x, p.y, p.z}, kWidth, kHeight);
    const Colour c = pixel(image, static_cast<int>(px[0]), static_cast<int>(px[1]));
    if (p.level == 0) {
      EXPECT_TRUE(isL0(c)) << "L0 at " << px[0] << "," << px[1] << " is " << c.r << " " << c.g << " " << c.b;
    } else {
      EXPECT_TRUE(isL1(c)) << "L1 at " << px[0] << "," << px[1] << " is " << c.r << " " << c.g << " " << c.b;
    }
  }
  // Between the particles there is only background, so a picture that is all one colour fails.
  EXPECT_TRUE(isDark(pixel(image, kWidth / 2, kHeight / 2 - 30)));
  // A back corner of the box outline (light grey lines meet there).
  const auto corner = projectToPixel(pose.view().data(), pose.projection().data(), {0.8, 0.8, -0.8}, kWidth, kHeight);
  EXPECT_TRUE(anyNear(image, corner[0], corner[1], 2, [](Colour c) { return c.r > 150 && c.g > 150 && c.b > 150; }));
  // Gaze circle, radius 0.1 W = 32 px about the centre: yellow on its rim, not at its centre.
  auto yellow = [](Colour c) { return c.r > 180 && c.g > 160 && c.b < 90; };
  EXPECT_TRUE(anyNear(image, kWidth / 2.0 + 32, kHeight / 2.0, 2, yellow));
  EXPECT_TRUE(anyNear(image, kWidth / 2.0, kHeight / 2.0 - 32, 2, yellow));
  EXPECT_FALSE(anyNear(image, kWidth / 2.0, kHeight / 2.0, 3, yellow));
}

// One particle per size level, each level its own radius (level_radii) and colour (the colour map
// spread over the four levels).
TEST(ViewerWindow, SizeLevelsDrawWithTheirRadiusAndColour) {
  const std::string dir = scratchDir();
  FrameSpec spec;
  spec.particles = {
      {-0.35f, 0.25f, 0.0f, 0}, {0.35f, 0.25f, 0.0f, 1}, {-0.35f, -0.25f, 0.0f, 2}, {0.35f, -0.25f, 0.0f, 3}};
  spec.level_radii = {0.04f, 0.06f, 0.09f, 0.12f};
  spec.radius_small = spec.level_radii[0];
  spec.radius_large = spec.level_radii[1];
  spec.box_lo = -0.8f;
  spec.box_hi = 0.8f;
  TestServer server(makeFrame(spec, 1));
  auto viewer = startViewer(
      join(join(cameraArgs(), server.endpointArgs()),
           {"--snapshot", dir + "/levels.png", "--frames", "2", "--viewer-id", "levels", "--timeout", "120"}),
      dir + "/viewer.log");
  const auto code = viewer->waitExit(150s);
  ASSERT_TRUE(code.has_value() && *code == 0) << readFile(dir + "/viewer.log");
  gsph::v1::CameraPose pose;
  ASSERT_TRUE(server.waitForPose([](const auto& p) { return p.viewer_id() == "levels"; }, kWait, &pose));
  const auto image = loadPng(dir + "/levels.png");
  const auto colourOf = [](std::size_t level) { return [level](Colour c) { return isLevel(c, level, 4); }; };
  for (const auto& p : spec.particles) {
    const float r = spec.level_radii[p.level];
    const auto centre = projectToPixel(pose.view().data(), pose.projection().data(), {p.x, p.y, p.z}, kWidth, kHeight);
    const auto rim = projectToPixel(pose.view().data(), pose.projection().data(), {p.x + r, p.y, p.z}, kWidth, kHeight);
    const double r_px = rim[0] - centre[0];
    const auto at = [&](double fraction) {
      return pixel(image, static_cast<int>(centre[0] + fraction * r_px), static_cast<int>(centre[1]));
    };
    const Colour c = at(0.0);
    EXPECT_TRUE(colourOf(p.level)(c)) << "level " << static_cast<int>(p.level) << " is " << c.r << " " << c.g << " "
                                      << c.b;
    EXPECT_FALSE(isDark(at(0.75))) << "level " << static_cast<int>(p.level) << " drawn smaller than its radius";
    EXPECT_TRUE(isDark(at(1.35))) << "level " << static_cast<int>(p.level) << " drawn larger than its radius";
  }
}

TEST(ViewerWindow, QuantizedAndFloatFramesRenderTheSamePicture) {
  const std::string dir = scratchDir();
  FrameSpec spec = cloudInABox();
  std::vector<viewer::RgbaImage> images;
  for (bool quantized : {false, true}) {
    spec.quantized = quantized;
    TestServer server(makeFrame(spec, 1));
    const std::string png = dir + (quantized ? "/quantized.png" : "/float.png");
    auto viewer = startViewer(
        join(join(cameraArgs(), server.endpointArgs()), {"--snapshot", png, "--frames", "2", "--timeout", "120"}),
        dir + "/viewer.log");
    const auto code = viewer->waitExit(150s);
    ASSERT_TRUE(code.has_value() && *code == 0) << readFile(dir + "/viewer.log");
    images.push_back(loadPng(png));
  }
  int coloured = 0;
  for (int y = 0; y < images[0].height; ++y) {
    for (int x = 0; x < images[0].width; ++x) coloured += isL0(pixel(images[0], x, y)) || isL1(pixel(images[0], x, y));
  }
  EXPECT_GT(coloured, 2000);  // the cloud is really there
  std::string where;
  EXPECT_TRUE(sameWithinOnePixel(images[0], images[1], where)) << "float pixel " << where << " unmatched";
  EXPECT_TRUE(sameWithinOnePixel(images[1], images[0], where)) << "quantized pixel " << where << " unmatched";
}

// A render cap (--max-fps, for software GL sharing the server's cores) still draws the picture an
// uncapped viewer draws.
TEST(ViewerWindow, ARenderCapDrawsTheSamePicture) {
  const std::string dir = scratchDir();
  const FrameSpec spec = cloudInABox();
  std::vector<viewer::RgbaImage> images;
  for (const char* cap : {"0", "4"}) {
    TestServer server(makeFrame(spec, 1));
    const std::string png = dir + "/cap" + cap + ".png";
    auto viewer = startViewer(join(join(cameraArgs(), server.endpointArgs()),
                                   {"--snapshot", png, "--frames", "3", "--max-fps", cap, "--timeout", "120"}),
                              dir + "/viewer" + cap + ".log");
    const auto code = viewer->waitExit(150s);
    ASSERT_TRUE(code.has_value() && *code == 0) << readFile(dir + "/viewer" + cap + ".log");
    images.push_back(loadPng(png));
  }
  std::string where;
  EXPECT_TRUE(sameWithinOnePixel(images[0], images[1], where)) << "uncapped pixel " << where << " unmatched";
  EXPECT_TRUE(sameWithinOnePixel(images[1], images[0], where)) << "capped pixel " << where << " unmatched";
}

// The test frames' sim time is 0.01 s per sequence number: 30 frames never reach 0.5 s, 100 do.
TEST(ViewerWindow, SnapshotAtWaitsForTheSimTime) {
  const std::string dir = scratchDir();
  for (const std::uint64_t frames : {30u, 100u}) {
    TestServer server(makeFrame(fourParticles(), 1), "", 1, std::chrono::milliseconds(20), frames);
    const std::string tag = std::to_string(frames);
    auto viewer =
        startViewer(join(join(cameraArgs(), server.endpointArgs()),
                         {"--snapshot", dir + "/at" + tag + ".png", "--snapshot-at", "0.5", "--timeout", "8"}),
                    dir + "/viewer" + tag + ".log");
    const auto code = viewer->waitExit(60s);
    ASSERT_TRUE(code.has_value());
    EXPECT_EQ(*code, frames < 50 ? 3 : 0) << readFile(dir + "/viewer" + tag + ".log");
  }
}

// No frame, no picture: a PNG of the empty window would pass for the water; the exit code and the
// log say what happened.
TEST(ViewerWindow, WaitsForServerAndTimesOutWithoutAPicture) {
  const std::string dir = scratchDir();
  // An endpoint no server is on: a TCP port held bound but not listening, so connections are
  // refused and no other test can take the port meanwhile.
  const sph_test::ReservedPort reserved;
  const std::string endpoint = reserved.tcpEndpoint();
  auto viewer = startViewer({"--frames-endpoint", endpoint, "--snapshot", dir + "/waiting.png", "--timeout", "1.5",
                             "--width", "320", "--height", "240"},
                            dir + "/viewer.log");
  const auto code = viewer->waitExit(60s);
  ASSERT_TRUE(code.has_value());
  EXPECT_EQ(*code, 3) << readFile(dir + "/viewer.log");
  EXPECT_NE(readFile(dir + "/viewer.log").find("no frame from a server at " + endpoint), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir + "/waiting.png"));
}

TEST(ViewerOptions, HelpListsEveryOptionAndBadOptionsFail) {
  const std::string dir = scratchDir();
  auto help = startViewer({"--help"}, dir + "/help.log");
  ASSERT_EQ(help->waitExit(20s), std::optional<int>(0));
  const std::string text = readFile(dir + "/help.log");
  for (const char* option :
       {"--frames-endpoint", "--pose-endpoint", "--gaze-endpoint", "--control-endpoint", "--mouse-gaze", "--snapshot",
        "--frames", "--eye", "--target", "--report", "--render", "--render-debug", "--fluid-scale", "--max-fps"}) {
    EXPECT_NE(text.find(option), std::string::npos) << option;
  }
  auto exitOf = [&dir](std::vector<std::string> args, const std::string& log) {
    return startViewer(std::move(args), dir + "/" + log)->waitExit(20s);
  };
  // Every usage error exits 2, CLI11's own checks included (cli::parse maps them).
  EXPECT_EQ(exitOf({"--width", "-5"}, "bad.log"), std::optional<int>(2));
  EXPECT_EQ(exitOf({"--render", "voxels"}, "bad_mode.log"), std::optional<int>(2));
  EXPECT_EQ(exitOf({"--max-fps", "-1"}, "bad_fps.log"), std::optional<int>(2));
  EXPECT_EQ(exitOf({"--eye", "0", "0", "1"}, "half_camera.log"), std::optional<int>(2));
  // Thickness is a fluid pass; particles mode has none to show.
  EXPECT_EQ(exitOf({"--render", "particles", "--render-debug", "thickness"}, "thickness.log"), std::optional<int>(2));
}
