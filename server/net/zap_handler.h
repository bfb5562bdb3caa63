// The ZAP handler (ZeroMQ Authentication Protocol, RFC 27) of one ZeroMQ context: libzmq asks it,
// over inproc://zeromq.zap.01, about every CURVE client key during the handshake, and a connection
// whose key it refuses never carries a message (docs/security.md).
//
// It answers 200 for a key in the allow-list, with the key's name as User-Id and its role as the
// "Role" property (curve_sockets.h), which every message of that connection then carries; 400 for
// any other key or mechanism. It runs on its own thread, since libzmq's I/O thread waits for the
// answer mid-handshake and the network thread must never be that answer's bottleneck. It must be
// bound before any CURVE socket of the context binds (libzmq lets every key in when no handler is
// there), so construct it first and destroy it after those sockets are closed.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <zmq.hpp>

#include "net/curve_keys.h"

namespace curve {

class ZapHandler {
 public:
  // Binds inproc://zeromq.zap.01 in `context` (throws zmq::error_t when another handler has) and
  // starts the thread. Refusals are logged at most once per `log_interval` (with their count).
  ZapHandler(zmq::context_t& context, AllowList keys, std::chrono::milliseconds log_interval = std::chrono::seconds(1));
  ~ZapHandler();
  ZapHandler(const ZapHandler&) = delete;
  ZapHandler& operator=(const ZapHandler&) = delete;

  std::uint64_t accepted() const { return accepted_.load(); }
  std::uint64_t refused() const { return refused_.load(); }

 private:
  void run();
  void answer(std::vector<zmq::message_t>& request);

  AllowList keys_;
  std::chrono::milliseconds log_interval_;
  zmq::socket_t socket_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> accepted_{0};
  std::atomic<std::uint64_t> refused_{0};
  std::thread thread_;
};

}  // namespace curve
