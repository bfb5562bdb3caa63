// What the window tests share: a display (Xvfb when DISPLAY is unset), a scratch folder, and a way
// to run sph_viewer against a TestServer.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "child_process.h"
#include "png_image.h"

namespace viewer_test {

// Installed once per test binary; the display outlives every test.
class DisplayEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { display_ = std::make_unique<VirtualDisplay>(); }
  void TearDown() override { display_.reset(); }

 private:
  std::unique_ptr<VirtualDisplay> display_;
};

// A fresh folder under the temp dir for one test's PNGs and logs.
std::string scratchDir();

std::unique_ptr<ChildProcess> startViewer(std::vector<std::string> args, const std::string& log_path);

struct Colour {
  int r, g, b;
};
Colour pixel(const viewer::RgbaImage& image, int x, int y);
// The colour particles mode gives level `level` of `count` (level_colours.h), shaded or not.
bool isLevel(Colour c, std::size_t level, std::size_t count);
bool isL0(Colour c);  // of a two-level frame
bool isL1(Colour c);
bool isDark(Colour c);
// Some pixel within `radius` of (x, y) satisfies `test`.
bool anyNear(const viewer::RgbaImage& image, double x, double y, int radius, bool (*test)(Colour));

}  // namespace viewer_test
