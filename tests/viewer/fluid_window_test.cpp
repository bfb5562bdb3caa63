// Fluid mode under a real (virtual) X display, on frames the test publishes: a resting pool comes
// out flat, L1 and L0 particles make one surface, thicker water is darker, spray the frame
// marks is drawn apart from the surface, and the overlays stay.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fluid_picture.h"
#include "test_frames.h"
#include "test_publisher.h"
#include "viewer_process.h"

using namespace viewer_test;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr double kSmall = 0.02;     // particle radii, metres
constexpr double kLarge = 0.0252;   // 2^(1/3) kSmall: an L1 particle has twice the volume
constexpr double kPoolTop = -1.48;  // the pools' surface, 12 cm above the floor of the box
constexpr float kBoxHalf = 1.6f;    // box [-1.6, 1.6]^3
const Vec3d kUp{0.0, 1.0, 0.0};

std::vector<std::string> cameraArgs(const std::string& eye_x, const std::string& eye_y, const std::string& eye_z,
                                    const std::string& target_y) {
  return {"--eye",     eye_x,
          eye_y,       eye_z,
          "--target",  "0",
          target_y,    "0",
          "--fov",     "45",
          "--width",   std::to_string(kWidth),
          "--height",  std::to_string(kHeight),
          "--no-panel"};
}

// Looking down at about 55 degrees onto the middle of the pool, which reaches past every edge of
// the picture, so that each pixel shows its top surface.
std::vector<std::string> poolCamera(std::vector<std::string> more) {
  auto args = cameraArgs("0", std::to_string(kPoolTop + 0.88), "0.6", std::to_string(kPoolTop));
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

FrameSpec poolSpec() {
  FrameSpec spec;
  spec.radius_small = static_cast<float>(kSmall);
  spec.radius_large = static_cast<float>(kLarge);
  spec.box_lo = -kBoxHalf;
  spec.box_hi = kBoxHalf;
  return spec;
}

struct NormalStats {
  int water = 0;
  int within_10_degrees = 0;
  double mean_degrees = 0.0;
  double fraction() const { return water > 0 ? static_cast<double>(within_10_degrees) / water : 0.0; }
};

// The normals of the columns [x0, x1) against the pool's normal in view space.
NormalStats normalStats(const Snapshot& shot, int x0, int x1) {
  const Vec3d up = toView(shot.pose, kUp);
  NormalStats s;
  for (int y = 0; y < shot.image.height; ++y) {
    for (int x = x0; x < x1; ++x) {
      const auto n = decodeNormal(shot.image, x, y);
      if (!n) continue;
      const double angle = angleDegrees(*n, up);
      ++s.water;
      s.within_10_degrees += angle <= 10.0;
      s.mean_degrees += angle;
    }
  }
  if (s.water > 0) s.mean_degrees /= s.water;
  return s;
}

// Mean world height of the surface the depth picture shows in columns [x0, x1), middle rows.
double meanHeight(const Snapshot& shot, int x0, int x1, int* samples) {
  double sum = 0.0;
  *samples = 0;
  for (int y = shot.image.height / 10; y < shot.image.height * 9 / 10; ++y) {
    for (int x = x0; x < x1; ++x) {
      const auto depth = decodeMetres(shot.image, x, y);
      if (!depth) continue;
      sum += worldPoint(shot.pose, x, y, *depth)[1];
      ++*samples;
    }
  }
  return *samples > 0 ? sum / *samples : 0.0;
}

}  // namespace

// At the default scale of software GL (half resolution) and at full resolution.
TEST(FluidWindow, RestingPoolIsFlatInFluidModeAndBeadsInParticleMode) {
  const std::string dir = scratchDir();
  FrameSpec spec = poolSpec();
  appendPool(spec.particles, -1.5, 1.5, -1.5, 1.5, kPoolTop, 3, kSmall, 0);
  TestServer server(makeFrame(spec, 1));
  for (const char* scale : {"2", "1"}) {
    auto fluid = takeSnapshot(server, poolCamera({"--render-debug", "normals", "--fluid-scale", scale}), dir,
                              std::string("fluid-") + scale);
    ASSERT_TRUE(fluid);
    const NormalStats s = normalStats(*fluid, 0, kWidth);
    EXPECT_GT(s.water, kWidth * kHeight * 9 / 10) << "the pool should fill the picture";
    EXPECT_GE(s.fraction(), 0.95) << "scale " << scale << ": " << s.within_10_degrees << " of " << s.water
                                  << " water pixels within 10 degrees, mean " << s.mean_degrees;
  }
  auto beads = takeSnapshot(server, poolCamera({"--render", "particles", "--render-debug", "normals"}), dir, "beads");
  ASSERT_TRUE(beads);
  const NormalStats b = normalStats(*beads, 0, kWidth);
  EXPECT_GT(b.water, kWidth * kHeight * 9 / 10);
  EXPECT_LT(b.fraction(), 0.95) << "sphere impostors pass the flatness check: it cannot fail";
  EXPECT_LT(b.fraction(), 0.5) << b.within_10_degrees << " of " << b.water;
}

