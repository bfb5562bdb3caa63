#include "viewer_process.h"

#include <cstdlib>
#include <filesystem>

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

bool isBlue(Colour c) { return c.b > 140 && c.b > c.r + 60 && c.b > c.g + 30; }
bool isRed(Colour c) { return c.r > 140 && c.r > c.b + 60 && c.r > c.g + 60; }
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
