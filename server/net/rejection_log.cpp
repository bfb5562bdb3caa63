#include "net/rejection_log.h"

#include <spdlog/spdlog.h>

namespace net {

const char* inputSocketName(InputSocket s) {
  switch (s) {
    case InputSocket::Gaze:
      return "gaze";
    case InputSocket::Pose:
      return "camera pose";
    case InputSocket::Control:
      return "control";
    case InputSocket::Subscriptions:
      return "frame subscriptions";
  }
  return "?";
}

RejectionLog::RejectionLog(std::chrono::milliseconds interval)
    : throttles_{LogThrottle(interval), LogThrottle(interval), LogThrottle(interval), LogThrottle(interval)} {}

void RejectionLog::reject(InputSocket socket, const std::string& reason) {
  const int i = static_cast<int>(socket);
  counts_[i].fetch_add(1, std::memory_order_relaxed);
  if (const std::uint64_t n = throttles_[i].note()) {
    spdlog::warn("rejected {} input on the {} socket (latest: {}; {} rejected in all)", n, inputSocketName(socket),
                 reason, count(socket));
  }
}

std::uint64_t RejectionLog::total() const {
  std::uint64_t sum = 0;
  for (const auto& c : counts_) sum += c.load(std::memory_order_relaxed);
  return sum;
}

}  // namespace net
