#include "net/curve_sockets.h"

namespace curve {

void makeCurveServer(zmq::socket_t& socket, const Certificate& own, const std::string& zap_domain) {
  socket.set(zmq::sockopt::curve_server, 1);
  socket.set(zmq::sockopt::curve_secretkey, own.secret_key);
  socket.set(zmq::sockopt::zap_domain, zap_domain);
}

ClientKeys loadClientKeys(const std::string& secret_file, const std::string& server_file) {
  const Certificate own = readCertificate(secret_file, /*need_secret=*/true);
  const Certificate server = readCertificate(server_file);
  return {own.public_key, own.secret_key, server.public_key};
}

void makeCurveClient(zmq::socket_t& socket, const ClientKeys& keys) {
  socket.set(zmq::sockopt::curve_serverkey, keys.server_key);
  socket.set(zmq::sockopt::curve_publickey, keys.public_key);
  socket.set(zmq::sockopt::curve_secretkey, keys.secret_key);
}

std::optional<PeerRole> roleOf(const zmq::message_t& message) {
  // zmq_msg_gets takes a non-const message although it only reads it.
  const char* value = zmq_msg_gets(const_cast<zmq_msg_t*>(message.handle()), kRoleProperty);
  PeerRole role;
  if (value == nullptr || !roleByName(value, role)) return std::nullopt;
  return role;
}

bool isLoopbackEndpoint(const std::string& endpoint) {
  if (endpoint.rfind("inproc://", 0) == 0 || endpoint.rfind("ipc://", 0) == 0) return true;
  if (endpoint.rfind("tcp://", 0) != 0) return false;
  std::string host = endpoint.substr(6);
  // tcp://SOURCE;HOST:PORT binds nothing on SOURCE; the host after ';' is what listens or is reached.
  if (const auto semicolon = host.find(';'); semicolon != std::string::npos) host = host.substr(semicolon + 1);
  const auto colon = host.rfind(':');
  if (colon == std::string::npos) return false;
  host = host.substr(0, colon);
  if (host == "localhost" || host == "[::1]") return true;
  return host.rfind("127.", 0) == 0 && host.find_first_not_of("0123456789.") == std::string::npos;
}

}  // namespace curve
