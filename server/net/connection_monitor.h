// What libzmq does not do for a bound socket: say how many peers are connected, cap them,
// report a failed accept (the descriptor limit reached: EMFILE, which otherwise leaves new peers
// unserved with nothing logged), or drop one peer. A socket monitor gives each TCP connection's
// descriptor as it is accepted and as it goes (ZMQ_EVENT_ACCEPTED / DISCONNECTED), and shutdown(2)
// on that descriptor makes libzmq drop the connection as if the peer had left (libzmq still closes
// it). A descriptor libzmq has closed and reused before its DISCONNECTED event is read could name
// another connection; the events are drained just before any drop, so that window is a few
// microseconds and its worst case is one peer that reconnects.
//
// One thread reads the events (the one that polls events()); drops may come from that thread only.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <zmq.hpp>

#include "net/log_throttle.h"

namespace net {

class ConnectionMonitor {
 public:
  using Clock = std::chrono::steady_clock;

  // Starts monitoring `socket`, which must not be bound yet (no event may be missed). `role` names
  // the socket in logs; beyond `max_peers` connections at a time, one is dropped for each that comes
  // (the oldest that never sent a greeting, else the newcomer);
  // `fd_limit` is only quoted in the log when accepting fails.
  ConnectionMonitor(zmq::context_t& context, zmq::socket_t& socket, std::string role, int max_peers, int fd_limit,
                    std::chrono::milliseconds log_interval);
  // Stops the monitor on the socket, which must still be open and owned by the calling thread.
  ~ConnectionMonitor();
  ConnectionMonitor(const ConnectionMonitor&) = delete;
  ConnectionMonitor& operator=(const ConnectionMonitor&) = delete;

  zmq::socket_t& events() { return events_; }  // poll for ZMQ_POLLIN, then drain()
  void drain();

  // TCP or IPC connections accepted and not gone yet (inproc peers are not seen).
  int peers() const;
  // Drops every peer that has sent more than `base_bytes + bytes_per_second * age`; returns how many.
  int dropPeersOver(std::uint64_t base_bytes, double bytes_per_second);
  int dropAll();

  std::uint64_t acceptFailures() const { return accept_failures_; }
  std::uint64_t refusedOverLimit() const { return refused_over_limit_; }
  std::uint64_t handshakeFailures() const { return handshake_failures_; }
  std::uint64_t dropped() const { return dropped_; }

 private:
  struct Peer {
    Clock::time_point accepted;
    bool dropped = false;
  };
  void onEvent(std::uint16_t event, std::uint32_t value);
  void drop(int fd, Peer& peer);
  // The oldest connection, accepted a while before `now`, that has not sent a whole greeting.
  std::map<int, Peer>::iterator silentPeer(Clock::time_point now);

  zmq::socket_t& socket_;
  std::string role_;
  int max_peers_;
  int fd_limit_;
  zmq::socket_t events_;
  std::map<int, Peer> peers_;  // by descriptor
  std::uint64_t accept_failures_ = 0;
  std::uint64_t refused_over_limit_ = 0;
  std::uint64_t handshake_failures_ = 0;
  std::uint64_t dropped_ = 0;
  LogThrottle accept_log_;
  LogThrottle limit_log_;
  LogThrottle handshake_log_;
};

}  // namespace net
