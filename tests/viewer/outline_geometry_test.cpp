#include "outline_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

TEST(OutlineGeometry, BoxHasTwelveEdgesOnItsCorners) {
  viewer::LineList lines;
  viewer::appendBox(lines, {0, 0, 0}, {2, 1, 3}, {1, 1, 1});
  ASSERT_EQ(lines.size(), 24u);
  for (const auto& v : lines) {
    EXPECT_TRUE(v.x == 0.0f || v.x == 2.0f);
    EXPECT_TRUE(v.y == 0.0f || v.y == 1.0f);
    EXPECT_TRUE(v.z == 0.0f || v.z == 3.0f);
  }
}

TEST(OutlineGeometry, ScreenCircleRadiusIsAFractionOfWidth) {
  viewer::LineList lines;
  const float aspect = 16.0f / 9.0f;
  viewer::appendScreenCircle(lines, 0.25f, 0.75f, 0.05f, aspect, {1, 1, 0});
  ASSERT_FALSE(lines.empty());
  // centre in NDC: x = 2*0.25-1 = -0.5, y = 1-2*0.75 = -0.5; in pixels the circle is round:
  // radius 0.05 W in x, and 0.05 W = 0.05 * aspect * H in y
  for (const auto& v : lines) {
    const float px = (v.x + 0.5f) / 2.0f;                    // in widths
    const float py = (v.y + 0.5f) / 2.0f * (1.0f / aspect);  // in widths
    EXPECT_NEAR(std::sqrt(px * px + py * py), 0.05f, 1e-4f);
  }
}

TEST(OutlineGeometry, GazeRingOnlyWhenWiderAndModeDrawable) {
  viewer::GazeOverlay gaze;
  gaze.mode = gsph::v1::GAZE_MODE_TRACKING;
  gaze.x = gaze.y = 0.5f;
  gaze.radius = 0.05f;
  viewer::LineList circle_only, with_ring, none;
  viewer::appendGazeOverlay(circle_only, gaze, 1.0f);
  gaze.ring_radius = 0.08f;
  viewer::appendGazeOverlay(with_ring, gaze, 1.0f);
  EXPECT_GT(with_ring.size(), circle_only.size());
  gaze.mode = gsph::v1::GAZE_MODE_FALLBACK;
  viewer::appendGazeOverlay(none, gaze, 1.0f);
  EXPECT_TRUE(none.empty());
}

TEST(OutlineGeometry, CylinderSpansFloorToRoof) {
  viewer::SceneGeometry g;
  g.has_box = true;
  g.box_min = {0, 0.0f, 0};
  g.box_max = {1, 0.7f, 1};
  g.cylinders.push_back({0.5f, 0.5f, 0.1f});
  viewer::LineList lines;
  viewer::appendGeometry(lines, g);
  float lo = 1e9f, hi = -1e9f;
  for (std::size_t i = 24; i < lines.size(); ++i) {
    lo = std::min(lo, lines[i].y);
    hi = std::max(hi, lines[i].y);
  }
  EXPECT_FLOAT_EQ(lo, 0.0f);
  EXPECT_FLOAT_EQ(hi, 0.7f);
}
