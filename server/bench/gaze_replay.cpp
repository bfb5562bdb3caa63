#include "bench/gaze_replay.h"

#include <algorithm>
#include <cmath>

namespace bench {

sph::GazeInput gazeInputAt(const gaze::GazeRecording& recording, double sim_time) {
  sph::GazeInput in;
  if (recording.samples.empty()) return in;
  const double start = recording.samples.front().time_s;
  // One sample period past the last sample, the loop starts again.
  const double period = recording.samples.size() > 1
                            ? recording.duration() * static_cast<double>(recording.samples.size()) /
                                  static_cast<double>(recording.samples.size() - 1)
                            : 1.0;
  const double t = start + std::fmod(std::max(0.0, sim_time), period);
  // Walk back from the newest sample at or before t to the newest valid one (blinks are short).
  auto it = std::upper_bound(recording.samples.begin(), recording.samples.end(), t,
                             [](double v, const gaze::GazePoint& p) { return v < p.time_s; });
  while (it != recording.samples.begin()) {
    --it;
    if (it->valid) {
      in.present = true;
      in.x = it->x;
      in.y = it->y;
      in.age_s = t - it->time_s;
      return in;
    }
  }
  return in;
}

}  // namespace bench
