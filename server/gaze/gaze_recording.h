// Gaze recordings: a plain CSV file of screen-space gaze samples (the README, "Scene files").
//
// Format:
//   # comment lines start with '#', blank lines are ignored
//   time_s,x,y,valid
//   0,0.5,0.5,1
//   0.0083333333333333332,0.5012,0.4987,1
// time_s: seconds, strictly increasing; x, y: normalized 0..1, origin top-left (inside [0, 1] when
// valid, any finite number otherwise); valid: 0 or 1.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace gaze {

struct GazePoint {
  double time_s = 0.0;
  double x = 0.0;
  double y = 0.0;
  bool valid = false;
};

struct GazeRecording {
  std::vector<GazePoint> samples;  // time strictly increasing

  // Time between the first and the last sample (0 when fewer than two).
  double duration() const;
  // The newest sample with time_s <= t, valid or not; false when t is before the first sample.
  bool latestAt(double t, GazePoint& out) const;
};

// A malformed recording: the message names the file and the line ("path:line: what").
class GazeFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr const char* kGazeRecordingHeader = "time_s,x,y,valid";

// Reads and validates a whole recording; throws GazeFormatError (also for an unreadable file or a
// file with no samples).
GazeRecording readGazeRecording(const std::string& path);

// Writes the recording so that readGazeRecording returns exactly the same numbers (shortest
// round-trip formatting). Throws GazeFormatError if the samples would not read back (none, bad time
// order, NaN, valid point off screen) and std::runtime_error if the file cannot be written; nothing is
// written in the first case.
void writeGazeRecording(const std::string& path, const GazeRecording& recording);

// Checks one sample against the previous one (nullptr for the first); returns an empty string when
// fine, else what is wrong. Shared by the reader, the writer and streaming recorders.
std::string checkGazePoint(const GazePoint& point, const GazePoint* previous);

// One data line (no newline), in the format the writer uses.
std::string formatGazePoint(const GazePoint& point);

}  // namespace gaze
