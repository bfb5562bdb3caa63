// Counts rejected input per socket and logs it at a bounded rate: a flood of garbage costs a counter
// increment per message and at most one log line per socket per interval, never a log line each.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

#include "net/log_throttle.h"

namespace net {

enum class InputSocket { Gaze = 0, Pose = 1, Control = 2, Subscriptions = 3 };
inline constexpr int kInputSocketCount = 4;
const char* inputSocketName(InputSocket s);

class RejectionLog {
 public:
  explicit RejectionLog(std::chrono::milliseconds interval = std::chrono::seconds(1));

  // Called by the network thread only; the counters may be read from any thread. `reason` is ours,
  // or peer text already passed through echoText (peer_text.h).
  void reject(InputSocket socket, const std::string& reason);

  std::uint64_t total() const;
  std::uint64_t count(InputSocket socket) const {
    return counts_[static_cast<int>(socket)].load(std::memory_order_relaxed);
  }

 private:
  std::array<std::atomic<std::uint64_t>, kInputSocketCount> counts_{};
  std::array<LogThrottle, kInputSocketCount> throttles_;  // network-thread state
};

}  // namespace net
