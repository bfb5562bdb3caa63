#include "viewer_process.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "level_colours.h"

namespace viewer_test {

std::string scratchDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "sph_viewer_test_XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

std::unique_ptr<ChildProcess> startViewer(std::vector<std::string> args, const std::string& log_path) {
  args.insert(args.begin(), SPH_VIEWER_PATH);
  // Under ASan: Mesa's GL driver leaks a few hundred bytes from modules it unloads at exit (a bare
  // GLFW program that only makes a context shows the same), which LeakSanitizer can neither
  // symbolize nor suppress; so leak checking is off for the viewer process only. Our own code's
  // leaks are checked by viewer_unit_tests (decoding, sockets, camera) and by address errors here.
  // Extra variables come first and getenv takes the first match, so keep any options already set.
  const char* existing = std::getenv("ASAN_OPTIONS");
  std::string asan = "ASAN_OPTIONS=";
  if (existing != nullptr && existing[0] != '\0') asan.append(existing).append(":");
  asan.append("detect_leaks=0");
  return std::make_unique<ChildProcess>(args, log_path, std::vector<std::string>{asan});
}

Colour pixel(const viewer::RgbaImage& image, int x, int y) {
  const auto* p = image.at(x, y);
  return {p[0], p[1], p[2]};
}

bool isLevel(Colour c, std::size_t level, std::size_t count) {
  const double sum = c.r + c.g + c.b;
  if (sum < 90) return false;  // the background, or a sphere's unlit rim
  // By chromaticity: shading scales a colour, which keeps it; the highlight greys it a little.
  std::size_t nearest = count;
  double nearest_d = 1e9;
  for (std::size_t k = 0; k < count; ++k) {
    const viewer::LevelRgb l = viewer::levelColour(k, count);
    const double lsum = l.r + l.g + l.b;
    const double d = std::hypot(c.r / sum - l.r / lsum, c.g / sum - l.g / lsum, c.b / sum - l.b / lsum);
    if (d < nearest_d) {
      nearest_d = d;
      nearest = k;
    }
  }
  return nearest == level && nearest_d < 0.1;
}
bool isL0(Colour c) { return isLevel(c, 0, 2); }
bool isL1(Colour c) { return isLevel(c, 1, 2); }
bool isDark(Colour c) { return c.r < 40 && c.g < 40 && c.b < 40; }

bool anyNear(const viewer::RgbaImage& image, double x, double y, int radius, bool (*test)(Colour)) {
  const int cx = static_cast<int>(x), cy = static_cast<int>(y);
  for (int py = cy - radius; py <= cy + radius; ++py) {
    for (int px = cx - radius; px <= cx + radius; ++px) {
      if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
      if (test(pixel(image, px, py))) return true;
    }
  }
  return false;
}

}  // namespace viewer_test
