// The gaze_bridge program itself: options, a replay streamed to a socket, clean exit on SIGTERM.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>

#include "bridge_harness.h"
#include "gaze/gaze_recording.h"

using namespace gaze_bridge_test;
using namespace std::chrono_literals;

namespace {

std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "gaze_bridge_program_" + name + "_" + std::to_string(::getpid()) + ".csv";
}

pid_t start(const std::vector<std::string>& args, const std::string& output_path) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<char*> argv;
    std::string program = GAZE_BRIDGE_PROGRAM;
    argv.push_back(program.data());
    std::vector<std::string> copy = args;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::FILE* out = std::freopen(output_path.c_str(), "w", stdout);
    if (out != nullptr) ::dup2(::fileno(stdout), STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

// Exit status, or -1 if it did not end within 30 s (then it is killed).
int waitExit(pid_t pid) {
  const auto end = std::chrono::steady_clock::now() + 30s;
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (::waitpid(pid, &status, WNOHANG) == pid)
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::this_thread::sleep_for(10ms);
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return -1;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(Program, HelpListsOptions) {
  const std::string out = tempPath("help");
  EXPECT_EQ(waitExit(start({"--help"}, out)), 0);
  const std::string text = readAll(out);
  for (const char* option : {"--source", "--endpoint", "--min-confidence", "--mincutoff", "--beta", "--dcutoff",
                             "--record", "--replay-speed", "--pupil-surface", "--gazepoint-port", "--ivt"}) {
    EXPECT_NE(text.find(option), std::string::npos) << option;
  }
  std::remove(out.c_str());
}

TEST(Program, BadOptionsFailWithMessage) {
  const std::string out = tempPath("bad");
  EXPECT_NE(waitExit(start({"--source", "tobii", "--endpoint", "tcp://127.0.0.1:1"}, out)), 0);
  EXPECT_NE(readAll(out).find("tobii_source.h"), std::string::npos);
  EXPECT_NE(waitExit(start({"--source", "replay"}, out)), 0);
  EXPECT_NE(readAll(out).find("--replay FILE"), std::string::npos);
  EXPECT_NE(waitExit(start({"--min-confidence", "2"}, out)), 0);
  EXPECT_NE(waitExit(start({"--source", "replay", "--replay", "/nonexistent.csv"}, out)), 0);
  EXPECT_NE(readAll(out).find("/nonexistent.csv"), std::string::npos);
  std::remove(out.c_str());
}

TEST(Program, ReplaysRecordingToServerAndStopsCleanlyOnSigterm) {
  gaze::GazeRecording recording;
  for (int i = 0; i < 20; ++i) recording.samples.push_back({i * 0.01, 0.05 * i, 1.0 - 0.05 * i, true});
  const std::string input = tempPath("input");
  const std::string recorded = tempPath("recorded");
  const std::string out = tempPath("log");
  gaze::writeGazeRecording(input, recording);

  zmq::context_t context;
  GazeReceiver receiver(context);
  const pid_t pid = start({"--source", "replay", "--replay", input, "--endpoint", receiver.endpoint(), "--no-filter",
                           "--record", recorded, "--stats-interval", "0.2"},
                          out);
  // Looping replay: every recorded point shows up, unchanged (as float).
  std::vector<bool> seen(recording.samples.size(), false);
  std::size_t distinct = 0;
  const auto end = std::chrono::steady_clock::now() + kWait;
  while (distinct < seen.size() && std::chrono::steady_clock::now() < end) {
    auto s = receiver.receive(200ms);
    if (!s || !s->valid()) continue;
    EXPECT_EQ(s->source_id(), "replay");
    const auto i = static_cast<std::size_t>(std::llround(std::fmod(s->tracker_time_s(), 0.2) / 0.01)) % seen.size();
    EXPECT_NEAR(s->x(), recording.samples[i].x, 1e-6) << i;
    EXPECT_NEAR(s->y(), recording.samples[i].y, 1e-6) << i;
    if (!seen[i]) ++distinct;
    seen[i] = true;
  }
  EXPECT_EQ(distinct, seen.size());
  // The statistics line comes every 0.2 s of the bridge's running time: wait for it.
  std::string log;
  const auto log_end = std::chrono::steady_clock::now() + 30s;
  while ((log = readAll(out)).find("added latency") == std::string::npos &&
         std::chrono::steady_clock::now() < log_end) {
    std::this_thread::sleep_for(20ms);
  }
  EXPECT_NE(log.find("added latency"), std::string::npos) << log;
  ::kill(pid, SIGTERM);
  EXPECT_EQ(waitExit(pid), 0);
  log = readAll(out);
  EXPECT_NE(log.find("stopped"), std::string::npos) << log;
  const auto written = gaze::readGazeRecording(recorded);  // flushed and well-formed at exit
  EXPECT_GE(written.samples.size(), 20u);
  for (const char* path : {input.c_str(), recorded.c_str(), out.c_str()}) std::remove(path);
}
