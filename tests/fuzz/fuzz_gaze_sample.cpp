// The server's gaze socket check (server/net/input_validation.h): whatever the bytes, either a
// reason comes back or the sample meets every promise the simulation relies on.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_check.h"
#include "net/input_validation.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gsph::v1::GazeSample sample;
  if (!net::parseGazeSample(data, size, sample).empty()) return 0;
  FUZZ_CHECK(sample.protocol_version() == gsph::v1::PROTOCOL_VERSION_CURRENT);
  FUZZ_CHECK(sample.source_id().size() <= net::kMaxIdLength);
  FUZZ_CHECK(std::isfinite(sample.confidence()) && sample.confidence() >= 0.0f && sample.confidence() <= 1.0f);
  if (sample.valid() && !sample.lost()) {
    FUZZ_CHECK(std::isfinite(sample.x()) && sample.x() >= 0.0f && sample.x() <= 1.0f);
    FUZZ_CHECK(std::isfinite(sample.y()) && sample.y() >= 0.0f && sample.y() <= 1.0f);
  }
  return 0;
}
