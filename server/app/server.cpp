#include "app/server.h"

#include <google/protobuf/stubs/logging.h>
#include <spdlog/spdlog.h>

#include <stdexcept>

namespace app {

void routeProtobufLogs() {
  google::protobuf::SetLogHandler(
      [](google::protobuf::LogLevel, const char* file, int line, const std::string& message) {
        spdlog::debug("protobuf {}:{}: {}", file, line, message);
      });
}

Server::Server(const ServerOptions& options) : context_(1), rejections_(options.sim.log_interval) {
  routeProtobufLogs();
  if (options.net.curve) {
    if (options.curve_clients.empty()) throw std::invalid_argument("CURVE needs at least one client key");
    zap_ = std::make_unique<curve::ZapHandler>(context_, options.curve_clients, options.sim.log_interval);
  }
  net_ = std::make_unique<net::NetLoop>(context_, options.net, mailbox_, rejections_);
  sim_ = std::make_unique<SimLoop>(context_, options.sim, mailbox_, *net_, rejections_);
}

Server::~Server() { stop(); }

void Server::start() {
  if (running_) return;
  net_->start();
  sim_->start();
  running_ = true;
}

void Server::stop() {
  if (!running_) return;
  sim_->stop();
  net_->stop();
  running_ = false;
}

}  // namespace app
