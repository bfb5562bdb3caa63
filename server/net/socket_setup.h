// One place for the socket options docs/design.md section 6 asks for, so every socket the server binds gets
// the same limits: a size cap on every input, bounded high-water marks, heartbeats to notice dead peers,
// and a bounded linger so shutdown never hangs on an unreachable peer.
#pragma once

#include <string>
#include <zmq.hpp>

namespace net {

// Largest message accepted on the gaze, camera pose and control sockets (and XPUB subscriptions).
// A peer that sends more is disconnected by libzmq before the message reaches us.
inline constexpr int kMaxInputBytes = 64 * 1024;
// Frames queued per subscriber before PUB drops for that subscriber: a slow viewer loses frames
// (it sees the sequence gap) instead of holding memory or time.
inline constexpr int kFrameSendHwm = 4;
inline constexpr int kInputReceiveHwm = 1000;
inline constexpr int kHeartbeatIntervalMs = 1000;
inline constexpr int kHeartbeatTimeoutMs = 3000;
// A connection that has not finished its ZMTP (or CURVE) handshake by then is dropped: a peer that
// connects and says nothing holds a descriptor this long at most (libzmq's default is 30 s).
inline constexpr int kHandshakeTimeoutMs = 10000;
// Connections per bound socket unless the descriptor limit asks for fewer (fd_limit.h).
inline constexpr int kDefaultMaxPeers = 256;

// Options common to every socket: heartbeats, the handshake timeout and linger 0 (nothing left
// unsent may delay exit).
void applyCommonOptions(zmq::socket_t& socket);
// An input socket: size cap and receive high-water mark.
void applyInputOptions(zmq::socket_t& socket, int max_bytes = kMaxInputBytes);

// Binds and returns the endpoint actually bound (tcp://127.0.0.1:* resolves to the chosen port).
// Throws std::runtime_error naming `role` and the endpoint when the bind fails.
std::string bindResolved(zmq::socket_t& socket, const std::string& endpoint, const std::string& role);

}  // namespace net
