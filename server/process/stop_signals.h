// SIGINT and SIGTERM for a program that shuts down in an ordinary thread: blocked in every thread
// (construct this before any thread starts, libzmq's included), so only wait() receives them and
// no signal handler runs. sph_server and sph_relay stop this way.
#pragma once

#include <signal.h>

#include <chrono>

namespace process {

class StopSignals {
 public:
  StopSignals();
  // The signal that arrived within `timeout` (SIGINT or SIGTERM), or 0.
  int wait(std::chrono::milliseconds timeout);
  static const char* name(int signal) { return signal == SIGINT ? "SIGINT" : "SIGTERM"; }

 private:
  sigset_t set_;
};

}  // namespace process
