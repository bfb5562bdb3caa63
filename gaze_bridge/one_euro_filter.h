// The One Euro filter (Casiez, Roussel, Vogel, "1 Euro Filter: A Simple Speed-based Low-pass Filter for
// Noisy Input in Interactive Systems", CHI 2012): an exponential low-pass whose cutoff rises with the
// signal's speed, so a fixation is smoothed hard and a saccade is followed with little lag.
//   tau = 1 / (2 pi f_c),  alpha = 1 / (1 + tau / T_e)            (T_e: time since the last sample)
//   dx_i = (x_i - xhat_{i-1}) / T_e,   dxhat_i = alpha(d_cutoff) dx_i + (1 - alpha(d_cutoff)) dxhat_{i-1}
//   f_c = min_cutoff + beta |dxhat_i|,  xhat_i = alpha(f_c) x_i + (1 - alpha(f_c)) xhat_{i-1}
// The first sample passes through unchanged with dxhat = 0.
#pragma once

namespace gaze_bridge {

struct OneEuroParams {
  // Defaults for normalized screen units (speeds of 0.01-0.1 screen/s in a fixation, 2-20 in a
  // saccade): 1 Hz smooths fixation jitter; beta 1 raises the cutoff to 10+ Hz within a saccade.
  double min_cutoff_hz = 1.0;
  double beta = 1.0;  // per (screen unit / s)
  double d_cutoff_hz = 1.0;
};

// Throws std::invalid_argument unless min_cutoff_hz > 0, beta >= 0, d_cutoff_hz > 0, all finite.
void validateOneEuroParams(const OneEuroParams& params);

class OneEuroFilter {
 public:
  explicit OneEuroFilter(const OneEuroParams& params = {});

  // Filters x observed dt_s after the previous sample (dt_s > 0; ignored for the first sample).
  double filter(double x, double dt_s);
  void reset() { initialized_ = false; }
  bool initialized() const { return initialized_; }

  // The smoothing factor for a cutoff frequency and a sample interval.
  static double alpha(double cutoff_hz, double dt_s);

 private:
  OneEuroParams params_;
  bool initialized_ = false;
  double x_hat_ = 0.0;
  double dx_hat_ = 0.0;
};

}  // namespace gaze_bridge
