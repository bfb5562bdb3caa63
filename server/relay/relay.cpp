#include "relay/relay.h"

#include <pthread.h>
#include <spdlog/spdlog.h>

#include "net/frame_subscriptions.h"

namespace relay {
namespace {

std::atomic<int> next_relay_id{0};
constexpr auto kWatchPeriod = std::chrono::milliseconds(100);  // how often greedy peers are looked for
// The capture pipe holds this many frames for the monitor thread; a frame copy shares its buffer.
constexpr int kCaptureQueue = 10000;

}  // namespace

Relay::Relay(const RelayOptions& options)
    : options_(options),
      upstream_(context_, zmq::socket_type::xsub),
      downstream_socket_(context_, zmq::socket_type::pub),
      capture_(context_, zmq::socket_type::pub),
      capture_reader_(context_, zmq::socket_type::sub),
      control_(context_, zmq::socket_type::pair),
      steer_(context_, zmq::socket_type::pair) {
  if (options.curve) {
    if (options.clients.empty()) throw std::invalid_argument("CURVE needs at least one client key");
    zap_ = std::make_unique<curve::ZapHandler>(context_, options.clients, options.log_interval);
    curve::makeCurveServer(downstream_socket_, *options.curve, "relay");
  }
  net::applyCommonOptions(downstream_socket_);
  downstream_socket_.set(zmq::sockopt::sndhwm, options.hwm);
  // A viewer's subscription is all it may send: the server's limits (frame_subscriptions.h).
  downstream_socket_.set(zmq::sockopt::maxmsgsize, static_cast<int64_t>(net::kMaxSubscriptionBytes));
  downstream_socket_.set(zmq::sockopt::rcvhwm, net::kSubscriptionQueue);
  monitor_ = std::make_unique<net::ConnectionMonitor>(context_, downstream_socket_, "relay", options.max_peers,
                                                      options.fd_limit, options.log_interval);
  downstream_ = net::bindResolved(downstream_socket_, options.downstream, "relay");

  upstream_.set(zmq::sockopt::linger, 0);
  upstream_.set(zmq::sockopt::rcvhwm, options.hwm);
  upstream_.set(zmq::sockopt::heartbeat_ivl, net::kHeartbeatIntervalMs);
  upstream_.set(zmq::sockopt::heartbeat_timeout, net::kHeartbeatTimeoutMs);
  upstream_.set(zmq::sockopt::reconnect_ivl, 100);
  upstream_.set(zmq::sockopt::reconnect_ivl_max, 1000);
  if (options.upstream_curve) curve::makeCurveClient(upstream_, *options.upstream_curve);
  try {
    upstream_.connect(options.upstream);
  } catch (const zmq::error_t& e) {
    throw std::runtime_error("cannot connect upstream to " + options.upstream + ": " + e.what());
  }
  // Everything, once: the XSUB repeats its subscriptions to a server it reconnects to.
  upstream_.send(zmq::str_buffer("\x01"), zmq::send_flags::none);

  const std::string id = std::to_string(next_relay_id.fetch_add(1));
  capture_.set(zmq::sockopt::linger, 0);
  capture_.set(zmq::sockopt::sndhwm, kCaptureQueue);
  capture_.bind("inproc://sph-relay-capture-" + id);
  capture_reader_.set(zmq::sockopt::linger, 0);
  capture_reader_.set(zmq::sockopt::rcvhwm, kCaptureQueue);
  capture_reader_.set(zmq::sockopt::subscribe, "");
  capture_reader_.connect("inproc://sph-relay-capture-" + id);
  control_.set(zmq::sockopt::linger, 0);
  steer_.set(zmq::sockopt::linger, 0);
  control_.bind("inproc://sph-relay-control-" + id);
  steer_.connect("inproc://sph-relay-control-" + id);
}

Relay::~Relay() { stop(); }

void Relay::start() {
  if (running_) return;
  running_ = true;
  stop_watch_ = false;
  watch_thread_ = std::thread([this] { watch(); });
  proxy_thread_ = std::thread([this] {
    pthread_setname_np(pthread_self(), "sph-relay");
    // Returns when TERMINATE arrives on the control socket (or the context ends).
    zmq_proxy_steerable(upstream_.handle(), downstream_socket_.handle(), capture_.handle(), control_.handle());
  });
}

void Relay::stop() {
  if (!running_) return;
  steer_.send(zmq::str_buffer("TERMINATE"), zmq::send_flags::none);
  proxy_thread_.join();
  stop_watch_ = true;
  watch_thread_.join();
  running_ = false;
}

void Relay::watch() {
  pthread_setname_np(pthread_self(), "sph-relay-watch");
  zmq::pollitem_t items[] = {{capture_reader_.handle(), 0, ZMQ_POLLIN, 0},
                             {monitor_->events().handle(), 0, ZMQ_POLLIN, 0}};
  auto next_sweep = std::chrono::steady_clock::now() + kWatchPeriod;
  while (!stop_watch_.load()) {
    try {
      zmq::poll(items, 2, kWatchPeriod);
      zmq::message_t message;
      // Frames come from upstream; PUB never passes a viewer's subscriptions up, so all are frames.
      while (capture_reader_.recv(message, zmq::recv_flags::dontwait)) {
        forwarded_.fetch_add(1);
        if (options_.on_forward) options_.on_forward(message);
      }
      monitor_->drain();
      const auto now = std::chrono::steady_clock::now();
      if (now >= next_sweep) {
        // PUB hides the subscriptions themselves, so the bytes each peer sent are the measure.
        if (const int n =
                monitor_->dropPeersOver(net::kSubscriberAllowanceBytes, net::kSubscriberAllowanceBytesPerSecond)) {
          spdlog::warn("dropped {} viewer connection(s) that sent far more than a subscriber does", n);
        }
        next_sweep = now + kWatchPeriod;
      }
      peers_.store(monitor_->peers());
      peers_dropped_.store(monitor_->dropped());
    } catch (const zmq::error_t& e) {
      if (e.num() == ETERM) break;
      spdlog::error("relay: {}", e.what());
    }
  }
}

}  // namespace relay
