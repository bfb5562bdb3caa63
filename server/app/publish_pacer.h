// When the simulation thread publishes a frame: on a steady clock at publish_hz, and at once when a
// step has used a gaze sample that no frame has shown yet, so the frame that answers a glance does
// not wait for the next tick of a 60 Hz clock (the latency that counts runs from gaze to refined
// frame). Early frames are capped: never more than two frames in any 1 / publish_hz, so a 200 Hz
// tracker cannot push the frame rate past twice publish_hz; an early frame also restarts the clock,
// so with sparse gaze the rate stays near publish_hz. Every due time derives from the last frames
// and the current rate, so a new rate applies from the next frame on (an old far-off deadline is
// never kept). Times are arguments, so the rules are tested without a clock.
#pragma once

#include <chrono>
#include <optional>

namespace app {

class PublishPacer {
 public:
  using Clock = std::chrono::steady_clock;

  // `hz` within [kMinPublishHz, kMaxPublishHz] (control_executor.h), so 1 / hz is a sane duration.
  PublishPacer(double hz, Clock::time_point start);

  void setRate(double hz);
  double rate() const { return hz_; }
  // A step has just used a gaze sample no published frame reflects yet.
  void freshSample() { fresh_ = true; }

  Clock::time_point nextDue() const;
  bool due(Clock::time_point now) const { return now >= nextDue(); }
  void published(Clock::time_point now);

 private:
  double hz_;
  Clock::duration period_;
  Clock::time_point tick_;  // the regular clock's next frame
  std::optional<Clock::time_point> last_;
  std::optional<Clock::time_point> before_last_;
  bool fresh_ = false;
};

}  // namespace app
