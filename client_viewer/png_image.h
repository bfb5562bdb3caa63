// RGBA images to and from PNG files (libpng): snapshots, and the tests that check their pixels.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace viewer {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // rows top first, 4 bytes per pixel
  const std::uint8_t* at(int x, int y) const {
    return pixels.data() +
           (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
  }
};

// False with a reason on failure (file not writable, libpng error); a partial file is removed.
bool writePng(const std::string& path, const RgbaImage& image, std::string& error);
// Reads any 8-bit PNG as RGBA.
bool readPng(const std::string& path, RgbaImage& image, std::string& error);

}  // namespace viewer
