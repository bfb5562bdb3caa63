// The gaze-recording reader (server/gaze/gaze_recording.h) reads files only, so each input goes
// through a temporary file. A recording that reads must also write and read back the same numbers
// (the writer's promise), which checks the reader's parsing against the writer's formatting.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_check.h"
#include "gaze/gaze_recording.h"

namespace {

// One pair of files per process (libFuzzer's -jobs/-workers run several processes at once), removed
// when the process ends.
struct ScratchFiles {
  std::string input = path(".csv");
  std::string copy = path("_copy.csv");
  static std::string path(const char* suffix) {
    return (std::filesystem::temp_directory_path() / ("sph_fuzz_gaze_" + std::to_string(getpid()) + suffix)).string();
  }
  ~ScratchFiles() {
    std::remove(input.c_str());
    std::remove(copy.c_str());
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ScratchFiles files;
  const std::string& input_path = files.input;
  const std::string& copy_path = files.copy;
  {
    std::ofstream out(input_path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  gaze::GazeRecording recording;
  try {
    recording = gaze::readGazeRecording(input_path);
  } catch (const gaze::GazeFormatError&) {
    return 0;  // the documented refusal
  }
  FUZZ_CHECK(!recording.samples.empty());
  gaze::writeGazeRecording(copy_path, recording);
  const gaze::GazeRecording again = gaze::readGazeRecording(copy_path);
  FUZZ_CHECK(again.samples.size() == recording.samples.size());
  for (std::size_t i = 0; i < again.samples.size(); ++i) {
    const gaze::GazePoint& a = recording.samples[i];
    const gaze::GazePoint& b = again.samples[i];
    FUZZ_CHECK(a.time_s == b.time_s && a.x == b.x && a.y == b.y && a.valid == b.valid);
  }
  return 0;
}
