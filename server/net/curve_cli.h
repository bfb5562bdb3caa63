// The CURVE options as every program spells them (docs/security.md), for CLI11. Header only: the
// programs link CLI11, the libraries need not.
#pragma once

#include <CLI/CLI.hpp>
#include <exception>

#include "net/curve_setup.h"

namespace curve {

// sph_server and sph_relay (the bound side).
inline void addServerOptions(CLI::App& app, ServerFiles& files) {
  app.add_option("--curve-secret", files.secret,
                 "CURVE: this program's own key pair (NAME.key_secret from sph_keygen)");
  app.add_option("--curve-clients", files.clients_dir,
                 "CURVE: folder of allowed client keys (DIR/*.key, each with role viewer or operator)");
  app.add_flag("--insecure", files.insecure, "bind beyond loopback without CURVE (no authentication, no encryption)");
}

// sph_viewer, gaze_bridge and the relay's upstream (the connecting side). `prefix` tells the relay's
// upstream options from its own ("--upstream-"); empty for the clients.
inline void addClientOptions(CLI::App& app, ClientFiles& files, const std::string& prefix = "--") {
  app.add_option(prefix + "curve-secret", files.secret, "CURVE: this client's own key pair (NAME.key_secret)");
  app.add_option(prefix + "curve-server", files.server, "CURVE: the server's public key (its NAME.key)");
}

// A program's exit status when loading its keys failed: 1 for a key file it cannot use, 2 for options
// that do not go together (as for any other bad command line).
inline int exitCodeFor(const std::exception& error) {
  return dynamic_cast<const CertificateError*>(&error) != nullptr ? 1 : 2;
}

}  // namespace curve
