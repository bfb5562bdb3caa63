// `--record FILE`: writes what the bridge sends in the gaze recording format (server/gaze), so a
// session with a real tracker can be replayed by the bridge or by sph_bench --gaze. Time is the bridge's
// monotonic clock in seconds since the first sample written (tracker clocks restart with the tracker);
// lost samples are written as invalid at the last point.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>

#include "gaze/gaze_recording.h"
#include "gaze_processor.h"

namespace gaze_bridge {

class GazeRecorder {
 public:
  // Throws std::runtime_error when the file cannot be created.
  explicit GazeRecorder(const std::string& path);
  void write(const ProcessedSample& sample, std::int64_t sent_ns);
  void flush();
  std::uint64_t written() const { return written_; }

 private:
  std::string path_;
  std::ofstream out_;
  std::int64_t first_ns_ = 0;
  bool have_previous_ = false;
  gaze::GazePoint previous_;
  std::uint64_t written_ = 0;
};

}  // namespace gaze_bridge
