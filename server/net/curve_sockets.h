// CURVE on a socket, both ends (docs/security.md). A server socket (sph_server, sph_relay
// downstream) presents its own key pair and has libzmq ask the ZAP handler (zap_handler.h) about
// every client key; the handler's answer carries the key's role, which every message from that
// connection then holds as its "Role" property. A client socket (sph_viewer, gaze_bridge, the
// relay's upstream) presents its own key pair and checks the server's public key.
#pragma once

#include <optional>
#include <string>
#include <zmq.hpp>

#include "net/curve_keys.h"

namespace curve {

// The message property the ZAP handler sets to the key's role ("viewer" or "operator"). libzmq puts
// the handler's properties before any the peer announces in its handshake, so a peer cannot forge it.
inline constexpr const char* kRoleProperty = "Role";

// Before bind. `own` must hold the secret key; `zap_domain` names the socket in the handler's log.
void makeCurveServer(zmq::socket_t& socket, const Certificate& own, const std::string& zap_domain);

// A client's key pair and the server it trusts, all Z85.
struct ClientKeys {
  std::string public_key;
  std::string secret_key;
  std::string server_key;
};
// From the client's NAME.key_secret and the server's public certificate (server.key). Throws
// CertificateError naming the file that is wrong.
ClientKeys loadClientKeys(const std::string& secret_file, const std::string& server_file);
// Before connect.
void makeCurveClient(zmq::socket_t& socket, const ClientKeys& keys);

// The role the ZAP handler gave the connection `message` came from; nullopt for a message from a
// connection that was not authenticated (no CURVE).
std::optional<PeerRole> roleOf(const zmq::message_t& message);

// True for endpoints only this machine can reach: tcp:// on 127.0.0.0/8, localhost or [::1], and
// ipc:// or inproc://. tcp://0.0.0.0, tcp://*, an interface name or any other address is not.
bool isLoopbackEndpoint(const std::string& endpoint);

}  // namespace curve
