// sph_relay: forwards one sph_server's frames to viewers that connect to it as to the server (see
// relay.h, docs/security.md). Downstream it binds loopback unless given CURVE keys or --insecure,
// as the server does; upstream it may present its own key to a CURVE server.
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <exception>
#include <string>

#include "cli/cli_conventions.h"
#include "net/curve_cli.h"
#include "net/fd_limit.h"
#include "process/stop_signals.h"
#include "relay/relay.h"

int main(int argc, char** argv) {
  CLI::App cli{"sph_relay: forwards an sph_server's frames (XSUB upstream -> PUB downstream, ZeroMQ's proxy)"};
  cli::prepare(cli, "sph_relay");
  relay::RelayOptions options;
  curve::ServerFiles downstream_keys;
  curve::ClientFiles upstream_keys;
  int max_peers = net::kDefaultMaxPeers;
  double status_interval_s = 5.0;
  std::string log_level = "info";
  cli.add_option("--upstream", options.upstream, "the server's (or a relay's) frames endpoint to connect to")
      ->capture_default_str();
  cli.add_option("--endpoint", options.downstream, "where viewers connect (bound)")->capture_default_str();
  curve::addServerOptions(cli, downstream_keys);
  curve::addClientOptions(cli, upstream_keys, "--upstream-");
  cli.add_option("--hwm", options.hwm, "frames queued per viewer before it misses some")
      ->check(cli::range(1, 100000))
      ->capture_default_str();
  cli.add_option("--max-peers", max_peers, "viewer connections at a time (fewer when the descriptor limit asks)")
      ->check(cli::range(1, 100000))
      ->capture_default_str();
  cli.add_option("--status-interval", status_interval_s, "seconds between status lines (0: off)")
      ->check(cli::range(0, 86400))
      ->capture_default_str();
  cli.add_option("--log-level", log_level, "trace, debug, info, warn, error")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}))
      ->capture_default_str();
  if (auto code = cli::parse(cli, argc, argv)) return *code;
  spdlog::set_level(spdlog::level::from_str(log_level));
  cli::logToStderr();

  bool insecure = false;
  try {
    curve::ServerSecurity security = curve::loadServerSecurity(downstream_keys, {options.downstream});
    options.curve = std::move(security.own);
    options.clients = std::move(security.clients);
    insecure = security.insecure;
    options.upstream_curve = curve::loadClientFiles(upstream_keys);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return curve::exitCodeFor(e);
  }
  const net::FileLimit fds = net::raiseFileLimit();
  options.fd_limit = fds.now;
  options.max_peers = net::peersPerSocket(fds.now, 1, max_peers);

  process::StopSignals stop_signals;  // before any thread starts
  try {
    relay::Relay relay(options);
    spdlog::info("endpoint relay {}", relay.downstream());
    spdlog::info("upstream {}{}", options.upstream, options.upstream_curve ? " (CURVE)" : "");
    spdlog::info("file descriptors: limit {} (was {}), up to {} viewers", fds.now, fds.before, options.max_peers);
    const std::string warning = insecure ? "; INSECURE: bound beyond loopback without CURVE (--insecure)" : "";
    if (options.curve) spdlog::info("CURVE downstream: {} client keys allowed", options.clients.size());
    if (insecure) spdlog::warn("INSECURE: bound beyond loopback without CURVE (--insecure)");
    relay.start();
    const auto status = [&] {
      return fmt::format("{} frames forwarded, {} viewers, {} dropped{}", relay.forwarded(), relay.peers(),
                         relay.peersDropped(), warning);
    };
    auto next_status = std::chrono::steady_clock::now();
    for (;;) {
      if (const int signal = stop_signals.wait(std::chrono::milliseconds(100))) {
        spdlog::info("{} received, shutting down", process::StopSignals::name(signal));
        break;
      }
      if (status_interval_s > 0.0 && std::chrono::steady_clock::now() >= next_status) {
        spdlog::info("{}", status());
        next_status += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(status_interval_s));
      }
    }
    relay.stop();
    spdlog::info("final status: {}", status());
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
  return 0;
}
