#include "net/socket_setup.h"

#include <stdexcept>

namespace net {

void applyCommonOptions(zmq::socket_t& socket) {
  socket.set(zmq::sockopt::linger, 0);
  socket.set(zmq::sockopt::heartbeat_ivl, kHeartbeatIntervalMs);
  socket.set(zmq::sockopt::heartbeat_timeout, kHeartbeatTimeoutMs);
  socket.set(zmq::sockopt::handshake_ivl, kHandshakeTimeoutMs);
}

void applyInputOptions(zmq::socket_t& socket, int max_bytes) {
  applyCommonOptions(socket);
  socket.set(zmq::sockopt::maxmsgsize, static_cast<int64_t>(max_bytes));
  socket.set(zmq::sockopt::rcvhwm, kInputReceiveHwm);
}

std::string bindResolved(zmq::socket_t& socket, const std::string& endpoint, const std::string& role) {
  try {
    socket.bind(endpoint);
  } catch (const zmq::error_t& e) {
    throw std::runtime_error("cannot bind " + role + " socket to " + endpoint + ": " + e.what());
  }
  return socket.get(zmq::sockopt::last_endpoint);
}

}  // namespace net
