// CURVE keys for tests: a server key pair, an operator and a viewer key the server allows, and a
// stranger's key it does not, written by the same code sph_keygen uses into a fresh folder.
#pragma once

#include <filesystem>
#include <string>

#include "net/curve_keys.h"
#include "net/curve_sockets.h"
#include "temp_dir.h"

namespace net_test {

struct TestKeys {
  TempDir temp{"sph-test-keys"};
  std::filesystem::path dir = temp.path;
  curve::Certificate server;
  curve::AllowList allowed;
  curve::ClientKeys operator_keys, viewer_keys, stranger_keys;

  TestKeys() {
    std::filesystem::create_directory(dir / "clients");
    server = make("server", "server", dir.string());
    operator_keys = client(make("op", "operator", (dir / "clients").string()));
    viewer_keys = client(make("view", "viewer", (dir / "clients").string()));
    stranger_keys = client(make("stranger", "operator", dir.string()));  // not in clients/
    allowed = curve::readAllowList((dir / "clients").string());
  }

  std::string path(const std::string& name) const { return (dir / name).string(); }

 private:
  static curve::Certificate make(const std::string& name, const std::string& role, const std::string& where) {
    curve::Certificate c = curve::generateCertificate(name, role);
    curve::writeCertificates(where, name, c);
    return c;
  }
  curve::ClientKeys client(const curve::Certificate& c) const {
    return {c.public_key, c.secret_key, server.public_key};
  }
};

}  // namespace net_test
