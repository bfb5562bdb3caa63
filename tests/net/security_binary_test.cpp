// The built programs' side of the security rules (docs/security.md): sph_keygen's files (read by
// this code and by pyzmq), the server's refusal to bind beyond loopback without CURVE or --insecure,
// CURVE from key files, and a descriptor limit the server raises, caps its peers by and reports.
#include <gtest/gtest.h>

#include <filesystem>

#include "child.h"
#include "net/curve_keys.h"
#include "net_test_util.h"
#include "temp_dir.h"

namespace {

namespace fs = std::filesystem;
using net_test::Child;
using net_test::serverArgs;

struct KeyDir : net_test::TempDir {
  KeyDir() : TempDir("sph-keygen") {}
  // Runs sph_keygen; true when it succeeded.
  bool make(const std::string& name, const std::string& role, const std::string& where) const {
    Child keygen({SPH_KEYGEN_BINARY, name, "--role", role, "--out", where});
    return keygen.waitExit() == 0;
  }
};

TEST(SphKeygen, WritesFilesThisCodeAndPyzmqRead) {
  KeyDir dir;
  ASSERT_TRUE(dir.make("viewer1", "viewer", dir.path.string()));
  const curve::Certificate secret = curve::readCertificate(dir / "viewer1.key_secret", true);
  EXPECT_EQ(curve::readCertificate(dir / "viewer1.key").public_key, secret.public_key);
  EXPECT_EQ(secret.metadata.at("role"), "viewer");
  Child again({SPH_KEYGEN_BINARY, "viewer1", "--out", dir.path.string()});
  EXPECT_EQ(again.waitExit(), 1) << "overwrote a key";
  EXPECT_NE(again.output.find("already exists"), std::string::npos) << again.output;
  Child bad_role({SPH_KEYGEN_BINARY, "x", "--role", "admin", "--out", dir.path.string()});
  EXPECT_NE(bad_role.waitExit(), 0);

  // The Python client (pyzmq, Debian's python3-zmq) loads the same files.
  const std::string script =
      "import zmq.auth\n"
      "p, s = zmq.auth.load_certificate('" +
      dir / "viewer1.key_secret" +
      "')\n"
      "q, t = zmq.auth.load_certificate('" +
      dir / "viewer1.key" +
      "')\n"
      "print('keys', p.decode(), s.decode(), q.decode(), t)\n";
  Child python({"/usr/bin/python3", "-c", script});
  ASSERT_EQ(python.waitExit(), 0) << python.output;
  EXPECT_NE(
      python.output.find("keys " + secret.public_key + " " + secret.secret_key + " " + secret.public_key + " None"),
      std::string::npos)
      << python.output;
}

TEST(ServerBinary, BindingBeyondLoopbackNeedsCurveOrInsecure) {
  auto args = serverArgs();
  args[10] = "tcp://lo:*";  // an interface name: not known to be loopback-only, so it counts as beyond
  Child refused(args);
  EXPECT_EQ(refused.waitExit(), 2);
  EXPECT_NE(refused.output.find("needs CURVE: --curve-secret"), std::string::npos) << refused.output;

  args.push_back("--insecure");
  Child insecure(args);
  const std::string control = insecure.waitForWordAfter("endpoint control ");
  ASSERT_FALSE(control.empty()) << insecure.output;
  EXPECT_EQ(insecure.waitForWordAfter("INSECURE: "), "bound") << insecure.output;
  zmq::context_t ctx;
  net_test::ControlClient client(ctx, control);
  auto status = client.send(net_test::statusRequest());
  ASSERT_TRUE(status);
  EXPECT_TRUE(status->status().insecure());
}

TEST(ServerBinary, ServesCurveClientsFromKeyFiles) {
  KeyDir dir;
  fs::create_directory(dir.path / "clients");
  ASSERT_TRUE(dir.make("server", "server", dir.path.string()));
  ASSERT_TRUE(dir.make("op", "operator", dir / "clients"));
  auto args = serverArgs();
  args.insert(args.end(), {"--curve-secret", dir / "server.key_secret", "--curve-clients", dir / "clients"});
  Child server(args);
  const std::string control = server.waitForWordAfter("endpoint control ");
  ASSERT_FALSE(control.empty()) << server.output;
  // Logged after the endpoints: wait for the line rather than expect it in what has been read so far.
  EXPECT_EQ(server.waitForWordAfter("CURVE on every socket: "), "1") << server.output;
  zmq::context_t ctx;
  const curve::Certificate op = curve::readCertificate(dir / "clients/op.key_secret", true);
  const curve::ClientKeys keys{op.public_key, op.secret_key, curve::readCertificate(dir / "server.key").public_key};
  net_test::ControlClient client(ctx, control, keys);
  auto status = client.send(net_test::statusRequest());
  ASSERT_TRUE(status);
  EXPECT_EQ(status->status().client_role(), "operator");

  auto bad = serverArgs();
  bad.insert(bad.end(), {"--curve-secret", dir / "server.key", "--curve-clients", dir / "clients"});
  Child wrong_file(bad);
  EXPECT_EQ(wrong_file.waitExit(), 1) << "a public certificate as the server's secret";
  EXPECT_NE(wrong_file.output.find("secret-key"), std::string::npos) << wrong_file.output;
}

// Without a cap, idle connections that used up the descriptor limit left new peers unserved, with nothing logged.
// Under a low limit the server raises its soft limit to the hard one, divides what is left among
// its sockets, drops idle connections beyond that (saying so), and keeps serving.
TEST(ServerBinary, ALowDescriptorLimitCapsPeersAndTheServerKeepsServing) {
  Child server(serverArgs(), {}, std::make_pair(rlim_t{96}, rlim_t{128}));
  const std::string control = server.waitForWordAfter("endpoint control ");
  ASSERT_FALSE(control.empty()) << server.output;
  ASSERT_FALSE(server.waitForWordAfter("up to ").empty());
  EXPECT_NE(server.output.find("file descriptors: limit 128 (was 96), up to 16 peers per socket"), std::string::npos)
      << server.output;
  std::vector<int> idle;
  for (int i = 0; i < 60; ++i) idle.push_back(net_test::idleTcpConnection(control));
  EXPECT_EQ(server.waitForWordAfter("connection(s) on the control socket: it has "), "16") << server.output;
  // A real client gets in (an idle connection makes way for it once it is a second old) and is answered.
  zmq::context_t ctx;
  net_test::ControlClient client(ctx, control);
  auto status = client.sendUntilAnswered(net_test::statusRequest());
  ASSERT_TRUE(status) << server.output;
  EXPECT_TRUE(status->ok());
  for (int fd : idle) ::close(fd);
}

}  // namespace

