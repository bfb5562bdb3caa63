// What a misbehaving client can no longer do: stop the frames with a tiny publish_hz,
// grow the log with refused requests, grow memory with subscriptions, or use up the descriptors.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <limits>
#include <vector>

#include "log_capture.h"
#include "net/peer_text.h"
#include "net_test_util.h"

namespace {

using net_test::ControlClient;
using net_test::FrameSubscriber;

gsph::v1::Control setParameter(const std::string& name, double value) {
  gsph::v1::Control c;
  (*c.mutable_set_parameters()->mutable_values())[name] = value;
  return c;
}

bool waitUntil(const std::function<bool()>& condition) {
  const auto end = std::chrono::steady_clock::now() + net_test::kTimeout;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

TEST(ServerLimits, PublishHzHasOneRangeAndANewRateAppliesAtOnce) {
  auto server = net_test::startServer(net_test::testOptions(sph::Method::Regular));
  zmq::context_t ctx;
  ControlClient client(ctx, server->endpoints().control);
  FrameSubscriber sub(ctx, server->endpoints().frames);
  auto last = sub.next();
  ASSERT_TRUE(last) << "subscribed before the rate changes";
  for (double bad : {1e-9, 1e-300, 0.0, -1.0, 1000.5, std::numeric_limits<double>::infinity()}) {
    auto reply = client.send(setParameter("publish_hz", bad));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->error_code(), gsph::v1::ERROR_CODE_BAD_PARAMETER) << bad;
    EXPECT_NE(reply->error().find("publish_hz"), std::string::npos) << reply->error();
    EXPECT_DOUBLE_EQ(reply->status().parameters().at("publish_hz"), 60.0) << bad;
  }
  // The slowest rate there is (a frame every 1000 s), then 60 again: frames come back at once, not
  // after the 1000 s the old deadline said.
  ASSERT_TRUE(client.send(setParameter("publish_hz", app::kMinPublishHz))->ok());
  while (auto more = sub.next(std::chrono::milliseconds(200))) last = more;  // what was queued before
  ASSERT_TRUE(client.send(setParameter("publish_hz", 60.0))->ok());
  const std::uint64_t seen = last->sequence();
  EXPECT_TRUE(sub.waitFor([&](const gsph::v1::Frame& f) { return f.sequence() > seen + 5; }));
}

TEST(ServerLimits, RefusedRequestsLogALineAnIntervalAndEchoLittle) {
  net_test::LogCapture log;
  auto options = net_test::testOptions(sph::Method::Regular);
  options.sim.log_interval = std::chrono::hours(1);  // the first refusal logs, later ones only count
  auto server = net_test::startServer(options);
  zmq::context_t ctx;
  ControlClient client(ctx, server->endpoints().control);
  const std::string huge(60000, 'x');
  for (int i = 0; i < 100; ++i) {
    gsph::v1::Control load;
    load.mutable_load_scene()->set_scene(huge + std::to_string(i));
    auto reply = client.send(load);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->error_code(), gsph::v1::ERROR_CODE_UNKNOWN_SCENE);
    EXPECT_LE(reply->error().size(), net::kMaxErrorBytes);
    EXPECT_NE(reply->error().find("(600"), std::string::npos) << "the echo says how long the name was";
    auto bad = client.send(setParameter(huge, 1.0));
    ASSERT_TRUE(bad);
    EXPECT_EQ(bad->error_code(), gsph::v1::ERROR_CODE_BAD_PARAMETER);
    EXPECT_NE(bad->error().find("unknown parameter 'xxxx"), std::string::npos) << "the parameter is named";
    EXPECT_LE(bad->error().size(), net::kMaxErrorBytes);
    (void)client.sendRaw("\xff garbage");  // rejected input: its own rate-limited line
  }
  EXPECT_EQ(client.send(net_test::statusRequest())->status().scene(), "tiny_pool") << "nothing changed";
  EXPECT_EQ(log.lines("refused"), 1) << log.text().substr(0, 2000);
  EXPECT_EQ(log.lines("rejected"), 1) << log.text().substr(0, 2000);
  EXPECT_LT(log.text().size(), 4096u) << "300 refusals of 60 kB requests grew the log";
}

TEST(ServerLimits, SubscriptionFloodDropsItsSenderAndTheCountStaysHonest) {
  auto server = net_test::startServer(net_test::testOptions(sph::Method::Regular));
  const net::Endpoints& ep = server->endpoints();
  zmq::context_t ctx;
  FrameSubscriber good(ctx, ep.frames);
  ASSERT_TRUE(good.next());
  zmq::socket_t flood(ctx, zmq::socket_type::xsub);
  flood.set(zmq::sockopt::linger, 0);
  flood.set(zmq::sockopt::sndhwm, 0);
  flood.connect(ep.frames);
  // 3,000 distinct 900-byte topics (under the 1 KiB size limit): 2.7 MB the old server kept in its
  // trie at ~50 bytes a byte, for as long as the peer stayed.
  for (int i = 0; i < 3000; ++i) {
    std::string topic(901, static_cast<char>('a' + i % 26));
    topic[0] = '\x01';
    std::memcpy(&topic[1], &i, sizeof i);
    (void)flood.send(zmq::buffer(topic), zmq::send_flags::dontwait);
  }
  EXPECT_TRUE(waitUntil([&] { return server->netCounters().peers_dropped.load() >= 1; }))
      << "the peer holding refused subscriptions was not dropped";
  EXPECT_GT(server->rejections().count(net::InputSocket::Subscriptions), 0u);
  flood.close();
  ControlClient client(ctx, ep.control);
  EXPECT_TRUE(waitUntil([&] { return client.send(net_test::statusRequest())->status().subscribers() == 1; }))
      << "the topics were counted as subscribers";
  const auto before = good.next();
  ASSERT_TRUE(before);
  EXPECT_TRUE(good.waitFor([&](const gsph::v1::Frame& f) { return f.sequence() > before->sequence() + 5; }));
}

