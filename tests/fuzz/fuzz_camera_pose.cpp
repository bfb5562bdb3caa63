// The server's camera pose check (server/net/input_validation.h), then the conversion the
// simulation thread runs on a pose that passed.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_check.h"
#include "net/input_validation.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gsph::v1::CameraPose pose;
  if (!net::parseCameraPose(data, size, pose).empty()) return 0;
  FUZZ_CHECK(pose.view_size() == 16 && pose.projection_size() == 16);
  FUZZ_CHECK(pose.viewer_id().size() <= net::kMaxIdLength);
  const sph::ScreenCamera camera = net::toScreenCamera(pose);
  FUZZ_CHECK(camera.viewport_width >= 1 && camera.viewport_width <= net::kMaxViewportPixels);
  FUZZ_CHECK(camera.viewport_height >= 1 && camera.viewport_height <= net::kMaxViewportPixels);
  FUZZ_CHECK(camera.view.allFinite() && camera.projection.allFinite());
  return 0;
}
