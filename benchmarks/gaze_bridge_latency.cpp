// Benchmark (not a test): the bridge's added latency at 200 Hz input, per real protocol.
//   gaze_bridge_latency_bench [seconds per protocol, default 10]
// For each sample: "in bridge" = bridge read the tracker bytes -> GazeSample handed to ZeroMQ (the
// bridge's own cost), and "tracker write -> server read" = the emulated tracker's write -> the test's
// SUB socket has the message (adds both loopback hops and the ZeroMQ I/O thread).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <thread>

#include <spdlog/spdlog.h>
#include "bridge.h"
#include "bridge_harness.h"
#include "emulators.h"
#include "gazepoint_source.h"
#include "pupil_source.h"

using namespace gaze_bridge_test;
using namespace std::chrono_literals;
using gaze_bridge::steadyNowNs;

namespace {

constexpr double kRateHz = 200.0;

void report(const char* what, std::vector<std::int64_t> ns) {
  if (ns.empty()) {
    std::printf("  %-32s no samples\n", what);
    return;
  }
  std::sort(ns.begin(), ns.end());
  const auto at = [&](double p) {
    return static_cast<double>(ns[std::min(ns.size() - 1, static_cast<std::size_t>(p * ns.size()))]) * 1e-3;
  };
  std::printf("  %-32s n=%zu  p50 %.0f us  p99 %.0f us  max %.0f us\n", what, ns.size(), at(0.5), at(0.99),
              static_cast<double>(ns.back()) * 1e-3);
}

// Drives `emit(k)` at 200 Hz for `seconds`, collecting the receive side; returns end-to-end latencies.
template <typename Emit>
std::vector<std::int64_t> drive(GazeReceiver& receiver, double seconds, Emit emit) {
  std::map<long, std::int64_t> sent_at;  // sample id (tracker time in ms) -> write time
  std::vector<std::int64_t> latencies;
  const std::int64_t period = static_cast<std::int64_t>(1e9 / kRateHz);
  const std::int64_t start = steadyNowNs() + 500'000'000;  // 0.5 s of warm-up before counting
  long k = 0;
  for (std::int64_t next = steadyNowNs(); next < start + static_cast<std::int64_t>(seconds * 1e9);
       next += period, ++k) {
    // Receive until the next write is due.
    while (true) {
      const std::int64_t wait = next - steadyNowNs();
      if (wait <= 0) break;
      auto s = receiver.receive(std::chrono::milliseconds(std::max<std::int64_t>(wait / 1'000'000, 0)));
      const std::int64_t now = steadyNowNs();
      if (s && s->valid()) {
        const long id = std::lround(s->tracker_time_s() * 1000.0);
        auto it = sent_at.find(id);
        if (it != sent_at.end()) {
          if (it->second >= start) latencies.push_back(now - it->second);
          sent_at.erase(it);
        }
      }
    }
    sent_at[k] = steadyNowNs();
    emit(k);
  }
  return latencies;
}

struct RunningBridge {
  RunningBridge(zmq::context_t& context, std::unique_ptr<gaze_bridge::GazeSource> source, const std::string& endpoint)
      : params(makeParams(endpoint)), bridge(context, std::move(source), params) {
    bridge.setLatencyLog(&in_bridge);
    thread = std::thread([this] { bridge.run(stop); });
  }
  ~RunningBridge() { finish(); }
  void finish() {
    stop = true;
    if (thread.joinable()) thread.join();
  }
  static gaze_bridge::BridgeParams makeParams(const std::string& endpoint) {
    gaze_bridge::BridgeParams p;  // default processing: One Euro filter on
    p.publisher.endpoint = endpoint;
    p.stats_interval_s = 1e6;
    return p;
  }
  gaze_bridge::BridgeParams params;
  std::vector<std::int64_t> in_bridge;
  std::atomic<bool> stop{false};
  gaze_bridge::GazeBridge bridge;
  std::thread thread;
};

void benchGazepoint(double seconds) {
  // A minimal Open Gaze server in this thread: ACK the three SETs, then write one REC per tick.
  const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address);
  ::listen(listener, 1);
  socklen_t length = sizeof address;
  ::getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length);
  zmq::context_t context;
  GazeReceiver receiver(context);
  gaze_bridge::GazepointParams params;
  params.port = ntohs(address.sin_port);
  RunningBridge bridge(context, std::make_unique<gaze_bridge::GazepointSource>(params), receiver.endpoint());
  const int client = ::accept(listener, nullptr, nullptr);
  const int one = 1;
  ::setsockopt(client, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  std::string inbox;
  for (int acked = 0; acked < 3;) {
    char buffer[512];
    const ssize_t n = ::recv(client, buffer, sizeof buffer, 0);
    if (n <= 0) return;
    inbox.append(buffer, static_cast<std::size_t>(n));
    for (std::size_t end; (end = inbox.find("\r\n")) != std::string::npos; ++acked) {
      const std::string ack = "<ACK" + inbox.substr(4, end - 4) + "\r\n";
      ::send(client, ack.data(), ack.size(), MSG_NOSIGNAL);
      inbox.erase(0, end + 2);
    }
  }
  auto e2e = drive(receiver, seconds, [&](long k) {
    const double x = 0.3 + 0.0005 * static_cast<double>(k % 200);
    const std::string record = gazepointRecord(static_cast<double>(k) * 1e-3, x, 0.5, true);
    ::send(client, record.data(), record.size(), MSG_NOSIGNAL);
  });
  bridge.finish();
  ::close(client);
  ::close(listener);
  std::printf("gazepoint (TCP, one REC per write) at %.0f Hz:\n", kRateHz);
  report("in bridge (read -> send)", bridge.in_bridge);
  report("tracker write -> server read", e2e);
}

void benchPupil(double seconds) {
  zmq::context_t context;
  PupilEmulator pupil(context);
  GazeReceiver receiver(context);
  gaze_bridge::PupilParams params;
  params.remote_port = pupil.remotePort();
  RunningBridge bridge(context, std::make_unique<gaze_bridge::PupilSource>(context, params), receiver.endpoint());
  auto e2e = drive(receiver, seconds, [&](long k) {
    const double x = 0.3 + 0.0005 * static_cast<double>(k % 200);
    pupil.publish("surfaces.screen",
                  packSurfaceMessage("screen", {{x, 0.5, 0.99, true, static_cast<double>(k) * 1e-3}}));
  });
  bridge.finish();
  std::printf("pupil (ZeroMQ SUB, msgpack, one sample per message) at %.0f Hz:\n", kRateHz);
  report("in bridge (read -> send)", bridge.in_bridge);
  report("tracker write -> server read", e2e);
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 10.0;
  spdlog::set_level(spdlog::level::warn);
  benchGazepoint(seconds);
  benchPupil(seconds);
  return 0;
}
