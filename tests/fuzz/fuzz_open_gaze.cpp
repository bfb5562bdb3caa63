// The Gazepoint Open Gaze parser (gaze_bridge/open_gaze_parser.h) as the bridge drives it: TCP bytes
// in arbitrary pieces through the line splitter, each line through the tag and record parsers. The
// first input byte chooses the piece size, so the fuzzer also explores how reads split lines.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.h"
#include "open_gaze_parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t piece = 1 + data[0] % 64;
  const char* text = reinterpret_cast<const char*>(data + 1);
  const std::size_t length = size - 1;

  gaze_bridge::OpenGazeLineSplitter splitter;
  std::string line;
  gaze_bridge::OpenGazeTag tag;
  gaze_bridge::OpenGazeRecord record;
  for (std::size_t at = 0; at < length; at += piece) {
    splitter.feed(text + at, std::min(piece, length - at));
    while (splitter.nextLine(line)) {
      FUZZ_CHECK(line.find('\n') == std::string::npos);
      FUZZ_CHECK(line.size() <= length);
      if (!gaze_bridge::parseOpenGazeTag(line, tag)) continue;
      FUZZ_CHECK(!tag.name.empty());
      if (gaze_bridge::parseOpenGazeRecord(tag, record)) {
        FUZZ_CHECK(std::isfinite(record.x) && std::isfinite(record.y));
      }
    }
  }
  return 0;
}
