// The built sph_server program: --help lists the endpoints, it serves on ephemeral ports, and SIGTERM
// (or SIGINT) shuts it down cleanly with a final status line.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <utility>
#include <vector>

#include "net_test_util.h"

namespace {

struct Child {
  pid_t pid = -1;
  int out_fd = -1;
  std::string output;

  // `environment`: variables to set in the child's environment, an empty value to unset one.
  explicit Child(std::vector<std::string> args,
                 const std::vector<std::pair<std::string, std::string>>& environment = {}) {
    int fds[2];
    if (::pipe(fds) != 0) return;
    pid = ::fork();
    if (pid == 0) {
      ::dup2(fds[1], STDOUT_FILENO);
      ::dup2(fds[1], STDERR_FILENO);
      ::close(fds[0]);
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

std::vector<std::string> serverArgs() {
  return {SPH_SERVER_BINARY,
          "--scene",
          "tiny_pool",
          "--scene-dir",
          SPH_NET_TEST_SCENE_DIR,
          "--method",
          "gaze",
          "--threads",
          "1",
          "--frames-endpoint",
          "tcp://127.0.0.1:*",
          "--gaze-endpoint",
          "tcp://127.0.0.1:*",
          "--pose-endpoint",
          "tcp://127.0.0.1:*",
          "--control-endpoint",
          "tcp://127.0.0.1:*"};
}

TEST(ServerBinary, HelpListsEveryEndpoint) {
  Child child({SPH_SERVER_BINARY, "--help"});
  EXPECT_EQ(child.waitExit(), 0);
  for (const char* option : {"--frames-endpoint", "--gaze-endpoint", "--pose-endpoint", "--control-endpoint",
                             "tcp://127.0.0.1:5555", "tcp://127.0.0.1:5558", "--camera-source", "--free-run"}) {
    EXPECT_NE(child.output.find(option), std::string::npos) << option;
  }
}

std::size_t countOf(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

// libgomp prints the wait it was loaded with when OMP_DISPLAY_ENV=VERBOSE: with no policy in the
// environment the program re-executes itself once with the bounded spin (process/omp_wait.h); a
// policy the user gives is left alone and the program runs once.
TEST(ServerBinary, WaitsWithABoundedSpinUnlessTheEnvironmentSaysOtherwise) {
  const std::string spin_line = "GOMP_SPINCOUNT = '";
  Child plain({SPH_SERVER_BINARY, "--help"},
              {{"OMP_DISPLAY_ENV", "VERBOSE"}, {"OMP_WAIT_POLICY", ""}, {"GOMP_SPINCOUNT", ""}});
  ASSERT_EQ(plain.waitExit(), 0) << plain.output;
  // Two loads of libgomp (before and after the re-execution), the last with the bounded spin.
  EXPECT_EQ(countOf(plain.output, spin_line), 2u) << plain.output;
  EXPECT_EQ(plain.output.rfind(spin_line), plain.output.find(spin_line + "1000'")) << plain.output;
  EXPECT_EQ(countOf(plain.output, "--frames-endpoint"), 1u) << "the help printed more than once";

  Child active({SPH_SERVER_BINARY, "--help"},
               {{"OMP_DISPLAY_ENV", "VERBOSE"}, {"OMP_WAIT_POLICY", "ACTIVE"}, {"GOMP_SPINCOUNT", ""}});
  ASSERT_EQ(active.waitExit(), 0) << active.output;
  EXPECT_EQ(countOf(active.output, spin_line), 1u) << active.output;
  EXPECT_EQ(active.output.find(spin_line + "1000'"), std::string::npos) << active.output;

  Child spin({SPH_SERVER_BINARY, "--help"},
             {{"OMP_DISPLAY_ENV", "VERBOSE"}, {"OMP_WAIT_POLICY", ""}, {"GOMP_SPINCOUNT", "7"}});
  ASSERT_EQ(spin.waitExit(), 0) << spin.output;
  EXPECT_EQ(countOf(spin.output, spin_line), 1u) << spin.output;
  EXPECT_NE(spin.output.find(spin_line + "7'"), std::string::npos) << spin.output;
}

TEST(ServerBinary, UnknownMethodIsAnError) {
  auto args = serverArgs();
  args[6] = "sideways";
  Child child(args);
  EXPECT_NE(child.waitExit(), 0);
  EXPECT_NE(child.output.find("--method"), std::string::npos) << child.output;
}

TEST(ServerBinary, BadAdaptiveSettingIsAnError) {
  auto args = serverArgs();
  args.insert(args.end(), {"--gaze-radius", "0.5"});  // wider than the hysteresis ring
  Child child(args);
  EXPECT_EQ(child.waitExit(), 1);
  EXPECT_NE(child.output.find("gaze_r"), std::string::npos) << child.output;
  Child unknown([] {
    auto a = serverArgs();
    a.insert(a.end(), {"--adaptive", "no_such=1"});
    return a;
  }());
  EXPECT_EQ(unknown.waitExit(), 1);
  EXPECT_NE(unknown.output.find("unknown parameter 'no_such'"), std::string::npos) << unknown.output;
}

void expectCleanShutdown(int signal) {
  Child child(serverArgs());
  const std::string control = child.waitForWordAfter("endpoint control ");
  ASSERT_EQ(control.rfind("tcp://127.0.0.1:", 0), 0u) << child.output;
  const std::string frames = child.waitForWordAfter("endpoint frames ");
  ASSERT_EQ(frames.rfind("tcp://127.0.0.1:", 0), 0u) << child.output;
  zmq::context_t ctx;
  net_test::FrameSubscriber sub(ctx, frames);
  ASSERT_TRUE(sub.next());
  net_test::ControlClient client(ctx, control);
  auto reply = client.send(net_test::statusRequest());
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->status().scene(), "tiny_pool");
  ::kill(child.pid, signal);
  EXPECT_EQ(child.waitExit(), 0) << child.output;
  EXPECT_NE(child.output.find("shutting down"), std::string::npos) << child.output;
  EXPECT_NE(child.output.find("final status: tiny_pool gaze"), std::string::npos) << child.output;
}

TEST(ServerBinary, SigtermShutsDownCleanly) { expectCleanShutdown(SIGTERM); }

TEST(ServerBinary, SigintShutsDownCleanly) { expectCleanShutdown(SIGINT); }

TEST(ServerBinary, MaxStepsEndsAScriptedRun) {
  auto args = serverArgs();
  args.insert(args.end(), {"--free-run", "--max-steps", "20"});
  Child child(args);
  EXPECT_EQ(child.waitExit(), 0) << child.output;
  EXPECT_NE(child.output.find("ran 20 steps"), std::string::npos) << child.output;
}

TEST(ServerBinary, PortInUseIsAClearError) {
  zmq::context_t ctx;
  zmq::socket_t holder(ctx, zmq::socket_type::pub);
  holder.bind("tcp://127.0.0.1:*");
  auto args = serverArgs();
  args[10] = holder.get(zmq::sockopt::last_endpoint);
  Child child(args);
  EXPECT_EQ(child.waitExit(), 1);
  EXPECT_NE(child.output.find("cannot bind frames socket"), std::string::npos) << child.output;
}

}  // namespace
