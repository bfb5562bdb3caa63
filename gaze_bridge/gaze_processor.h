// From raw tracker samples to what the bridge sends:
//  1. drop samples the tracker marks invalid, below the confidence threshold, not finite, or off screen;
//  2. bridge short gaps: while no sample is accepted for up to max_gap_s nothing is sent (the server
//     keeps the last gaze) and the filter keeps its state;
//  3. after a longer gap send one explicit "gaze lost" sample (valid = false, lost = true), repeated
//     every lost_repeat_s while the gap lasts (so a server that connects late still learns it), and
//     restart the filter so the next fixation is not smeared with the old one;
//  4. One Euro filter on x and y with the tracker's time steps;
//  5. optional I-VT (velocity threshold) fixation flag on the filtered points.
#pragma once

#include <cstdint>

#include "one_euro_filter.h"
#include "tracker_sample.h"

namespace gaze_bridge {

struct ProcessorParams {
  double min_confidence = 0.6;
  double max_gap_s = 0.2;      // longer gaps (bridge clock) are reported as lost
  double lost_repeat_s = 1.0;  // re-send "lost" this often while it lasts
  bool filter = true;
  OneEuroParams one_euro;
  bool ivt = false;
  // I-VT threshold in screen widths per second; vertical motion is scaled by 1 / screen_aspect so the
  // speed is isotropic. 0.6 widths/s is about 30 deg/s on docs/design.md's reference set-up (531 mm wide
  // screen at 600 mm: 1 deg = 10.5 mm = 0.0197 widths).
  double ivt_threshold = 0.6;
  double screen_aspect = 531.0 / 299.0;  // width / height
};

// Throws std::invalid_argument naming the bad field.
void validateProcessorParams(const ProcessorParams& params);

// What the bridge sends: GazeSample fields before the publisher adds source id, sequence and clock.
struct ProcessedSample {
  double tracker_time_s = 0.0;
  double x = 0.0;
  double y = 0.0;
  bool valid = false;
  float confidence = 0.0f;
  bool lost = false;
  bool fixation = false;
  std::int64_t arrival_ns = 0;  // of the tracker sample (0 for a lost sample)
};

struct ProcessorCounters {
  std::uint64_t received = 0;
  std::uint64_t accepted = 0;
  std::uint64_t dropped_invalid = 0;     // tracker said invalid
  std::uint64_t dropped_confidence = 0;  // below min_confidence
  std::uint64_t dropped_bad = 0;         // not finite or off screen although "valid"
  std::uint64_t lost_sent = 0;
};

class GazeProcessor {
 public:
  // now_ns: bridge clock at start; a tracker that never delivers is reported lost after max_gap_s.
  GazeProcessor(const ProcessorParams& params, std::int64_t now_ns);

  // True (and `out` filled) when the sample is to be sent.
  bool accept(const TrackerSample& sample, ProcessedSample& out);
  // Call regularly; true (and `out` filled) when a "lost" sample is due at bridge time now_ns.
  bool checkLost(std::int64_t now_ns, ProcessedSample& out);
  // Bridge time at which checkLost will next have something to say (for the loop's poll timeout).
  std::int64_t nextDeadlineNs() const;

  bool lost() const { return lost_; }
  const ProcessorCounters& counters() const { return counters_; }

 private:
  ProcessorParams params_;
  OneEuroFilter filter_x_, filter_y_;
  ProcessorCounters counters_;
  std::int64_t last_accepted_ns_;
  std::int64_t last_lost_sent_ns_ = 0;
  bool lost_ = false;
  bool have_previous_ = false;  // previous accepted sample since the last reset
  double previous_tracker_time_s_ = 0.0;
  double previous_x_ = 0.5, previous_y_ = 0.5;  // last sent (filtered) point
};

}  // namespace gaze_bridge
