// Holds simulated time in step with wall time by trading the foveated method's periphery gain g
// (adaptive/method.h: a particle may look q (1 + g m e / w0) finest particles wide): behind real
// time g grows, so the rings of finer levels around the gaze narrow from the outside in, the
// periphery coarsening first while the gaze point keeps q's level; with time to spare g falls back
// towards the configured one. It sees only figures per window, no clock, so its rule is tested on
// its own.
#pragma once

namespace app {

class RealtimeGovernor {
 public:
  // `base_gain`: the configured g, the least the governor uses; `max_gain`: the most.
  RealtimeGovernor(double base_gain, double max_gain);

  // After a window of running: the simulated and wall-clock seconds it spanned and the wall
  // seconds the steps took. Returns the g to use next.
  double update(double sim_s, double wall_s, double busy_s);
  // Back to the configured g (a new scene or method, or a new setting).
  void reset(double base_gain);

  double gain() const { return gain_; }
  double baseGain() const { return base_; }
  double maxGain() const { return max_; }
  // The gain at the most the governor may use: it cannot coarsen the periphery further.
  bool atCeiling() const { return gain_ >= max_; }
  // Simulated over wall-clock seconds in the last window (1: real time; 0 before the first).
  double realtimeRatio() const { return ratio_; }

  // Behind real time below this ratio; with time to spare at or above kCaughtUp while the steps
  // took less than kSpare of the wall clock. Between the two the gain holds, so the pacing's
  // jitter does not move it.
  static constexpr double kBehind = 0.95;
  static constexpr double kCaughtUp = 0.98;
  static constexpr double kSpare = 0.75;

 private:
  double base_;
  double max_;
  double gain_;
  double ratio_ = 0.0;
};

}  // namespace app
