// At most one log line per interval for a stream of like events, and how many events that line
// stands for: a flood costs a counter increment per event, never a line each (refused
// control requests, rejected input, refused keys and connections all log through one of these).
#pragma once

#include <chrono>
#include <cstdint>

namespace net {

class LogThrottle {
 public:
  using Clock = std::chrono::steady_clock;

  explicit LogThrottle(std::chrono::milliseconds interval = std::chrono::seconds(1)) : interval_(interval) {}

  // Counts one event. Returns how many events a line written now should report (this one and those
  // held back since the last line), or 0 while the next line is not due. The first event logs at once.
  std::uint64_t note(Clock::time_point now = Clock::now()) {
    ++held_;
    if (logged_ && now - last_ < interval_) return 0;
    logged_ = true;
    last_ = now;
    const std::uint64_t n = held_;
    held_ = 0;
    return n;
  }

 private:
  std::chrono::milliseconds interval_;
  bool logged_ = false;  // (not std::optional: GCC 12 sees it as maybe uninitialized under -O3)
  Clock::time_point last_{};
  std::uint64_t held_ = 0;
};

}  // namespace net
