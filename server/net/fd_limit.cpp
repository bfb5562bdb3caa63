#include "net/fd_limit.h"

#include <sys/resource.h>

#include <algorithm>

namespace net {

FileLimit raiseFileLimit() {
  FileLimit limit;
  rlimit r{};
  if (::getrlimit(RLIMIT_NOFILE, &r) != 0) return limit;
  limit.before = limit.now = static_cast<long>(r.rlim_cur);
  if (r.rlim_cur < r.rlim_max) {
    const rlim_t old = r.rlim_cur;
    r.rlim_cur = r.rlim_max;
    if (::setrlimit(RLIMIT_NOFILE, &r) == 0) {
      limit.now = static_cast<long>(r.rlim_max == RLIM_INFINITY ? old : r.rlim_max);
    }
  }
  return limit;
}

int peersPerSocket(long fd_limit, int sockets, int wanted) {
  if (fd_limit <= 0 || sockets <= 0) return wanted;
  const long room = (fd_limit - kReservedDescriptors) / sockets;
  return static_cast<int>(std::clamp<long>(room, 1, wanted));
}

}  // namespace net
