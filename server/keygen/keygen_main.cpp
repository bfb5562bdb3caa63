// sph_keygen NAME --role viewer|operator|server --out DIR: writes DIR/NAME.key (the public key, with
// metadata name and role) and DIR/NAME.key_secret (both keys, mode 0600) in ZeroMQ's certificate
// format, which sph_server, sph_relay, sph_viewer, gaze_bridge and pyzmq's zmq.auth all read
// (docs/security.md). Never overwrites a key.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

#include "cli/cli_conventions.h"
#include "net/curve_keys.h"

int main(int argc, char** argv) {
  CLI::App app{
      "sph_keygen: makes a CURVE key pair for sph_server / sph_relay (role server) or a client (role viewer: "
      "frames, camera pose, status; role operator: also gaze and every control verb)"};
  cli::prepare(app, "sph_keygen");
  std::string name;
  std::string role = "viewer";
  std::string out = ".";
  app.add_option("name", name, "key name: the files are NAME.key and NAME.key_secret")->required();
  app.add_option("--role", role, "viewer, operator or server")
      ->check(CLI::IsMember({"viewer", "operator", "server"}))
      ->capture_default_str();
  app.add_option("--out", out, "folder to write into (created if missing)")->capture_default_str();
  if (auto code = cli::parse(app, argc, argv)) return *code;
  try {
    const curve::Certificate certificate = curve::generateCertificate(name, role);
    curve::writeCertificates(out, name, certificate);
    std::printf("wrote %s/%s.key and %s/%s.key_secret (role %s, public key %s)\n", out.c_str(), name.c_str(),
                out.c_str(), name.c_str(), role.c_str(), certificate.public_key.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph_keygen: %s\n", e.what());
    return 1;
  }
  return 0;
}