namespace {

TEST(RelayBinary, ForwardsFramesAndBindsLoopbackUnlessToldOtherwise) {
  auto server = net_test::startServer(net_test::testOptions(sph::Method::Regular));
  Child refused({SPH_RELAY_BINARY, "--upstream", server->endpoints().frames, "--endpoint", "tcp://lo:*"});
  EXPECT_EQ(refused.waitExit(), 2);
  EXPECT_NE(refused.output.find("needs CURVE"), std::string::npos) << refused.output;

  Child relay({SPH_RELAY_BINARY, "--upstream", server->endpoints().frames, "--endpoint", "tcp://127.0.0.1:*"});
  const std::string endpoint = relay.waitForWordAfter("endpoint relay ");
  ASSERT_EQ(endpoint.rfind("tcp://127.0.0.1:", 0), 0u) << relay.output;
  zmq::context_t ctx;
  net_test::FrameSubscriber viewer(ctx, endpoint);
  auto frame = viewer.next();
  ASSERT_TRUE(frame) << relay.output;
  EXPECT_EQ(frame->scene(), "tiny_pool");
  ::kill(relay.pid, SIGTERM);
  EXPECT_EQ(relay.waitExit(), 0) << relay.output;
  EXPECT_NE(relay.output.find("final status: "), std::string::npos) << relay.output;
}

}  // namespace
