#include "one_euro_filter.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gaze_bridge {

void validateOneEuroParams(const OneEuroParams& p) {
  if (!(std::isfinite(p.min_cutoff_hz) && p.min_cutoff_hz > 0.0)) {
    throw std::invalid_argument("One Euro filter: mincutoff must be > 0 Hz");
  }
  if (!(std::isfinite(p.beta) && p.beta >= 0.0)) throw std::invalid_argument("One Euro filter: beta must be >= 0");
  if (!(std::isfinite(p.d_cutoff_hz) && p.d_cutoff_hz > 0.0)) {
    throw std::invalid_argument("One Euro filter: dcutoff must be > 0 Hz");
  }
}

OneEuroFilter::OneEuroFilter(const OneEuroParams& params) : params_(params) { validateOneEuroParams(params_); }

double OneEuroFilter::alpha(double cutoff_hz, double dt_s) {
  const double tau = 1.0 / (2.0 * std::numbers::pi * cutoff_hz);
  return 1.0 / (1.0 + tau / dt_s);
}

double OneEuroFilter::filter(double x, double dt_s) {
  if (!initialized_) {
    initialized_ = true;
    x_hat_ = x;
    dx_hat_ = 0.0;
    return x;
  }
  const double dx = (x - x_hat_) / dt_s;
  const double a_d = alpha(params_.d_cutoff_hz, dt_s);
  dx_hat_ = a_d * dx + (1.0 - a_d) * dx_hat_;
  const double cutoff = params_.min_cutoff_hz + params_.beta * std::abs(dx_hat_);
  const double a = alpha(cutoff, dt_s);
  x_hat_ = a * x + (1.0 - a) * x_hat_;
  return x_hat_;
}

}  // namespace gaze_bridge
