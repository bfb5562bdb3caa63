// viewer_bench_publisher: a stand-in server for benchmarks and demos. Publishes frames of N moving
// particles (a block of water that sloshes) on a PUB socket at a fixed rate, and prints the bound
// endpoint. Not a test: see benchmarks/bench_viewer.sh for the viewer benchmark that uses it.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <thread>
#include <zmq.hpp>

#include "test_frames.h"

namespace {
volatile std::sig_atomic_t g_stop = 0;
void onSignal(int /*signal*/) { g_stop = 1; }
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"viewer_bench_publisher: publishes synthetic frames for sph_viewer benchmarks"};
  std::string endpoint = "tcp://127.0.0.1:*";
  std::size_t particles = 20000;
  double hz = 60.0;
  double seconds = 0.0;
  bool quantized = false;
  app.add_option("--endpoint", endpoint, "PUB endpoint to bind")->capture_default_str();
  app.add_option("--particles", particles, "particles per frame")->capture_default_str();
  app.add_option("--hz", hz, "frames per second")->check(CLI::Range(0.1, 1000.0))->capture_default_str();
  app.add_option("--seconds", seconds, "stop after this long (0: until SIGINT/SIGTERM)");
  app.add_flag("--quantized", quantized, "16-bit positions");
  CLI11_PARSE(app, argc, argv);
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);

  zmq::context_t context;
  zmq::socket_t pub(context, zmq::socket_type::pub);
  pub.set(zmq::sockopt::linger, 0);
  pub.set(zmq::sockopt::sndhwm, 4);
  pub.bind(endpoint);
  std::printf("%s\n", pub.get(zmq::sockopt::last_endpoint).c_str());
  std::fflush(stdout);

  viewer_test::FrameSpec spec;
  spec.box_lo = 0.0f;
  spec.box_hi = 1.0f;
  spec.radius_small = 0.01337f;
  spec.radius_large = 0.01685f;
  spec.quantized = quantized;
  spec.with_gaze = true;
  spec.gaze_radius = 0.05f;
  spec.gaze_ring = 0.08f;
  const auto base = viewer_test::particleCloud(particles, 0.05f, 0.6f);
  spec.particles = base;
  std::string bytes;
  const auto start = std::chrono::steady_clock::now();
  const auto period = std::chrono::duration<double>(1.0 / hz);
  for (std::uint64_t seq = 1; !g_stop; ++seq) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > 0.0 && t > seconds) break;
    for (std::size_t i = 0; i < particles; ++i) {
      spec.particles[i].x = base[i].x + 0.2f * static_cast<float>(std::sin(2.0 * t + base[i].y * 4.0));
    }
    auto frame = viewer_test::makeFrame(spec, seq);
    frame.set_send_time_us(
        std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
            .count());
    frame.SerializeToString(&bytes);
    (void)pub.send(zmq::buffer(bytes), zmq::send_flags::dontwait);
    std::this_thread::sleep_until(
        start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(period * static_cast<double>(seq)));
  }
  return 0;
}
