// Wall-clock time of the step's phases (PhaseTimings, solvers/fluid_solver.h): a timer adds the
// milliseconds from start to stop, or to the end of its scope, to the total it was started on.
#pragma once

#include <chrono>

namespace sph {

class PhaseTimer {
 public:
  explicit PhaseTimer(double& total_ms) { start(total_ms); }
  ~PhaseTimer() { stop(); }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

  // Stops the phase being timed, if any, and times the next one into `total_ms`.
  void start(double& total_ms) {
    stop();
    total_ms_ = &total_ms;
    start_ = Clock::now();
  }
  void stop() {
    if (total_ms_ == nullptr) return;
    *total_ms_ += std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
    total_ms_ = nullptr;
  }

 private:
  using Clock = std::chrono::steady_clock;
  double* total_ms_ = nullptr;
  Clock::time_point start_;
};

}  // namespace sph
