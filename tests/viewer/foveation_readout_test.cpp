// What the panel and log say about the method (foveation_readout.h), the level colours
// (level_colours.h), and which overlay each method gets (outline_geometry.h).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "foveation_readout.h"
#include "level_colours.h"
#include "outline_geometry.h"

namespace {

viewer::DecodedFrame foveatedFrame() {
  viewer::DecodedFrame f;
  f.scene = "dambreak";
  f.method = gsph::v1::METHOD_FOVEATED;
  f.gaze.mode = gsph::v1::GAZE_MODE_TRACKING;
  f.gaze.x = 0.5f;
  f.gaze.y = 0.5f;
  f.gaze.radius = 0.05f;
  f.level_radii = {0.01f, 0.0126f, 0.0159f, 0.02f};
  f.level_counts = {100, 200, 300, 400};
  f.foveation.quality = 1.0f;
  f.foveation.periphery_gain = 16.0f;
  f.foveation.periphery_gain_ceiling = 16.0f;
  f.foveation.realtime_ratio = 0.62f;
  f.foveation.visible = 800;
  f.foveation.over_budget = 20;
  f.foveation.fovea_width_arcmin = 2.5f;
  f.foveation.fovea_mar_arcmin = 1.25f;
  f.foveation.ring_radii = {0.0f, 0.1f, 0.2f};
  return f;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string all;
  for (const auto& l : lines) all += l + "\n";
  return all;
}

TEST(FoveationReadout, PanelLinesGiveEveryFigure) {
  viewer::DecodedFrame f = foveatedFrame();
  const std::string text = joined(viewer::foveationLines(f));
  EXPECT_NE(text.find("0.62 of real time"), std::string::npos) << text;
  EXPECT_NE(text.find("q 1.00, g 16.0 (AT CEILING)"), std::string::npos) << text;
  EXPECT_NE(text.find("2.5 % of 800 visible over budget"), std::string::npos) << text;
  EXPECT_NE(text.find("particle 2.50' wide, eye resolves 1.25'"), std::string::npos) << text;
  EXPECT_NE(text.find("gaze       tracking"), std::string::npos) << text;
  f.foveation.periphery_gain = 4.0f;
  f.foveation.fovea_width_arcmin = 0.0f;
  f.foveation.realtime_ratio = 0.0f;
  const std::string below = joined(viewer::foveationLines(f));
  EXPECT_EQ(below.find("CEILING"), std::string::npos) << below;
  EXPECT_NE(below.find("gaze on no water"), std::string::npos) << below;
  EXPECT_NE(below.find("not measured"), std::string::npos) << below;
  EXPECT_EQ(viewer::levelCountsText(f), "L0 100, L1 200, L2 300, L3 400");
  const std::string log = viewer::foveationLogLine(f);
  EXPECT_NE(log.find("dambreak: not measured; q 1.00, g 4.0;"), std::string::npos) << log;
  EXPECT_NE(log.find("L3 400"), std::string::npos) << log;
}

TEST(FoveationReadout, GazeStateInTheMethodsWords) {
  using gsph::v1::GAZE_MODE_FALLBACK;
  EXPECT_STREQ(viewer::gazeStateText(gsph::v1::METHOD_FOVEATED, GAZE_MODE_FALLBACK),
               "lost: fovea at the screen's centre");
  EXPECT_STREQ(viewer::gazeStateText(gsph::v1::METHOD_GAZE, GAZE_MODE_FALLBACK), "lost: surface refinement instead");
  EXPECT_STREQ(viewer::gazeStateText(gsph::v1::METHOD_REGULAR, gsph::v1::GAZE_MODE_NONE), "not used by the method");
  EXPECT_STREQ(viewer::gazeStateText(gsph::v1::METHOD_HYBRID, gsph::v1::GAZE_MODE_HOLDING), "holding the last sample");
  // The thesis's methods' panel shows no foveation figures.
  viewer::DecodedFrame f = foveatedFrame();
  f.method = gsph::v1::METHOD_GAZE;
  EXPECT_EQ(joined(viewer::foveationLines(f)).find("foveation"), std::string::npos);
}

double lightness(viewer::LevelRgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

TEST(LevelColours, AnyNumberOfLevelsFromOneOrderedMap) {
  for (std::size_t count = 2; count <= 8; ++count) {
    std::set<std::tuple<float, float, float>> distinct;
    for (std::size_t k = 0; k < count; ++k) {
      const viewer::LevelRgb c = viewer::levelColour(k, count);
      distinct.insert({c.r, c.g, c.b});
      if (k > 0) {
        EXPECT_GT(lightness(c), lightness(viewer::levelColour(k - 1, count))) << k << " of " << count;
      }
    }
    EXPECT_EQ(distinct.size(), count);
    // The ends are the map's ends whatever the count: viridis at 0.25 and at 1.
    EXPECT_NEAR(viewer::levelColour(0, count).b, 0.545706f, 1e-6f);
    EXPECT_NEAR(viewer::levelColour(count - 1, count).r, 0.993248f, 1e-6f);
  }
}

TEST(LevelColours, TheThesisMethodsTwoLevelsTakeTheMapsEnds) {
  viewer::DecodedFrame f = foveatedFrame();
  EXPECT_EQ(f.colourLevelCount(), 4u);  // foveated: every declared level
  f.method = gsph::v1::METHOD_GAZE;
  f.level_counts = {100, 200, 0, 0};
  EXPECT_EQ(f.colourLevelCount(), 2u);
  f.level_counts = {100, 200, 5, 0};  // a level the frame has particles in keeps its own colour
  EXPECT_EQ(f.colourLevelCount(), 3u);
}

// Distances from (x, y) of the overlay's vertices, in viewport widths, grouped to 1e-3.
std::set<int> ringRadii(const viewer::LineList& lines, float x, float y, float aspect) {
  std::set<int> radii;
  for (const auto& v : lines) {
    const float dx = (v.x - (2 * x - 1)) / 2.0f;
    const float dy = (v.y - (1 - 2 * y)) / 2.0f / aspect;
    radii.insert(static_cast<int>(std::lround(1000.0f * std::sqrt(dx * dx + dy * dy))));
  }
  return radii;
}

TEST(MethodOverlay, FoveatedDrawsTheServersRingsAndTheThesisMethodsTheirCircle) {
  const float aspect = 16.0f / 9.0f;
  viewer::DecodedFrame f = foveatedFrame();
  viewer::LineList rings;
  viewer::appendMethodOverlay(rings, f, aspect);
  EXPECT_EQ(ringRadii(rings, 0.5f, 0.5f, aspect), (std::set<int>{100, 200})) << "the radius-0 ring is left out";
  // Each ring in its level's colour.
  const viewer::LevelRgb l2 = viewer::levelColour(2, 4);
  bool found = false;
  for (const auto& v : rings) found = found || (v.r == l2.r && v.g == l2.g && v.b == l2.b);
  EXPECT_TRUE(found);
  f.method = gsph::v1::METHOD_GAZE;
  viewer::LineList circle;
  viewer::appendMethodOverlay(circle, f, aspect);
  EXPECT_EQ(ringRadii(circle, 0.5f, 0.5f, aspect), (std::set<int>{50}));
  f.method = gsph::v1::METHOD_REGULAR;
  viewer::LineList none;
  viewer::appendMethodOverlay(none, f, aspect);
  EXPECT_TRUE(none.empty());
}

}  // namespace