TEST(ServerLimits, APeerSubscribingTwiceIsOneSubscriber) {
  auto server = net_test::startServer(net_test::testOptions(sph::Method::Regular));
  zmq::context_t ctx;
  FrameSubscriber good(ctx, server->endpoints().frames);
  ASSERT_TRUE(good.next());
  auto twice = std::make_unique<zmq::socket_t>(ctx, zmq::socket_type::xsub);
  twice->set(zmq::sockopt::linger, 0);
  twice->connect(server->endpoints().frames);
  for (const char* m : {"\x01", "\x01", "\x01topic"}) twice->send(zmq::buffer(std::string(m)), zmq::send_flags::none);
  ControlClient client(ctx, server->endpoints().control);
  const auto subscribers = [&] { return client.send(net_test::statusRequest())->status().subscribers(); };
  EXPECT_TRUE(waitUntil([&] { return server->rejections().count(net::InputSocket::Subscriptions) == 1; }));
  EXPECT_TRUE(waitUntil([&] { return subscribers() == 2; })) << subscribers();
  twice.reset();
  EXPECT_TRUE(waitUntil([&] { return subscribers() == 1; })) << subscribers();
}

TEST(ServerLimits, ConnectionsBeyondASocketsLimitAreDropped) {
  auto options = net_test::testOptions(sph::Method::Regular);
  options.net.max_peers = 3;
  auto server = net_test::startServer(options);
  std::vector<int> idle;
  for (int i = 0; i < 10; ++i) idle.push_back(net_test::idleTcpConnection(server->endpoints().control));
  EXPECT_TRUE(waitUntil([&] { return server->netCounters().peers_dropped.load() >= 7; }));
  // A client still gets in: a full socket drops a connection that never sent a greeting for it (one
  // a second old). Until then the client's own connection may be the one dropped, and its request
  // with it, so it asks again.
  zmq::context_t ctx;
  ControlClient client(ctx, server->endpoints().control);
  auto status = client.sendUntilAnswered(net_test::statusRequest());
  ASSERT_TRUE(status);
  EXPECT_TRUE(status->ok());
  for (int fd : idle) ::close(fd);
}

int openDescriptors() {
  int n = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator("/proc/self/fd")) ++n;
  return n;
}

TEST(ServerLimits, RunningOutOfDescriptorsIsLogged) {
  net_test::LogCapture log;
  auto options = net_test::testOptions(sph::Method::Regular);
  options.net.max_peers = 10000;  // no cap: let the descriptors run out
  auto server = net_test::startServer(options);
  zmq::context_t ctx;
  FrameSubscriber sub(ctx, server->endpoints().frames);
  ASSERT_TRUE(sub.next());
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_NOFILE, &saved), 0);
  rlimit low = saved;
  low.rlim_cur = static_cast<rlim_t>(openDescriptors() + 20);
  ASSERT_EQ(::setrlimit(RLIMIT_NOFILE, &low), 0);
  // This process and the server share the limit. Take every descriptor it leaves (ballast that no
  // one else closes), then give one back for a connection: the connection is made in the kernel,
  // and the server's accept of it finds no descriptor. (Connecting until none was left raced the
  // server: when its accept took the last descriptor, nothing was left pending to fail, and the
  // test failed once in CI.)
  std::vector<int> ballast;
  for (int fd; ballast.size() < 200 && (fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC)) >= 0;) ballast.push_back(fd);
  ASSERT_FALSE(ballast.empty());
  ::close(ballast.back());
  ballast.pop_back();
  const int connection = net_test::idleTcpConnection(server->endpoints().control);
  const bool logged = waitUntil([&] { return server->netCounters().accept_failures.load() > 0; });
  if (connection >= 0) ::close(connection);
  for (int fd : ballast) ::close(fd);
  ASSERT_EQ(::setrlimit(RLIMIT_NOFILE, &saved), 0);
  EXPECT_GE(connection, 0) << "the descriptor given back was taken before the connection";
  EXPECT_TRUE(logged) << "no accept failure seen";
  EXPECT_GE(log.lines("could not be accepted on the control socket: Too many open files"), 1) << log.text();
  EXPECT_LE(log.lines("could not be accepted"), 3) << "one line a second, not one a failure";
  // Descriptors back: the server serves again.
  ControlClient client(ctx, server->endpoints().control);
  auto status = client.send(net_test::statusRequest());
  ASSERT_TRUE(status);
  EXPECT_TRUE(status->ok());
}

}  // namespace
