#include "net/connection_monitor.h"

// linux/tcp.h, not netinet/tcp.h: glibc's struct tcp_info lacks tcpi_bytes_received.
#include <linux/tcp.h>
#include <netinet/in.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>

#include <atomic>
#include <cstring>

namespace net {
namespace {

std::atomic<int> next_monitor_id{0};

constexpr int kEvents = ZMQ_EVENT_ACCEPTED | ZMQ_EVENT_ACCEPT_FAILED | ZMQ_EVENT_DISCONNECTED |
                        ZMQ_EVENT_HANDSHAKE_FAILED_NO_DETAIL | ZMQ_EVENT_HANDSHAKE_FAILED_PROTOCOL |
                        ZMQ_EVENT_HANDSHAKE_FAILED_AUTH;
// Events waiting in the pipe before libzmq's sender would block: far more than a busy second brings.
constexpr int kEventQueue = 100000;

// A ZMTP greeting is 64 bytes; a peer that sent fewer this long after connecting is not a ZeroMQ peer
// at work (a handshake takes milliseconds).
constexpr std::uint64_t kGreetingBytes = 64;
constexpr auto kSilentAfter = std::chrono::seconds(1);

bool bytesReceived(int fd, std::uint64_t& out) {
  tcp_info info{};
  socklen_t length = sizeof info;
  if (::getsockopt(fd, IPPROTO_TCP, TCP_INFO, &info, &length) != 0) return false;
  out = info.tcpi_bytes_received;
  return true;
}

}  // namespace

ConnectionMonitor::ConnectionMonitor(zmq::context_t& context, zmq::socket_t& socket, std::string role, int max_peers,
                                     int fd_limit, std::chrono::milliseconds log_interval)
    : socket_(socket),
      role_(std::move(role)),
      max_peers_(max_peers),
      fd_limit_(fd_limit),
      events_(context, zmq::socket_type::pair),
      accept_log_(log_interval),
      limit_log_(log_interval),
      handshake_log_(log_interval) {
  const std::string endpoint = "inproc://sph-monitor-" + std::to_string(next_monitor_id.fetch_add(1));
  if (zmq_socket_monitor(socket_.handle(), endpoint.c_str(), kEvents) != 0) throw zmq::error_t();
  events_.set(zmq::sockopt::linger, 0);
  events_.set(zmq::sockopt::rcvhwm, kEventQueue);
  // At once: libzmq's sender blocks (the I/O thread with it) while its PAIR has no peer.
  events_.connect(endpoint);
}

ConnectionMonitor::~ConnectionMonitor() { zmq_socket_monitor(socket_.handle(), nullptr, 0); }

void ConnectionMonitor::drain() {
  for (;;) {
    zmq::message_t head;
    if (!events_.recv(head, zmq::recv_flags::dontwait)) return;
    zmq::message_t address;  // the second part always follows the first
    if (head.more()) (void)events_.recv(address, zmq::recv_flags::dontwait);
    if (head.size() < 6) continue;
    std::uint16_t event = 0;
    std::uint32_t value = 0;
    std::memcpy(&event, head.data(), sizeof event);
    std::memcpy(&value, static_cast<const char*>(head.data()) + 2, sizeof value);
    onEvent(event, value);
  }
}

void ConnectionMonitor::onEvent(std::uint16_t event, std::uint32_t value) {
  const int fd = static_cast<int>(value);
  switch (event) {
    case ZMQ_EVENT_ACCEPTED: {
      Peer& peer = peers_[fd];
      peer = Peer{Clock::now(), false};
      if (peers() > max_peers_) {
        ++refused_over_limit_;
        // A full socket makes room by dropping a connection that never even sent a greeting, so idle
        // connections cannot lock peers out; else the newcomer goes.
        const auto idle = silentPeer(peer.accepted);
        drop(idle != peers_.end() ? idle->first : fd, idle != peers_.end() ? idle->second : peer);
        if (const std::uint64_t n = limit_log_.note()) {
          spdlog::warn("dropped {} connection(s) on the {} socket: it has {} peers, its limit ({} in all)", n, role_,
                       max_peers_, refused_over_limit_);
        }
      }
      break;
    }
    case ZMQ_EVENT_DISCONNECTED:
      peers_.erase(fd);
      break;
    case ZMQ_EVENT_ACCEPT_FAILED:
      ++accept_failures_;
      if (const std::uint64_t n = accept_log_.note()) {
        const bool no_fds = value == EMFILE || value == ENFILE;
        spdlog::error("{} connection(s) could not be accepted on the {} socket: {}{} ({} in all)", n, role_,
                      std::strerror(static_cast<int>(value)),
                      no_fds ? fmt::format("; this process may hold {} descriptors: raise the limit (ulimit -n, "
                                           "systemd LimitNOFILE=) or lower --max-peers",
                                           fd_limit_)
                             : std::string(),
                      accept_failures_);
      }
      break;
    default:  // the handshake failures: no CURVE, a bad greeting, a key the handler refused
      ++handshake_failures_;
      if (const std::uint64_t n = handshake_log_.note()) {
        const char* why = event == ZMQ_EVENT_HANDSHAKE_FAILED_AUTH ? "key refused"
                          : event == ZMQ_EVENT_HANDSHAKE_FAILED_PROTOCOL
                              ? "protocol error (a client without CURVE, or not ZeroMQ at all?)"
                              : "no detail";
        spdlog::info("{} handshake(s) failed on the {} socket (latest: {}; {} in all)", n, role_, why,
                     handshake_failures_);
      }
      break;
  }
}

void ConnectionMonitor::drop(int fd, Peer& peer) {
  if (peer.dropped) return;
  peer.dropped = true;
  ++dropped_;
  ::shutdown(fd, SHUT_RDWR);
}

int ConnectionMonitor::peers() const {
  int n = 0;
  for (const auto& [fd, peer] : peers_) n += peer.dropped ? 0 : 1;
  return n;
}

std::map<int, ConnectionMonitor::Peer>::iterator ConnectionMonitor::silentPeer(Clock::time_point now) {
  auto oldest = peers_.end();
  for (auto it = peers_.begin(); it != peers_.end(); ++it) {
    std::uint64_t received = 0;
    if (it->second.dropped || now - it->second.accepted < kSilentAfter || !bytesReceived(it->first, received) ||
        received >= kGreetingBytes) {
      continue;
    }
    if (oldest == peers_.end() || it->second.accepted < oldest->second.accepted) oldest = it;
  }
  return oldest;
}

int ConnectionMonitor::dropPeersOver(std::uint64_t base_bytes, double bytes_per_second) {
  drain();  // the freshest descriptor table (see the header)
  const Clock::time_point now = Clock::now();
  int n = 0;
  for (auto& [fd, peer] : peers_) {
    std::uint64_t received = 0;
    if (peer.dropped || !bytesReceived(fd, received)) continue;
    const double age = std::chrono::duration<double>(now - peer.accepted).count();
    if (static_cast<double>(received) > static_cast<double>(base_bytes) + bytes_per_second * age) {
      drop(fd, peer);
      ++n;
    }
  }
  return n;
}

int ConnectionMonitor::dropAll() {
  drain();
  int n = 0;
  for (auto& [fd, peer] : peers_) {
    if (!peer.dropped) ++n;
    drop(fd, peer);
  }
  return n;
}

}  // namespace net
