#include "gaze_processor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gaze_bridge {

namespace {

std::int64_t secondsToNs(double s) { return static_cast<std::int64_t>(std::llround(s * 1e9)); }

}  // namespace

void validateProcessorParams(const ProcessorParams& p) {
  if (!(std::isfinite(p.min_confidence) && p.min_confidence >= 0.0 && p.min_confidence <= 1.0)) {
    throw std::invalid_argument("min-confidence must lie in [0, 1]");
  }
  if (!(std::isfinite(p.max_gap_s) && p.max_gap_s > 0.0 && p.max_gap_s <= 3600.0)) {
    throw std::invalid_argument("max-gap must be > 0 s (and at most an hour)");
  }
  if (!(std::isfinite(p.lost_repeat_s) && p.lost_repeat_s > 0.0 && p.lost_repeat_s <= 3600.0)) {
    throw std::invalid_argument("lost-repeat must be > 0 s (and at most an hour)");
  }
  validateOneEuroParams(p.one_euro);
  if (!(std::isfinite(p.ivt_threshold) && p.ivt_threshold > 0.0)) {
    throw std::invalid_argument("ivt-threshold must be > 0");
  }
  if (!(std::isfinite(p.screen_aspect) && p.screen_aspect > 0.0)) {
    throw std::invalid_argument("screen-aspect must be > 0");
  }
}

GazeProcessor::GazeProcessor(const ProcessorParams& params, std::int64_t now_ns)
    : params_(params), filter_x_(params.one_euro), filter_y_(params.one_euro), last_accepted_ns_(now_ns) {
  validateProcessorParams(params_);
}

bool GazeProcessor::accept(const TrackerSample& sample, ProcessedSample& out) {
  ++counters_.received;
  if (!sample.valid) {
    ++counters_.dropped_invalid;
    return false;
  }
  if (!(std::isfinite(sample.confidence) && sample.confidence >= params_.min_confidence)) {
    ++counters_.dropped_confidence;
    return false;
  }
  if (!(std::isfinite(sample.x) && std::isfinite(sample.y) && sample.x >= 0.0 && sample.x <= 1.0 && sample.y >= 0.0 &&
        sample.y <= 1.0 && std::isfinite(sample.tracker_time_s))) {
    ++counters_.dropped_bad;
    return false;
  }
  ++counters_.accepted;

  const double dt = sample.tracker_time_s - previous_tracker_time_s_;
  const bool arrival_gap = sample.arrival_ns - last_accepted_ns_ > secondsToNs(params_.max_gap_s);
  // Start the filter afresh after a lost period or any gap too long to bridge, and when the tracker's
  // clock went backwards (it restarted): smoothing across those would drag the new gaze towards the old.
  if (lost_ || arrival_gap || !have_previous_ || !(dt > 0.0) || dt > params_.max_gap_s) {
    filter_x_.reset();
    filter_y_.reset();
    have_previous_ = false;
  }

  double x = sample.x, y = sample.y;
  if (params_.filter) {
    x = std::clamp(filter_x_.filter(sample.x, dt), 0.0, 1.0);
    y = std::clamp(filter_y_.filter(sample.y, dt), 0.0, 1.0);
  }
  bool fixation = false;
  if (params_.ivt && have_previous_) {
    const double speed = std::hypot(x - previous_x_, (y - previous_y_) / params_.screen_aspect) / dt;
    fixation = speed < params_.ivt_threshold;
  }

  out = ProcessedSample{};
  out.tracker_time_s = sample.tracker_time_s;
  out.x = x;
  out.y = y;
  out.valid = true;
  out.confidence = sample.confidence;
  out.fixation = fixation;
  out.arrival_ns = sample.arrival_ns;

  have_previous_ = true;
  previous_tracker_time_s_ = sample.tracker_time_s;
  previous_x_ = x;
  previous_y_ = y;
  last_accepted_ns_ = std::max(last_accepted_ns_, sample.arrival_ns);
  lost_ = false;
  return true;
}

bool GazeProcessor::checkLost(std::int64_t now_ns, ProcessedSample& out) {
  if (now_ns < nextDeadlineNs()) return false;
  if (!lost_) {
    lost_ = true;
    filter_x_.reset();
    filter_y_.reset();
    have_previous_ = false;
  }
  last_lost_sent_ns_ = now_ns;
  ++counters_.lost_sent;
  out = ProcessedSample{};
  out.tracker_time_s = previous_tracker_time_s_;
  out.x = previous_x_;  // receivers ignore x, y of an invalid sample; recordings keep the last point
  out.y = previous_y_;
  out.valid = false;
  out.lost = true;
  return true;
}

std::int64_t GazeProcessor::nextDeadlineNs() const {
  // The first "lost" comes when the gap exceeds max_gap_s (strictly), the repeats every lost_repeat_s.
  return lost_ ? last_lost_sent_ns_ + secondsToNs(params_.lost_repeat_s)
               : last_accepted_ns_ + secondsToNs(params_.max_gap_s) + 1;
}

}  // namespace gaze_bridge
