// One interface for every gaze source (Pupil Capture, Gazepoint, replay, synthetic; Tobii would be
// one more implementation, see tobii_source.h). The bridge's loop owns the source and polls it.
#pragma once

#include <string>
#include <vector>

#include "tracker_sample.h"

namespace gaze_bridge {

class GazeSource {
 public:
  virtual ~GazeSource() = default;

  // source_id written into every GazeSample ("pupil", "gazepoint", "replay", "synthetic").
  virtual std::string id() const = 0;

  // Waits at most timeout_ms for tracker data and appends every sample that arrived, in order
  // (possibly none). A peer that misbehaves, disappears or restarts is never an exception: the source
  // logs, reconnects by itself with a back-off, and reports the state through connected().
  virtual void poll(std::vector<TrackerSample>& out, int timeout_ms) = 0;

  // True while the source is talking to its tracker (always true for replay and synthetic).
  virtual bool connected() const = 0;

  // True when the source will never produce another sample (a replay told not to loop).
  virtual bool finished() const { return false; }
};

}  // namespace gaze_bridge
