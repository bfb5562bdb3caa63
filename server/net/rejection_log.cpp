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

void RejectionLog::reject(InputSocket socket, const std::string& reason) {
  const int i = static_cast<int>(socket);
  counts_[i].fetch_add(1, std::memory_order_relaxed);
  ++unreported_[i];
  const auto now = std::chrono::steady_clock::now();
  if (now - last_logged_[i] < interval_) return;
  spdlog::warn("rejected {} input on the {} socket (latest: {}; {} rejected in all)", unreported_[i],
               inputSocketName(socket), reason, count(socket));
  last_logged_[i] = now;
  unreported_[i] = 0;
}

std::uint64_t RejectionLog::total() const {
  std::uint64_t sum = 0;
  for (const auto& c : counts_) sum += c.load(std::memory_order_relaxed);
  return sum;
}

}  // namespace net
