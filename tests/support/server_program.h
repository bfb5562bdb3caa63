// The built sph_server as a child process for tests that kill and restart it (the fault
// tests): the first start binds ephemeral loopback ports, a restart binds the same ones again. Each
// start logs to its own file. Needs tests/viewer/child_process.cpp in the test binary.
#pragma once

#include <signal.h>

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "support/server_args.h"
#include "viewer/child_process.h"

namespace sph_test {

struct ServerEndpoints {
  std::string frames, gaze, pose, control;
};

class ServerProgram {
 public:
  // `args`: the program, the scene and any other options but the endpoints.
  ServerProgram(std::vector<std::string> args, std::string log_prefix)
      : args_(std::move(args)), log_prefix_(std::move(log_prefix)) {
    start({"tcp://127.0.0.1:*", "tcp://127.0.0.1:*", "tcp://127.0.0.1:*", "tcp://127.0.0.1:*"});
  }
  ~ServerProgram() {
    if (process_) {
      process_->terminate();
      process_->waitExit(std::chrono::seconds(10));
    }
  }

  const ServerEndpoints& endpoints() const { return endpoints_; }
  void kill() {
    ::kill(process_->pid(), SIGKILL);
    process_->waitExit(std::chrono::seconds(10));
  }
  // On the endpoints the first start bound (libzmq listens with SO_REUSEADDR, so they are free again).
  void restart() { start(endpoints_); }
  std::string log() const { return viewer_test::readFile(logPath()); }

 private:
  std::string logPath() const { return log_prefix_ + "." + std::to_string(starts_) + ".log"; }
  void start(const ServerEndpoints& at) {
    ++starts_;
    std::vector<std::string> argv = args_;
    argv.insert(argv.end(), {"--frames-endpoint", at.frames, "--gaze-endpoint", at.gaze, "--pose-endpoint", at.pose,
                             "--control-endpoint", at.control});
    process_ = std::make_unique<viewer_test::ChildProcess>(argv, logPath());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    ServerEndpoints bound;
    while (bound.control.empty() && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      const std::string text = log();
      bound = {find(text, "endpoint frames "), find(text, "endpoint gaze "), find(text, "endpoint pose "),
               find(text, "endpoint control ")};
    }
    if (bound.control.empty()) throw std::runtime_error("sph_server did not start: " + log());
    endpoints_ = bound;
  }
  static std::string find(const std::string& text, const std::string& key) {
    const auto at = text.find(key);
    if (at == std::string::npos) return {};
    const auto begin = at + key.size();
    const auto end = text.find_first_of(" \n", begin);
    return end == std::string::npos ? std::string() : text.substr(begin, end - begin);
  }

  std::vector<std::string> args_;
  std::string log_prefix_;
  int starts_ = 0;
  ServerEndpoints endpoints_;
  std::unique_ptr<viewer_test::ChildProcess> process_;
};

}  // namespace sph_test
