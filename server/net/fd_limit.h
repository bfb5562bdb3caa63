// File descriptors: every TCP peer holds one, and a process out of them can accept no
// one, with nothing said by libzmq. So a program raises its soft RLIMIT_NOFILE to the hard limit at
// start, and caps the peers of each bound socket so that all of them together leave room for what
// the process itself needs (libzmq's own descriptors, files, logs).
#pragma once

namespace net {

// Descriptors kept free of peers: libzmq's signalling descriptors (one a socket, a few per
// thread), the ZAP and monitor pipes, stdio and a scene file or two.
inline constexpr long kReservedDescriptors = 64;

struct FileLimit {
  long before = 0;  // the soft limit the process started with
  long now = 0;     // after raising it (the hard limit, or `before` where raising failed)
};
FileLimit raiseFileLimit();

// Peers each of `sockets` bound sockets may take: `wanted`, or fewer where the limit asks (at least 1).
int peersPerSocket(long fd_limit, int sockets, int wanted);

}  // namespace net