TEST(FluidWindow, LargeAndSmallHalvesMeetWithoutASeam) {
  const std::string dir = scratchDir();
  FrameSpec spec = poolSpec();
  // L1 left of x = 0, L0 right of it, both tops at the same height: the seam is the
  // picture's middle column.
  appendPool(spec.particles, -1.5, 0.0, -1.5, 1.5, kPoolTop, 3, kLarge, 1, /*from_x1=*/true);
  appendPool(spec.particles, 0.0, 1.5, -1.5, 1.5, kPoolTop, 4, kSmall, 0);
  TestServer server(makeFrame(spec, 1));
  auto normals = takeSnapshot(server, poolCamera({"--render-debug", "normals"}), dir, "normals");
  auto depth = takeSnapshot(server, poolCamera({"--render-debug", "depth"}), dir, "depth");
  ASSERT_TRUE(normals && depth);
  const NormalStats large = normalStats(*normals, 0, kWidth / 2);
  const NormalStats small = normalStats(*normals, kWidth / 2, kWidth);
  EXPECT_NEAR(large.mean_degrees, small.mean_degrees, 2.0);
  EXPECT_LT(large.mean_degrees, 5.0);
  EXPECT_LT(small.mean_degrees, 5.0);
  // No step at the seam: the surface either side of it, 2 to 8 pixels out, at one height.
  int left_samples = 0, right_samples = 0;
  const double left = meanHeight(*depth, kWidth / 2 - 8, kWidth / 2 - 2, &left_samples);
  const double right = meanHeight(*depth, kWidth / 2 + 2, kWidth / 2 + 8, &right_samples);
  ASSERT_GT(left_samples, 500);
  ASSERT_GT(right_samples, 500);
  EXPECT_NEAR(left, right, 0.2 * kSmall) << "L1 side " << left << " m, L0 side " << right << " m";
  // And that height is the pool's surface (the decoding and the camera agree).
  EXPECT_NEAR(left, kPoolTop, 2.0 * kLarge);
}

TEST(FluidWindow, ThickerWaterIsDarker) {
  const std::string dir = scratchDir();
  FrameSpec spec = poolSpec();
  spec.with_box = false;  // against the sky, the same behind every part of the wedge
  // A wedge facing the camera: front face at z = 0, depth from 4 cm at x = -0.6 to 34 cm at 0.6
  // (past that the absorption has taken most of the light and the colour changes little).
  const double r = kSmall, spacing = kSpacingPerRadius * kSmall;
  for (double x = -0.6 + r; x < 0.6; x += spacing) {
    const int layers = std::max(1, static_cast<int>(std::lround((0.04 + 0.3 * (x + 0.6) / 1.2) / spacing)));
    for (double y = -0.3 + r; y < 0.3; y += spacing) {
      for (int k = 0; k < layers; ++k) {
        spec.particles.push_back(
            {static_cast<float>(x), static_cast<float>(y), static_cast<float>(-r - k * spacing), 0});
      }
    }
  }
  TestServer server(makeFrame(spec, 1));
  auto shot = takeSnapshot(server, cameraArgs("0", "0", "1.6", "0"), dir, "wedge");
  ASSERT_TRUE(shot);
  // Mean brightness in 8 bins across the wedge's inner 70 %, middle half of its height.
  const auto left =
      projectToPixel(shot->pose.view().data(), shot->pose.projection().data(), {-0.6, 0.0, 0.0}, kWidth, kHeight);
  const auto right =
      projectToPixel(shot->pose.view().data(), shot->pose.projection().data(), {0.6, 0.0, 0.0}, kWidth, kHeight);
  const auto top =
      projectToPixel(shot->pose.view().data(), shot->pose.projection().data(), {0.0, 0.3, 0.0}, kWidth, kHeight);
  const double x0 = left[0] + 0.15 * (right[0] - left[0]), x1 = right[0] - 0.15 * (right[0] - left[0]);
  const double half_height = kHeight / 2.0 - top[1];
  constexpr int kBins = 8;
  std::vector<double> brightness;
  for (int b = 0; b < kBins; ++b) {
    double sum = 0.0;
    int n = 0;
    for (int x = static_cast<int>(x0 + b * (x1 - x0) / kBins); x < static_cast<int>(x0 + (b + 1) * (x1 - x0) / kBins);
         ++x) {
      for (int y = static_cast<int>(kHeight / 2.0 - half_height / 2); y < kHeight / 2.0 + half_height / 2; ++y) {
        const Colour c = pixel(shot->image, x, y);
        sum += (c.r + c.g + c.b) / 3.0;
        ++n;
      }
    }
    brightness.push_back(sum / n);
  }
  std::string bins;
  for (double v : brightness) bins += std::to_string(v) + " ";
  for (int b = 1; b < kBins; ++b) EXPECT_LE(brightness[b], brightness[b - 1] + 1.0) << "bins: " << bins;
  EXPECT_GT(brightness.front() - brightness.back(), 25.0) << "bins: " << bins;
  // The sky beside the wedge is brighter than its thinnest part: the water absorbs.
  const Colour sky = pixel(shot->image, std::max(2, static_cast<int>(left[0]) - 12), kHeight / 2);
  EXPECT_GT((sky.r + sky.g + sky.b) / 3.0, brightness.front());
}

