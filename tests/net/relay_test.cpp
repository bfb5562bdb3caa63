// sph_relay's core on loopback: viewers connect to it as to the server and each gets every frame
// the relay forwarded; CURVE on its downstream side lets allowed keys in (a viewer's is enough) and
// nobody else; a peer that floods it with subscriptions is dropped.
#include "relay/relay.h"

#include <gtest/gtest.h>

#include <mutex>
#include <vector>

#include "net_test_util.h"
#include "test_keys.h"

namespace {

using net_test::FrameSubscriber;

struct Forwarded {
  std::mutex mutex;
  std::vector<std::uint64_t> sequences;
  void add(const zmq::message_t& message) {
    gsph::v1::Frame frame;
    if (!frame.ParseFromArray(message.data(), static_cast<int>(message.size()))) return;
    std::lock_guard lock(mutex);
    sequences.push_back(frame.sequence());
  }
  std::vector<std::uint64_t> snapshot() {
    std::lock_guard lock(mutex);
    return sequences;
  }
};

TEST(Relay, SixteenSubscribersGetEveryFrameTheRelayForwarded) {
  constexpr int kSubscribers = 16;
  constexpr std::size_t kFrames = 60;  // per subscriber, after its first
  auto options = net_test::testOptions(sph::Method::Regular);
  options.sim.settings.publish_hz = 20.0;  // slow enough that no queue on the way fills up
  auto server = net_test::startServer(options);
  Forwarded forwarded;
  relay::RelayOptions ro;
  ro.upstream = server->endpoints().frames;
  ro.downstream = "tcp://127.0.0.1:*";
  ro.hwm = 10000;
  ro.on_forward = [&](const zmq::message_t& m) { forwarded.add(m); };
  relay::Relay relay(ro);
  relay.start();

  zmq::context_t ctx;
  std::vector<std::unique_ptr<FrameSubscriber>> subs;
  for (int i = 0; i < kSubscribers; ++i) subs.push_back(std::make_unique<FrameSubscriber>(ctx, relay.downstream()));
  std::vector<std::vector<std::uint64_t>> received(kSubscribers);
  const auto receive = [&](std::chrono::milliseconds timeout) {
    std::vector<zmq::pollitem_t> items;
    for (auto& s : subs) items.push_back({s->socket().handle(), 0, ZMQ_POLLIN, 0});
    zmq::poll(items, timeout);
    for (int i = 0; i < kSubscribers; ++i) {
      if (!(items[i].revents & ZMQ_POLLIN)) continue;
      auto frame = subs[i]->next(std::chrono::milliseconds(0));
      if (frame) received[i].push_back(frame->sequence());
    }
  };
  const auto all = [&](const std::function<bool(int)>& condition) {
    const auto end = std::chrono::steady_clock::now() + net_test::kTimeout;
    for (;;) {
      bool done = true;
      for (int i = 0; i < kSubscribers; ++i) done = done && condition(i);
      if (done || std::chrono::steady_clock::now() > end) return done;
      receive(std::chrono::milliseconds(50));
    }
  };
  ASSERT_TRUE(all([&](int i) { return received[i].size() > kFrames; })) << "a subscriber got too few frames";
  server->stop();  // no more frames: each subscriber must end with the relay's last
  ASSERT_TRUE(all([&](int i) {
    const auto f = forwarded.snapshot();
    return !f.empty() && received[i].back() == f.back();
  })) << "a subscriber never got the relay's last frame";

  const std::vector<std::uint64_t> f = forwarded.snapshot();
  EXPECT_EQ(f.size(), relay.forwarded());
  for (int i = 0; i < kSubscribers; ++i) {
    // Everything the relay forwarded from this subscriber's first frame on, in order, nothing else.
    const auto first = std::find(f.begin(), f.end(), received[i].front());
    ASSERT_NE(first, f.end()) << "subscriber " << i << " got a frame the relay did not forward";
    EXPECT_EQ(std::vector<std::uint64_t>(first, f.end()), received[i]) << "subscriber " << i;
  }
  std::printf(
      "relay forwarded %zu frames; each of %d subscribers got every one from its first on (%zu-%zu each)\n", f.size(),
      kSubscribers,
      std::min_element(received.begin(), received.end(), [](auto& a, auto& b) { return a.size() < b.size(); })->size(),
      std::max_element(received.begin(), received.end(), [](auto& a, auto& b) { return a.size() < b.size(); })->size());
}

TEST(Relay, CurveOnBothSides) {
  net_test::TestKeys keys;
  auto options = net_test::testOptions(sph::Method::Regular);
  options.net.curve = keys.server;
  options.curve_clients = keys.allowed;
  auto server = net_test::startServer(options);
  relay::RelayOptions ro;
  ro.upstream = server->endpoints().frames;
  ro.upstream_curve = keys.viewer_keys;  // a viewer's key is enough for frames
  ro.downstream = "tcp://127.0.0.1:*";
  ro.curve = keys.server;  // the relay's own key pair (the same one, for the test)
  ro.clients = keys.allowed;
  relay::Relay relay(ro);
  relay.start();
  zmq::context_t ctx;
  FrameSubscriber viewer(ctx, relay.downstream(), false, 0, keys.viewer_keys);
  FrameSubscriber stranger(ctx, relay.downstream(), false, 0, keys.stranger_keys);
  FrameSubscriber plain(ctx, relay.downstream());
  ASSERT_TRUE(viewer.next()) << "an allowed key gets frames through the relay";
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(viewer.next());
  EXPECT_FALSE(stranger.next(std::chrono::milliseconds(0))) << "a stranger's key got a frame";
  EXPECT_FALSE(plain.next(std::chrono::milliseconds(0))) << "a plaintext client got a frame";
}

TEST(Relay, APeerFloodingSubscriptionsIsDropped) {
  auto server = net_test::startServer(net_test::testOptions(sph::Method::Regular));
  relay::RelayOptions ro;
  ro.upstream = server->endpoints().frames;
  ro.downstream = "tcp://127.0.0.1:*";
  relay::Relay relay(ro);
  relay.start();
  zmq::context_t ctx;
  FrameSubscriber good(ctx, relay.downstream());
  ASSERT_TRUE(good.next());
  zmq::socket_t flood(ctx, zmq::socket_type::xsub);
  flood.set(zmq::sockopt::linger, 0);
  flood.set(zmq::sockopt::sndhwm, 0);
  flood.connect(relay.downstream());
  for (int i = 0; i < 2000; ++i) {
    std::string topic(901, 't');
    topic[0] = '\x01';
    std::memcpy(&topic[1], &i, sizeof i);
    (void)flood.send(zmq::buffer(topic), zmq::send_flags::dontwait);
  }
  const auto end = std::chrono::steady_clock::now() + net_test::kTimeout;
  while (relay.peersDropped() == 0 && std::chrono::steady_clock::now() < end) good.next(std::chrono::milliseconds(50));
  EXPECT_GE(relay.peersDropped(), 1u);
  const auto before = good.next();
  ASSERT_TRUE(before);
  EXPECT_TRUE(good.waitFor([&](const gsph::v1::Frame& f) { return f.sequence() > before->sequence() + 5; }));
}

}  // namespace
