// sph_server --save-state / --load-state as a user runs them: 20 free-run steps and a checkpoint
// equal 10 steps, a checkpoint, and 10 more from it, byte for byte (the regular method takes no
// gaze, so a free run is deterministic); a checkpoint of another preset is refused with exit 1.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "support/server_args.h"
#include "viewer/child_process.h"

namespace {

std::string scratch(const std::string& name) {
  return ::testing::TempDir() + "sph_server_ckpt_" + name + "_" + std::to_string(::getpid());
}

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs sph_server on tiny_pool to the end of `steps` and returns its exit code (-1: it hung).
int runServer(const std::string& name, std::vector<std::string> extra) {
  std::vector<std::string> args = sph_test::tinyPoolServerArgs(SPH_SERVER_BINARY, SPH_NET_TEST_SCENE_DIR);
  const auto method = std::find(args.begin(), args.end(), "--method");
  if (method != args.end()) *(method + 1) = "regular";
  for (const char* option : {"--frames-endpoint", "--gaze-endpoint", "--pose-endpoint", "--control-endpoint"}) {
    args.insert(args.end(), {option, "tcp://127.0.0.1:*"});
  }
  args.insert(args.end(), {"--free-run", "--status-interval", "0"});
  args.insert(args.end(), extra.begin(), extra.end());
  viewer_test::ChildProcess server(args, scratch(name) + ".log");
  const auto code = server.waitExit(std::chrono::minutes(3));
  return code ? *code : -1;
}

TEST(ServerCheckpoint, RestartedRunEqualsTheUninterruptedOneByteForByte) {
  const std::string whole = scratch("whole.ckpt"), half = scratch("half.ckpt"), resumed = scratch("resumed.ckpt");
  ASSERT_EQ(runServer("whole", {"--max-steps", "20", "--save-state", whole}), 0) << bytesOf(scratch("whole") + ".log");
  ASSERT_EQ(runServer("half", {"--max-steps", "10", "--save-state", half}), 0);
  ASSERT_EQ(runServer("resumed", {"--max-steps", "10", "--load-state", half, "--save-state", resumed}), 0)
      << bytesOf(scratch("resumed") + ".log");
  EXPECT_NE(bytesOf(scratch("resumed") + ".log").find("continuing from"), std::string::npos);
  const std::string expected = bytesOf(whole);
  ASSERT_GT(expected.size(), 1000u);
  EXPECT_TRUE(expected == bytesOf(resumed)) << "the continued run's state differs from the uninterrupted run's";
  EXPECT_FALSE(expected == bytesOf(half));

  // Another preset cannot continue it: a clear error, exit 1, nothing written.
  const std::string refused = scratch("refused.ckpt");
  EXPECT_EQ(
      runServer("refused", {"--preset", "dfsph", "--max-steps", "5", "--load-state", half, "--save-state", refused}),
      1);
  EXPECT_NE(bytesOf(scratch("refused") + ".log").find("saved with preset 'pbf', this run uses 'dfsph'"),
            std::string::npos)
      << bytesOf(scratch("refused") + ".log");
  EXPECT_FALSE(std::filesystem::exists(refused));
  for (const auto& f : {whole, half, resumed}) std::filesystem::remove(f);
}

}  // namespace