// With neighbour counts a lone particle is spray: left out of the surface (its pixel is no water
// in the depth picture) and drawn as a droplet; without them it is part of the surface.
TEST(FluidWindow, SprayTheFrameMarksIsDrawnApartFromTheSurface) {
  const std::string dir = scratchDir();
  constexpr double kRadius = 0.03;
  FrameSpec spec = poolSpec();
  spec.radius_small = spec.radius_large = static_cast<float>(kRadius);
  appendPool(spec.particles, -0.6, 0.6, -0.6, 0.6, kPoolTop, 2, kRadius, 0);
  const Vec3d drop{0.1, kPoolTop + 0.25, 0.1};
  spec.particles.push_back({static_cast<float>(drop[0]), static_cast<float>(drop[1]), static_cast<float>(drop[2]), 0});
  const auto camera = poolCamera({});
  std::vector<Snapshot> shots;
  for (const bool counts : {false, true}) {
    spec.neighbor_counts.assign(counts ? spec.particles.size() : 0, 20);
    if (counts) spec.neighbor_counts.back() = 0;
    TestServer server(makeFrame(spec, 1));
    const std::string tag = counts ? "counts" : "nocounts";
    auto depth = takeSnapshot(server, poolCamera({"--render-debug", "depth"}), dir, "depth-" + tag);
    auto shaded = takeSnapshot(server, camera, dir, "shaded-" + tag);
    ASSERT_TRUE(depth && shaded);
    shots.push_back(*depth);
    shots.push_back(*shaded);
  }
  const auto at = projectToPixel(shots[0].pose.view().data(), shots[0].pose.projection().data(), drop, kWidth, kHeight);
  const int x = static_cast<int>(at[0]), y = static_cast<int>(at[1]);
  ASSERT_TRUE(x > 4 && y > 4 && x < kWidth - 4 && y < kHeight - 4) << "the drop is off the picture";
  // Its front along the view axis; the pool lies a good 20 cm behind it there.
  const Vec3d centre = toView(shots[0].pose, drop);
  const double front = -(centre[2] + shots[0].pose.view(14)) - kRadius;
  const auto without_counts = decodeMetres(shots[0].image, x, y);
  const auto with_counts = decodeMetres(shots[2].image, x, y);
  ASSERT_TRUE(without_counts && with_counts);
  // (The filter rounds a lone blob off, a radius or so behind its front.)
  EXPECT_LT(*without_counts, front + 2.0 * kRadius) << "without counts the drop is surface";
  EXPECT_GT(*with_counts, front + 0.1) << "with counts the drop is not surface: the pool shows behind it";
  // Drawn as a droplet: a light, opaque sphere where the surface blob was faint water.
  const Colour blob = pixel(shots[1].image, x, y), droplet = pixel(shots[3].image, x, y);
  EXPECT_GT(droplet.r + droplet.g + droplet.b, blob.r + blob.g + blob.b + 90)
      << "droplet " << droplet.r << " " << droplet.g << " " << droplet.b << ", blob " << blob.r << " " << blob.g << " "
      << blob.b;
}

TEST(FluidWindow, GazeCircleAndBoxOutlineStayOverTheWater) {
  const std::string dir = scratchDir();
  FrameSpec spec = poolSpec();
  appendPool(spec.particles, -1.5, 1.5, -1.5, 1.5, kPoolTop, 2, kSmall, 0);
  spec.with_gaze = true;  // circle of 0.1 W around the screen centre
  spec.gaze_ring = 0.15f;
  TestServer server(makeFrame(spec, 1));
  auto shot = takeSnapshot(server, poolCamera({}), dir, "gaze");
  ASSERT_TRUE(shot);
  auto yellow = [](Colour c) { return c.r > 180 && c.g > 160 && c.b < 90; };
  EXPECT_TRUE(anyNear(shot->image, kWidth / 2.0 + 32, kHeight / 2.0, 2, yellow));
  EXPECT_TRUE(anyNear(shot->image, kWidth / 2.0, kHeight / 2.0 - 32, 2, yellow));
  EXPECT_FALSE(anyNear(shot->image, kWidth / 2.0, kHeight / 2.0, 3, yellow));
  // The dashed ring (grey) at 0.15 W on the left.
  auto grey = [](Colour c) { return c.r > 180 && std::abs(c.r - c.b) < 25 && std::abs(c.r - c.g) < 25; };
  EXPECT_TRUE(anyNear(shot->image, kWidth / 2.0 - 48, kHeight / 2.0, 3, grey));
}
