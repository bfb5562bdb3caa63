// The viewer's frame decoder (client_viewer/decoded_frame.h): frames come from the network, so any
// bytes must either be refused with a reason or decode into arrays of one consistent length.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "decoded_frame.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  viewer::DecodedFrame frame;
  std::string error;
  if (!viewer::decodeFrameBytes(data, size, frame, error)) {
    FUZZ_CHECK(!error.empty());
    return 0;
  }
  const std::size_t n = frame.particleCount();
  FUZZ_CHECK(frame.classes.size() == n);
  FUZZ_CHECK(frame.speeds.empty() || frame.speeds.size() == n);
  FUZZ_CHECK(frame.level_counts.size() == frame.level_radii.size());
  FUZZ_CHECK(frame.level_radii.size() <= viewer::kMaxSizeLevels);
  std::size_t counted = 0;
  for (std::uint32_t c : frame.level_counts) counted += c;
  FUZZ_CHECK(counted == n);
  for (std::uint8_t level : frame.classes) FUZZ_CHECK(level < frame.level_radii.size());
  FUZZ_CHECK(frame.wire_bytes == size);
  for (const viewer::Vec3f& p : frame.positions) {
    FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  }
  return 0;
}
