// Starting sph_viewer (and Xvfb) as child processes from a test, with bounded waits.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace viewer_test {

class ChildProcess {
 public:
  // Starts `argv[0]` with its stdout and stderr appended to `log_path`, with this process's
  // environment plus `extra_env` ("NAME=value"). Throws on failure.
  ChildProcess(const std::vector<std::string>& argv, const std::string& log_path,
               const std::vector<std::string>& extra_env = {});
  ~ChildProcess();  // kills a child still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // The exit code, or nullopt if it did not exit within `timeout` (the child is then killed).
  std::optional<int> waitExit(std::chrono::milliseconds timeout);
  bool running();
  void terminate();  // SIGTERM
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  std::optional<int> status_;
};

std::string readFile(const std::string& path);

// If DISPLAY is unset, starts Xvfb on a free display (Xvfb -displayfd picks it, so parallel tests
// never race for a number) and sets DISPLAY for this process and its children. Stops it at exit.
class VirtualDisplay {
 public:
  VirtualDisplay();
  ~VirtualDisplay();
  const std::string& display() const { return display_; }

 private:
  pid_t pid_ = -1;
  std::string display_;
};

}  // namespace viewer_test
