// Synthetic gaze: a seeded fixation/saccade model (it writes the recordings shipped with the scenes, and
// is the bridge's default source when no tracker is named).
//
// The gaze holds a target for a fixation (duration uniform in [fixation_min_s, fixation_max_s], each
// sample the target plus normal jitter), then makes a saccade of saccade_s to the next target (samples
// on the straight line between the two targets with a smooth velocity profile, no jitter), and so on.
// Targets are uniform in the region rectangle. With blink_probability a fixation holds a blink:
// blink_s of invalid samples starting a third of the way into it. All points are clamped into [0, 1].
//
// Reproducible across platforms: std::mt19937_64 is specified bit for bit by the standard, and the
// uniform and normal transforms are our own (std::uniform_real_distribution and
// std::normal_distribution differ between standard libraries).
#pragma once

#include <cstdint>
#include <functional>
#include <random>

#include "gaze/gaze_recording.h"

namespace gaze {

struct FixationModelParams {
  std::uint64_t seed = 1;
  double rate_hz = 120;  // samples per second
  double fixation_min_s = 0.2, fixation_max_s = 0.4;
  double saccade_s = 0.04;
  double jitter = 0.003;  // normal sigma, screen units
  // Fixation targets are drawn in this rectangle (the water on screen); normalized, origin top-left.
  double region_x0 = 0.25, region_y0 = 0.25, region_x1 = 0.75, region_y1 = 0.75;
  double blink_probability = 0.0;  // chance per fixation of a short invalid gap
  double blink_s = 0.1;            // length of that gap (at most half the fixation)
  // Optional: where fixation targets are at a given time (e.g. on moving water). Called with the
  // time of the fixation and a uniform number u in [0, 1) from the model's own stream; returns
  // false to fall back to the rectangle. The result is clamped into [0, 1].
  std::function<bool(double time_s, double u, double& x, double& y)> pick_target;
};

// Throws std::invalid_argument naming the first bad field (non-finite, rate <= 0, min > max, region
// outside [0, 1] or inverted, probability outside [0, 1], negative durations or jitter).
void validateFixationModelParams(const FixationModelParams& params);

// uniform and normal numbers from std::mt19937_64 with portable transforms.
class PortableRandom {
 public:
  explicit PortableRandom(std::uint64_t seed) : engine_(seed) {}
  // [0, 1) with 53 random bits.
  double uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  // Standard normal, Marsaglia's polar method (needs only log and sqrt, both correctly rounded in
  // IEEE libms in practice, unlike sin/cos of Box-Muller at large arguments).
  double normal();

 private:
  std::mt19937_64 engine_;
  bool have_spare_ = false;
  double spare_ = 0.0;
};

class FixationSaccadeModel {
 public:
  enum class Phase { kFixation, kSaccade };

  explicit FixationSaccadeModel(const FixationModelParams& params);

  // One sample at 1/rate_hz after the previous one; the first is at time 0. Times are index / rate,
  // so they do not drift.
  GazePoint next();

  // Of the sample last returned by next(): its phase and which fixation it belongs to (or which
  // fixation the saccade leaves), counted from 0. For tests and tools.
  Phase phase() const { return phase_; }
  std::uint64_t fixationIndex() const { return fixation_index_; }
  const FixationModelParams& params() const { return params_; }

 private:
  void drawTarget(double& x, double& y);
  void startFixation();
  void startSaccade();

  FixationModelParams params_;
  PortableRandom random_;
  std::uint64_t sample_index_ = 0;
  Phase phase_ = Phase::kFixation;
  std::uint64_t fixation_index_ = 0;
  bool started_ = false;
  // Current phase: its length in samples and how many were emitted.
  std::int64_t phase_samples_ = 0;
  std::int64_t phase_done_ = 0;
  // Blink window inside the current fixation, [blink_begin_, blink_end_) in phase samples.
  std::int64_t blink_begin_ = 0, blink_end_ = 0;
  double target_x_ = 0.5, target_y_ = 0.5;  // fixation target (saccade destination while in saccade)
  double from_x_ = 0.5, from_y_ = 0.5;      // saccade start
};

// duration_s of synthetic gaze: the samples at times 0, 1/rate, ... up to and including duration_s.
GazeRecording synthesizeRecording(const FixationModelParams& params, double duration_s);

}  // namespace gaze
