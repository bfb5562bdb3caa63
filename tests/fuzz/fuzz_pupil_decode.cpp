// Pupil Capture's surface gaze (gaze_bridge/pupil_decode.h): msgpack from the network. Either the
// payload is refused with a reason and nothing is appended, or every appended sample is finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_check.h"
#include "pupil_decode.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<gaze_bridge::TrackerSample> samples;
  std::size_t skipped = 0;
  const std::string error = gaze_bridge::decodePupilSurfaceMessage(data, size, 7, samples, skipped);
  if (!error.empty()) {
    FUZZ_CHECK(samples.empty());
    return 0;
  }
  for (const auto& s : samples) {
    FUZZ_CHECK(std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.tracker_time_s));
    FUZZ_CHECK(s.confidence >= 0.0f && s.confidence <= 1.0f);
    FUZZ_CHECK(s.arrival_ns == 7);
  }
  return 0;
}
