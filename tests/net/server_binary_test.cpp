// The built sph_server program: --help lists the endpoints, it serves on ephemeral ports, and SIGTERM
// (or SIGINT) shuts it down cleanly with a final status line.
#include <gtest/gtest.h>
#include <signal.h>

#include <string>
#include <utility>
#include <vector>

#include "child.h"
#include "net_test_util.h"

namespace {

using net_test::Child;
using net_test::serverArgs;

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
  // An unknown name is a usage error (exit 2), found before any scene loads; --help lists the known ones.
  EXPECT_EQ(unknown.waitExit(), 2);
  EXPECT_NE(unknown.output.find("unknown setting 'no_such' (see sph_server --help)"), std::string::npos)
      << unknown.output;
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
  EXPECT_EQ(reply->status().preset(), "pbf") << "sph_server's water is pbf unless told otherwise";
  ::kill(child.pid, signal);
  EXPECT_EQ(child.waitExit(), 0) << child.output;
  EXPECT_NE(child.output.find("shutting down"), std::string::npos) << child.output;
  EXPECT_NE(child.output.find("final status: tiny_pool pbf gaze"), std::string::npos) << child.output;
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
