// sph_relay: frames from one sph_server (or another relay) to viewers beyond one machine.
// ZeroMQ's own proxy does the forwarding (zmq_proxy_steerable): an XSUB connects upstream and a PUB
// binds downstream, so a viewer connects to a relay exactly as to the server. The downstream side
// takes the server's protections: CURVE and the ZAP handler (any allowed key, a viewer's is enough),
// the subscription size limit, a cap on connections, and a drop for a peer that sends far more than
// a subscriber does (libzmq would keep every subscription it sent, connection_monitor.h).
//
// Why PUB and not XPUB downstream: the proxy passes whatever XPUB receives upstream, so a viewer's
// junk subscriptions would reach the server as the relay's own and get the relay dropped there. PUB
// keeps subscriptions to itself; the XSUB asks upstream for everything once, and again by itself
// after every reconnection.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <zmq.hpp>

#include "net/connection_monitor.h"
#include "net/curve_keys.h"
#include "net/curve_sockets.h"
#include "net/socket_setup.h"
#include "net/zap_handler.h"

namespace relay {

struct RelayOptions {
  std::string upstream = "tcp://127.0.0.1:5555";    // the server's (or a relay's) frames endpoint
  std::string downstream = "tcp://127.0.0.1:5565";  // bound; viewers connect here
  std::optional<curve::ClientKeys> upstream_curve;  // the relay's own client key for the server
  std::optional<curve::Certificate> curve;          // downstream: the relay's key pair
  curve::AllowList clients;                         // downstream: the keys let in
  // Frames queued per viewer (and from upstream) before PUB drops for that viewer: a few frames,
  // as on the server (net::kFrameSendHwm); more for a relay over a slow link.
  int hwm = net::kFrameSendHwm;
  int max_peers = net::kDefaultMaxPeers;
  int fd_limit = 0;
  std::chrono::milliseconds log_interval{1000};
  // Called on the relay's monitor thread with every frame it forwarded (tests, statistics).
  std::function<void(const zmq::message_t&)> on_forward;
};

class Relay {
 public:
  // Binds downstream and connects upstream (throws std::runtime_error naming what failed).
  explicit Relay(const RelayOptions& options);
  ~Relay();
  Relay(const Relay&) = delete;
  Relay& operator=(const Relay&) = delete;

  void start();
  void stop();  // ends the proxy, then the monitor thread; sockets close with linger 0

  const std::string& downstream() const { return downstream_; }  // as bound (port resolved)
  std::uint64_t forwarded() const { return forwarded_.load(); }
  int peers() const { return peers_.load(); }
  std::uint64_t peersDropped() const { return peers_dropped_.load(); }

 private:
  void watch();

  RelayOptions options_;
  zmq::context_t context_{1};
  std::unique_ptr<curve::ZapHandler> zap_;  // before the sockets: from the first handshake on
  zmq::socket_t upstream_;
  zmq::socket_t downstream_socket_;
  zmq::socket_t capture_;  // the proxy's copy of every message it passes
  zmq::socket_t capture_reader_;
  zmq::socket_t control_;  // the proxy's steering socket (its end)
  zmq::socket_t steer_;    // ours: TERMINATE
  std::unique_ptr<net::ConnectionMonitor> monitor_;
  std::string downstream_;
  std::atomic<std::uint64_t> forwarded_{0};
  std::atomic<int> peers_{0};
  std::atomic<std::uint64_t> peers_dropped_{0};
  std::atomic<bool> stop_watch_{false};
  std::thread proxy_thread_;
  std::thread watch_thread_;
  bool running_ = false;
};

}  // namespace relay
