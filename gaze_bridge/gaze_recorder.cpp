#include "gaze_recorder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gaze_bridge {

GazeRecorder::GazeRecorder(const std::string& path) : path_(path), out_(path, std::ios::binary | std::ios::trunc) {
  if (!out_) throw std::runtime_error("--record: cannot create '" + path + "'");
  out_ << "# gaze_bridge recording: time_s is the bridge clock since the first sample\n"
       << gaze::kGazeRecordingHeader << '\n';
}

void GazeRecorder::write(const ProcessedSample& sample, std::int64_t sent_ns) {
  if (!have_previous_) first_ns_ = sent_ns;
  gaze::GazePoint point;
  point.time_s = static_cast<double>(sent_ns - first_ns_) * 1e-9;
  // The format wants strictly increasing times; two sends within one clock tick get the next double.
  if (have_previous_ && !(point.time_s > previous_.time_s)) point.time_s = std::nextafter(previous_.time_s, 1e300);
  point.valid = sample.valid;
  point.x = sample.x;
  point.y = sample.y;
  if (point.valid) {
    point.x = std::clamp(point.x, 0.0, 1.0);
    point.y = std::clamp(point.y, 0.0, 1.0);
  }
  if (!gaze::checkGazePoint(point, have_previous_ ? &previous_ : nullptr).empty()) return;  // never write junk
  out_ << gaze::formatGazePoint(point) << '\n';
  previous_ = point;
  have_previous_ = true;
  ++written_;
}

void GazeRecorder::flush() { out_.flush(); }

}  // namespace gaze_bridge
