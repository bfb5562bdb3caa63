#include "net/curve_setup.h"

#include <stdexcept>

namespace curve {

ServerSecurity loadServerSecurity(const ServerFiles& files, const std::vector<std::string>& bound_endpoints) {
  ServerSecurity security;
  if (files.secret.empty() != files.clients_dir.empty()) {
    throw std::invalid_argument("--curve-secret and --curve-clients go together");
  }
  const bool with_curve = !files.secret.empty();
  if (with_curve && files.insecure) throw std::invalid_argument("--insecure and --curve-secret exclude each other");
  if (with_curve) {
    security.own = readCertificate(files.secret, /*need_secret=*/true);
    security.clients = readAllowList(files.clients_dir);
    return security;
  }
  std::string beyond;
  for (const std::string& endpoint : bound_endpoints) {
    if (!isLoopbackEndpoint(endpoint)) beyond += (beyond.empty() ? "" : ", ") + endpoint;
  }
  if (!beyond.empty() && !files.insecure) {
    throw std::invalid_argument("binding beyond loopback (" + beyond +
                                ") needs CURVE: --curve-secret FILE.key_secret --curve-clients DIR (keys from "
                                "sph_keygen), or --insecure to serve without authentication");
  }
  security.insecure = !beyond.empty();
  return security;
}

std::optional<ClientKeys> loadClientFiles(const ClientFiles& files) {
  if (files.secret.empty() && files.server.empty()) return std::nullopt;
  if (files.secret.empty() || files.server.empty()) {
    throw std::invalid_argument("--curve-secret and --curve-server go together");
  }
  return loadClientKeys(files.secret, files.server);
}

}  // namespace curve
