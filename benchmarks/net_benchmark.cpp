// Benchmarks of sph_server's network path (aims: docs/design.md section 8). Figures, not tests:
//   EncodePublish/<encoding>: encode a 20,000-particle frame and publish it on an XPUB with one
//     reading subscriber (target <= 1 ms).
//   GazeToRefinedFrame/<scene>: real-time server (gaze method, 60 frames/s; dambreak, then a
//     1,000-particle pool); a client sends a gaze sample and times until the first frame whose
//     adaptive step used it (p50, p99; target p99 <= 12 ms), and counts the frames it
//     received per second meanwhile (the early frames for new gaze must not raise it much).
//   StepRate/<subscribers>: free-run regular dambreak (20,000 L0) with 0 or 8 subscribers reading
//     every frame at 60 frames/s (target: 8 cost <= 5 %).
// Run: build/bin/sph_net_benchmark [--benchmark_repetitions=3]
#include <benchmark/benchmark.h>
#include <omp.h>

#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "app/server.h"
#include "net/frame_encoder.h"
#include "scene/scene_loader.h"

namespace {

constexpr int kThreads = 2;

// Arg 0: the dambreak scene (10,000 L1); arg 1: the 1,000-particle test pool, where the step is
// cheap and the figure shows the network path's own share.
app::ServerOptions benchOptions(sph::Method method, int scene = 0) {
  app::ServerOptions o;
  o.net.endpoints = {"tcp://127.0.0.1:*", "tcp://127.0.0.1:*", "tcp://127.0.0.1:*", "tcp://127.0.0.1:*"};
  o.sim.scene = scene == 0 ? "dambreak" : "tiny_pool";
  o.sim.scene_dir = scene == 0 ? scene::defaultSceneDir() : SPH_NET_TEST_SCENE_DIR;
  o.sim.method = method;
  // The small pool's step is too short to share: two OpenMP threads would only add barrier waits
  // on a loaded machine.
  o.sim.threads = scene == 0 ? kThreads : 1;
  o.sim.status_interval_s = 0.0;
  o.sim.settings.publish_hz = 60.0;
  return o;
}

std::int64_t nowUs() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// CPU seconds used so far by this process's threads whose name starts with `prefix` (Linux /proc).
double threadCpuSeconds(const std::string& prefix) {
  double total = 0.0;
  const long ticks = sysconf(_SC_CLK_TCK);
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream comm(task.path() / "comm");
    std::string name;
    std::getline(comm, name);
    if (name.rfind(prefix, 0) != 0) continue;
    std::ifstream stat(task.path() / "stat");
    std::string line;
    std::getline(stat, line);
    // Fields after the parenthesised name: state is field 3, utime 14, stime 15.
    std::istringstream rest(line.substr(line.rfind(')') + 2));
    std::string field;
    double utime = 0, stime = 0;
    for (int i = 3; i <= 15 && rest >> field; ++i) {
      if (i == 14) utime = std::stod(field);
      if (i == 15) stime = std::stod(field);
    }
    total += (utime + stime) / ticks;
  }
  return total;
}

// Subscribers that read and discard every frame on one thread until stopped.
class Readers {
 public:
  Readers(zmq::context_t& ctx, const std::string& endpoint, int count) {
    for (int i = 0; i < count; ++i) {
      sockets_.emplace_back(ctx, zmq::socket_type::sub);
      sockets_.back().set(zmq::sockopt::linger, 0);
      sockets_.back().set(zmq::sockopt::subscribe, "");
      sockets_.back().connect(endpoint);
    }
    if (count > 0) {
      thread_ = std::thread([this] {
        pthread_setname_np(pthread_self(), "bench-readers");
        run();
      });
    }
  }
  ~Readers() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  std::uint64_t received() const { return received_.load(); }

