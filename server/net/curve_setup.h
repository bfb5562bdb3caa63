// From command-line options to a bound side's security (sph_server, sph_relay; docs/security.md):
// CURVE on every bound socket when --curve-secret and --curve-clients are given; without them a
// program binds only loopback, or beyond it with --insecure, which it then says at start and in
// every status line. Also the client side's two files (sph_viewer, gaze_bridge, the relay upstream).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "net/curve_keys.h"
#include "net/curve_sockets.h"

namespace curve {

struct ServerFiles {
  std::string secret;       // --curve-secret: the program's own NAME.key_secret
  std::string clients_dir;  // --curve-clients: the allowed client keys, DIR/*.key
  bool insecure = false;    // --insecure: beyond loopback without CURVE
};

struct ServerSecurity {
  std::optional<Certificate> own;  // set: CURVE on every bound socket
  AllowList clients;
  bool insecure = false;  // bound beyond loopback without CURVE
};

// Checks the combination against the endpoints the program binds and reads the key files. Throws
// std::invalid_argument (a bad combination) or CertificateError (a bad file), with the message for
// the user.
ServerSecurity loadServerSecurity(const ServerFiles& files, const std::vector<std::string>& bound_endpoints);

struct ClientFiles {
  std::string secret;  // --curve-secret: this client's NAME.key_secret
  std::string server;  // --curve-server: the server's (or relay's) public certificate
};

// None when neither file is given; throws std::invalid_argument when only one is, CertificateError
// for a bad file.
std::optional<ClientKeys> loadClientFiles(const ClientFiles& files);

}  // namespace curve
