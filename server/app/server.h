// sph_server as an object: the network thread (NetLoop), the simulation thread (SimLoop) and what
// they share (the ZeroMQ context, the input mailbox, the rejection counters). The program's main()
// and the integration tests both run it this way.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <zmq.hpp>

#include "app/sim_loop.h"
#include "net/curve_keys.h"
#include "net/input_mailbox.h"
#include "net/net_loop.h"
#include "net/rejection_log.h"
#include "net/zap_handler.h"

namespace app {

struct ServerOptions {
  net::NetConfig net;
  SimLoopOptions sim;
  // With net.curve: the client keys the ZAP handler lets in, each with its role (docs/security.md).
  curve::AllowList curve_clients;
};

class Server {
 public:
  // Binds every socket and loads the scene; throws std::exception (naming what failed) when it cannot.
  explicit Server(const ServerOptions& options);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  void start();
  // Stops the simulation thread, then the network thread; sockets close with linger 0.
  void stop();

  // The endpoints actually bound (tcp://127.0.0.1:* resolved to its port).
  const net::Endpoints& endpoints() const { return net_->bound(); }
  bool finished() const { return sim_->finished(); }
  std::string statusLine() const { return sim_->statusLine(); }
  // After stop(): false when a --save-state checkpoint was asked for and could not be written.
  bool stateSaved() const { return sim_->stateSaved(); }
  const SimCounters& simCounters() const { return sim_->counters(); }
  const net::NetCounters& netCounters() const { return net_->counters(); }
  const net::RejectionLog& rejections() const { return rejections_; }
  // Connections the ZAP handler refused (0 without CURVE).
  std::uint64_t keysRefused() const { return zap_ ? zap_->refused() : 0; }

 private:
  zmq::context_t context_;
  net::InputMailbox mailbox_;
  net::RejectionLog rejections_;
  // Before the sockets: it must answer from the first handshake on, and outlive them.
  std::unique_ptr<curve::ZapHandler> zap_;
  std::unique_ptr<net::NetLoop> net_;
  std::unique_ptr<SimLoop> sim_;
  bool running_ = false;
};

// Protobuf reports parse problems (invalid UTF-8 in a string, for example) on stderr itself; route
// them to the debug log so a flood of garbage does not flood the console. Idempotent.
void routeProtobufLogs();

}  // namespace app
