// A program started by a test (sph_server, sph_keygen) with its stdout and stderr read back, and
// bounded waits for its output and exit. Killed (SIGKILL) if still running when the object goes.
#pragma once

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "net_test_util.h"
#include "support/server_args.h"

namespace net_test {

struct Child {
  pid_t pid = -1;
  int out_fd = -1;
  std::string output;

  // `environment`: variables to set in the child's environment, an empty value to unset one;
  // `files`: the child's RLIMIT_NOFILE (soft, hard), when given.
  explicit Child(std::vector<std::string> args,
                 const std::vector<std::pair<std::string, std::string>>& environment = {},
                 std::optional<std::pair<rlim_t, rlim_t>> files = std::nullopt) {
    int fds[2];
    if (::pipe(fds) != 0) return;
    pid = ::fork();
    if (pid == 0) {
      ::dup2(fds[1], STDOUT_FILENO);
      ::dup2(fds[1], STDERR_FILENO);
      ::close(fds[0]);
      if (files) {
        const rlimit limit{files->first, files->second};
        if (::setrlimit(RLIMIT_NOFILE, &limit) != 0) ::_exit(126);
      }
      for (const auto& [name, value] : environment) {
        if (value.empty()) {
          ::unsetenv(name.c_str());
        } else {
          ::setenv(name.c_str(), value.c_str(), 1);
        }
      }
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    ::close(fds[1]);
    out_fd = fds[0];
  }
  ~Child() {
    if (pid > 0 && ::waitpid(pid, nullptr, WNOHANG) == 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
    if (out_fd >= 0) ::close(out_fd);
  }
  // Reads output until a line holds `prefix` followed by a word; returns the word ("" after the
  // deadline). (std::regex trips GCC 12 warnings under the sanitizers, so plain search.)
  std::string waitForWordAfter(const std::string& prefix) {
    const auto end = std::chrono::steady_clock::now() + net_test::kTimeout;
    while (std::chrono::steady_clock::now() < end) {
      const auto at = output.find(prefix);
      if (at != std::string::npos) {
        const auto begin = at + prefix.size();
        const auto stop = output.find_first_of(" \r\n", begin);
        if (stop != std::string::npos) return output.substr(begin, stop - begin);
      }
      if (!readSome(100)) break;
    }
    return {};
  }
  bool readSome(int timeout_ms) {
    pollfd p{out_fd, POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) < 0) return false;
    if (p.revents & (POLLIN | POLLHUP)) {
      char buf[4096];
      const ssize_t n = ::read(out_fd, buf, sizeof buf);
      if (n <= 0) return false;
      output.append(buf, static_cast<std::size_t>(n));
    }
    return true;
  }
  // Exit status, or -1 when it has not exited before the deadline.
  int waitExit() {
    const auto end = std::chrono::steady_clock::now() + net_test::kTimeout;
    while (std::chrono::steady_clock::now() < end) {
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        pid = -1;
        while (readSome(0)) {
        }
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      }
      readSome(50);
    }
    return -1;
  }
};

// sph_server on the small test scene (gaze method), every endpoint an ephemeral loopback port. The
// tests replace arguments by index: 6 is the method, 10 the frames endpoint.
inline std::vector<std::string> serverArgs() {
  std::vector<std::string> args = sph_test::tinyPoolServerArgs(SPH_SERVER_BINARY, SPH_NET_TEST_SCENE_DIR);
  for (const char* option : {"--frames-endpoint", "--gaze-endpoint", "--pose-endpoint", "--control-endpoint"}) {
    args.insert(args.end(), {option, "tcp://127.0.0.1:*"});
  }
  return args;
}

}  // namespace net_test
