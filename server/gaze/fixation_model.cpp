#include "gaze/fixation_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gaze {

namespace {

void require(bool condition, const std::string& what) {
  if (!condition) throw std::invalid_argument("fixation model: " + what);
}

std::int64_t samplesFor(double seconds, double rate_hz) {
  return static_cast<std::int64_t>(std::llround(seconds * rate_hz));
}

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

}  // namespace

void validateFixationModelParams(const FixationModelParams& p) {
  require(std::isfinite(p.rate_hz) && p.rate_hz > 0.0, "rate_hz must be a positive number");
  require(std::isfinite(p.fixation_min_s) && p.fixation_min_s > 0.0, "fixation_min_s must be > 0");
  require(std::isfinite(p.fixation_max_s) && p.fixation_max_s >= p.fixation_min_s,
          "fixation_max_s must be >= fixation_min_s");
  require(std::isfinite(p.saccade_s) && p.saccade_s >= 0.0, "saccade_s must be >= 0");
  require(std::isfinite(p.jitter) && p.jitter >= 0.0, "jitter must be >= 0");
  for (double v : {p.region_x0, p.region_y0, p.region_x1, p.region_y1}) {
    require(std::isfinite(v) && v >= 0.0 && v <= 1.0, "region bounds must lie in [0, 1]");
  }
  require(p.region_x0 <= p.region_x1 && p.region_y0 <= p.region_y1, "region must have x0 <= x1, y0 <= y1");
  require(std::isfinite(p.blink_probability) && p.blink_probability >= 0.0 && p.blink_probability <= 1.0,
          "blink_probability must lie in [0, 1]");
  require(std::isfinite(p.blink_s) && p.blink_s >= 0.0, "blink_s must be >= 0");
  // A fixation must span at least one sample, or the model would emit nothing but saccades.
  require(samplesFor(p.fixation_min_s, p.rate_hz) >= 1, "fixation_min_s is shorter than one sample");
}

double PortableRandom::normal() {
  if (have_spare_) {
    have_spare_ = false;
    return spare_;
  }
  double u = 0.0, v = 0.0, s = 0.0;
  do {
    u = 2.0 * uniform01() - 1.0;
    v = 2.0 * uniform01() - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double factor = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * factor;
  have_spare_ = true;
  return u * factor;
}

FixationSaccadeModel::FixationSaccadeModel(const FixationModelParams& params) : params_(params), random_(params.seed) {
  validateFixationModelParams(params_);
}

void FixationSaccadeModel::drawTarget(double& x, double& y) {
  if (params_.pick_target) {
    const double u = random_.uniform01();
    const double time_s = static_cast<double>(sample_index_) / params_.rate_hz;
    if (params_.pick_target(time_s, u, x, y)) {
      x = std::clamp(x, 0.0, 1.0);
      y = std::clamp(y, 0.0, 1.0);
      return;
    }
  }
  x = random_.uniform(params_.region_x0, params_.region_x1);
  y = random_.uniform(params_.region_y0, params_.region_y1);
}

void FixationSaccadeModel::startFixation() {
  phase_ = Phase::kFixation;
  phase_done_ = 0;
  // Duration drawn in seconds, then rounded to whole samples; rounding keeps it inside the bounds
  // whenever the bounds are whole samples (the defaults at 120 Hz are 24..48 samples).
  phase_samples_ = std::max<std::int64_t>(
      1, samplesFor(random_.uniform(params_.fixation_min_s, params_.fixation_max_s), params_.rate_hz));
  blink_begin_ = blink_end_ = 0;
  if (params_.blink_probability > 0.0 && random_.uniform01() < params_.blink_probability) {
    const std::int64_t length = std::min(samplesFor(params_.blink_s, params_.rate_hz), phase_samples_ / 2);
    blink_begin_ = phase_samples_ / 3;
    blink_end_ = blink_begin_ + std::max<std::int64_t>(length, 0);
  }
}

void FixationSaccadeModel::startSaccade() {
  phase_ = Phase::kSaccade;
  phase_done_ = 0;
  phase_samples_ = samplesFor(params_.saccade_s, params_.rate_hz);
  from_x_ = target_x_;
  from_y_ = target_y_;
  drawTarget(target_x_, target_y_);
}

GazePoint FixationSaccadeModel::next() {
  if (!started_) {
    started_ = true;
    drawTarget(target_x_, target_y_);
    startFixation();
  } else if (phase_done_ >= phase_samples_) {
    if (phase_ == Phase::kFixation) {
      startSaccade();
      if (phase_samples_ == 0) {  // saccade_s shorter than a sample: jump straight to the target
        ++fixation_index_;
        startFixation();
      }
    } else {
      ++fixation_index_;
      startFixation();
    }
  }

  GazePoint point;
  point.time_s = static_cast<double>(sample_index_) / params_.rate_hz;
  if (phase_ == Phase::kFixation) {
    const bool blinking = phase_done_ >= blink_begin_ && phase_done_ < blink_end_;
    // Draw the jitter even while blinking so the random stream does not depend on blink timing.
    const double jx = params_.jitter * random_.normal();
    const double jy = params_.jitter * random_.normal();
    point.x = clamp01(target_x_ + jx);
    point.y = clamp01(target_y_ + jy);
    point.valid = !blinking;
  } else {
    // Sample k of n lies at fraction (k + 1) / (n + 1) of the way, eased with smoothstep (slow at both
    // ends, fastest mid-flight, like the main sequence of real saccades).
    const double s = static_cast<double>(phase_done_ + 1) / static_cast<double>(phase_samples_ + 1);
    const double eased = s * s * (3.0 - 2.0 * s);
    point.x = clamp01(from_x_ + (target_x_ - from_x_) * eased);
    point.y = clamp01(from_y_ + (target_y_ - from_y_) * eased);
    point.valid = true;
  }
  ++phase_done_;
  ++sample_index_;
  return point;
}

GazeRecording synthesizeRecording(const FixationModelParams& params, double duration_s) {
  if (!std::isfinite(duration_s) || duration_s < 0.0) {
    throw std::invalid_argument("synthesizeRecording: duration_s must be a number >= 0");
  }
  FixationSaccadeModel model(params);
  // Count from the index, not by accumulating times; a tiny tolerance keeps the sample that lands on
  // duration_s itself despite rounding of duration_s * rate.
  const auto count = static_cast<std::size_t>(std::floor(duration_s * params.rate_hz + 1e-9)) + 1;
  GazeRecording recording;
  recording.samples.reserve(count);
  for (std::size_t i = 0; i < count; ++i) recording.samples.push_back(model.next());
  return recording;
}

}  // namespace gaze