 private:
  void run() {
    std::vector<zmq::pollitem_t> items;
    for (auto& s : sockets_) items.push_back({s.handle(), 0, ZMQ_POLLIN, 0});
    zmq::message_t msg;
    while (!stop_) {
      zmq::poll(items, std::chrono::milliseconds(50));
      for (std::size_t i = 0; i < items.size(); ++i) {
        while (sockets_[i].recv(msg, zmq::recv_flags::dontwait)) received_.fetch_add(1);
      }
    }
  }
  std::vector<zmq::socket_t> sockets_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> received_{0};
  std::thread thread_;
};

void EncodePublish(benchmark::State& state) {
  omp_set_num_threads(kThreads);
  sph::Simulation sim(scene::loadScene("dambreak"), sph::Level{0});
  for (int i = 0; i < 5; ++i) sim.step();
  net::FrameEncoder encoder(state.range(0) == 0 ? net::PositionEncoding::Float32 : net::PositionEncoding::Quantized16);
  zmq::context_t ctx;
  zmq::socket_t pub(ctx, zmq::socket_type::xpub);
  pub.set(zmq::sockopt::linger, 0);
  pub.set(zmq::sockopt::sndhwm, 4);
  pub.bind("tcp://127.0.0.1:*");
  Readers reader(ctx, pub.get(zmq::sockopt::last_endpoint), 1);
  zmq::message_t subscription;
  (void)pub.recv(subscription);  // wait until the reader has joined
  net::FrameInfo info;
  info.scene = "dambreak";
  std::size_t bytes = 0;
  for (auto _ : state) {
    ++info.sequence;
    encoder.encode(sim, info);
    zmq::message_t msg = encoder.serialize();
    bytes = msg.size();
    benchmark::DoNotOptimize(pub.send(msg, zmq::send_flags::dontwait));
  }
  state.counters["frame_bytes"] = static_cast<double>(bytes);
  state.counters["particles"] = static_cast<double>(sim.particles().size());
  state.SetLabel(state.range(0) == 0 ? "float32" : "quantized16");
}
BENCHMARK(EncodePublish)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void GazeToRefinedFrame(benchmark::State& state) {
  constexpr int kSamples = 300;
  auto server = std::make_unique<app::Server>(benchOptions(sph::Method::Gaze, static_cast<int>(state.range(0))));
  server->start();
  zmq::context_t ctx;
  zmq::socket_t sub(ctx, zmq::socket_type::sub);
  sub.set(zmq::sockopt::linger, 0);
  sub.set(zmq::sockopt::subscribe, "");
  sub.connect(server->endpoints().frames);
  zmq::socket_t gaze(ctx, zmq::socket_type::pub);
  gaze.set(zmq::sockopt::linger, 0);
  gaze.connect(server->endpoints().gaze);
  std::mt19937 rng(7);
  std::vector<double> latencies_ms;
  std::uint64_t sequence = 0;
  gsph::v1::Frame frame;
  zmq::message_t msg;
  std::uint64_t frames_received = 0;
  const auto receive = [&](int timeout_ms) {
    zmq::pollitem_t item{sub.handle(), 0, ZMQ_POLLIN, 0};
    if (zmq::poll(&item, 1, std::chrono::milliseconds(timeout_ms)) <= 0) return false;
    const bool got = sub.recv(msg).has_value() && frame.ParseFromArray(msg.data(), static_cast<int>(msg.size()));
    frames_received += got;
    return got;
  };
  std::chrono::steady_clock::time_point measured_from{};
  for (auto _ : state) {
    latencies_ms.clear();
    for (int k = -20; k < kSamples; ++k) {  // the first 20 warm up the PUB/SUB links
      if (k == 0) {
        frames_received = 0;
        measured_from = std::chrono::steady_clock::now();
      }
      gsph::v1::GazeSample g;
      g.set_protocol_version(1);
      g.set_source_id("bench");
      g.set_sequence(++sequence);
      g.set_x(sequence % 2 ? 0.3f : 0.7f);
      g.set_y(0.5f);
      g.set_valid(true);
      g.set_confidence(1.0f);
      g.set_bridge_time_us(nowUs());
      const auto sent = std::chrono::steady_clock::now();
      gaze.send(zmq::buffer(g.SerializeAsString()), zmq::send_flags::none);
      bool seen = false;
      // Refined by it: the step used this sample's point (tracking, or holding it when the step
      // came later than gaze_stale_s after its arrival).
      while (!seen && std::chrono::steady_clock::now() - sent < std::chrono::seconds(1)) {
        seen =
            receive(200) && frame.gaze().sample_sequence() >= sequence &&
            (frame.gaze().mode() == gsph::v1::GAZE_MODE_TRACKING || frame.gaze().mode() == gsph::v1::GAZE_MODE_HOLDING);
      }
      if (seen && k >= 0) {
        latencies_ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - sent).count());
      }
      // A random phase against the step and frame clocks, as a tracker's samples have.
      const auto pause = std::chrono::milliseconds(5 + rng() % 30);
      const auto until = std::chrono::steady_clock::now() + pause;
      while (std::chrono::steady_clock::now() < until) receive(1);
    }
  }
  std::sort(latencies_ms.begin(), latencies_ms.end());
  const auto pct = [&](double p) {
    return latencies_ms.empty() ? -1.0 : latencies_ms[static_cast<std::size_t>(p * (latencies_ms.size() - 1))];
  };
  state.counters["p50_ms"] = pct(0.50);
  state.counters["p99_ms"] = pct(0.99);
  state.counters["max_ms"] = pct(1.0);
  state.counters["samples"] = static_cast<double>(latencies_ms.size());
  state.counters["frames_per_s"] =
      frames_received / std::chrono::duration<double>(std::chrono::steady_clock::now() - measured_from).count();
  state.counters["steps_per_s"] = server->simCounters().steps_per_second.load();
  state.SetLabel(state.range(0) == 0 ? "dambreak" : "tiny_pool");
  server->stop();
}
BENCHMARK(GazeToRefinedFrame)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void StepRate(benchmark::State& state) {
  const int subscribers = static_cast<int>(state.range(0));
  auto options = benchOptions(sph::Method::Regular);
  options.sim.settings.free_run = true;
  auto server = std::make_unique<app::Server>(options);
  zmq::context_t ctx;
  Readers readers(ctx, server->endpoints().frames, subscribers);
  const auto join_end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (server->netCounters().subscriptions.load() < subscribers && std::chrono::steady_clock::now() < join_end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  server->start();
  std::this_thread::sleep_for(std::chrono::seconds(1));  // past the first steps' page faults
  double seconds = 0.0;
  std::int64_t steps = 0;
  std::uint64_t frames_before = readers.received();
  double net_cpu = 0.0;
  double reader_cpu = 0.0;
  for (auto _ : state) {
    const std::int64_t s0 = server->simCounters().steps.load();
    // The server's network work: its poll loop and libzmq's I/O thread (which writes to the sockets).
    const double net0 = threadCpuSeconds("sph-net") + threadCpuSeconds("ZMQbg/IO");
    const double read0 = threadCpuSeconds("bench-readers");
    const auto t0 = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::seconds(5));
    steps = server->simCounters().steps.load() - s0;
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    net_cpu = threadCpuSeconds("sph-net") + threadCpuSeconds("ZMQbg/IO") - net0;
    reader_cpu = threadCpuSeconds("bench-readers") - read0;
    state.SetIterationTime(seconds);
  }
  // CPU milliseconds per wall second: what the fan-out takes from the cores the step could use.
  state.counters["server_net_cpu_ms_per_s"] = 1e3 * net_cpu / seconds;
  state.counters["readers_cpu_ms_per_s"] = 1e3 * reader_cpu / seconds;
  state.counters["steps_per_s"] = steps / seconds;
  state.counters["ms_per_step"] = 1e3 * seconds / std::max<std::int64_t>(steps, 1);
  state.counters["frames_per_s_per_sub"] =
      subscribers > 0 ? (readers.received() - frames_before) / seconds / subscribers : 0.0;
  server->stop();
}
// Alternating runs, so a change in the machine's load hits both configurations alike.
BENCHMARK(StepRate)->Arg(0)->Arg(8)->Arg(0)->Arg(8)->Arg(0)->Arg(8)->Iterations(1)->UseManualTime()->Unit(
    benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
