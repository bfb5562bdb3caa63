// What every gaze source hands the bridge: one tracker sample in screen space, plus the bridge's clock
// at the moment the sample was read (the start of the bridge's added latency).
#pragma once

#include <chrono>
#include <cstdint>

namespace gaze_bridge {

struct TrackerSample {
  double tracker_time_s = 0.0;  // the tracker's own clock
  double x = 0.0;               // normalized 0..1, origin top-left (sources convert)
  double y = 0.0;
  bool valid = false;           // the tracker's own validity (off surface, BPOGV 0, blink)
  float confidence = 0.0f;      // 0..1; trackers without one report 1 when valid
  std::int64_t arrival_ns = 0;  // steadyNowNs() when the bridge read it
};

// Monotonic clock for intervals and latency (never jumps).
inline std::int64_t steadyNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// System clock in microseconds since the Unix epoch: GazeSample.bridge_time_us (docs/design.md section 6).
inline std::int64_t systemNowUs() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace gaze_bridge
