#include "app/realtime_governor.h"

#include <algorithm>
#include <cmath>

namespace app {

RealtimeGovernor::RealtimeGovernor(double base_gain, double max_gain)
    : base_(base_gain), max_(std::max(max_gain, base_gain)), gain_(base_gain) {}

void RealtimeGovernor::reset(double base_gain) {
  base_ = base_gain;
  max_ = std::max(max_, base_);
  gain_ = base_;
  ratio_ = 0.0;
}

double RealtimeGovernor::update(double sim_s, double wall_s, double busy_s) {
  if (!(wall_s > 0.0) || !std::isfinite(sim_s) || !std::isfinite(busy_s)) return gain_;
  ratio_ = sim_s / wall_s;
  if (ratio_ < kBehind) {
    // In proportion to the shortfall, at least a fifth more a window and at most doubling, so one
    // slow window does not throw the rings away.
    gain_ = std::min(max_, gain_ * std::clamp(1.0 / std::max(ratio_, 1e-3), 1.2, 2.0));
  } else if (ratio_ >= kCaughtUp && busy_s / wall_s < kSpare) {
    gain_ = std::max(base_, gain_ / 1.1);
  }
  return gain_;
}

}  // namespace app
