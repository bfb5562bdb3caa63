#include "emulators.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <msgpack.hpp>
#include <stdexcept>

namespace gaze_bridge_test {

namespace {

int portOf(const std::string& endpoint) { return std::stoi(endpoint.substr(endpoint.rfind(':') + 1)); }

}  // namespace

std::string packSurfaceMessage(const std::string& surface, const std::vector<PupilGaze>& gaze) {
  msgpack::sbuffer buffer;
  msgpack::packer<msgpack::sbuffer> pk(&buffer);
  // The fields Pupil Capture's surface tracker sends, including ones the bridge ignores.
  pk.pack_map(5);
  pk.pack(std::string("topic"));
  pk.pack("surfaces." + surface);
  pk.pack(std::string("name"));
  pk.pack(surface);
  pk.pack(std::string("timestamp"));
  pk.pack(gaze.empty() ? 0.0 : gaze.back().timestamp);
  pk.pack(std::string("fixations_on_surfaces"));
  pk.pack_array(0);
  pk.pack(std::string("gaze_on_surfaces"));
  pk.pack_array(static_cast<std::uint32_t>(gaze.size()));
  for (const PupilGaze& g : gaze) {
    pk.pack_map(6);
    pk.pack(std::string("topic"));
    pk.pack(std::string("gaze.3d.01._on_surface"));
    pk.pack(std::string("norm_pos"));
    pk.pack_array(2);
    pk.pack(g.x);
    pk.pack(g.y);
    pk.pack(std::string("confidence"));
    pk.pack(g.confidence);
    pk.pack(std::string("on_surf"));
    pk.pack(g.on_surf);
    pk.pack(std::string("base_data"));
    pk.pack_array(2);
    pk.pack(std::string("gaze.3d.01."));
    pk.pack(g.timestamp);
    pk.pack(std::string("timestamp"));
    pk.pack(g.timestamp);
  }
  return std::string(buffer.data(), buffer.size());
}

PupilEmulator::PupilEmulator(zmq::context_t& context, int remote_port)
    : pub_(context, zmq::socket_type::pub), remote_(context, zmq::socket_type::rep) {
  pub_.set(zmq::sockopt::linger, 0);
  remote_.set(zmq::sockopt::linger, 0);
  pub_.bind("tcp://127.0.0.1:*");
  pub_port_ = portOf(pub_.get(zmq::sockopt::last_endpoint));
  if (remote_port == 0) {
    remote_.bind("tcp://127.0.0.1:*");
  } else {
    // A restart on the old port: libzmq closes the previous listener asynchronously, so retry a while.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    for (;;) {
      try {
        remote_.bind("tcp://127.0.0.1:" + std::to_string(remote_port));
        break;
      } catch (const zmq::error_t&) {
        if (std::chrono::steady_clock::now() > give_up) throw;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    }
  }
  remote_port_ = portOf(remote_.get(zmq::sockopt::last_endpoint));
  thread_ = std::thread([this] { serveRemote(); });
}

PupilEmulator::~PupilEmulator() {
  stop_.store(true);
  thread_.join();
}

void PupilEmulator::serveRemote() {
  while (!stop_.load()) {
    zmq::pollitem_t item{remote_.handle(), 0, ZMQ_POLLIN, 0};
    zmq::poll(&item, 1, std::chrono::milliseconds(20));
    if (!(item.revents & ZMQ_POLLIN)) continue;
    zmq::message_t request;
    if (!remote_.recv(request, zmq::recv_flags::dontwait)) continue;
    ++port_requests_;
    const std::string reply = request.to_string() == "SUB_PORT" ? std::to_string(pub_port_) : "unknown command";
    remote_.send(zmq::buffer(reply), zmq::send_flags::none);
  }
}

void PupilEmulator::publish(const std::string& topic, const std::string& payload) {
  pub_.send(zmq::buffer(topic), zmq::send_flags::sndmore);
  pub_.send(zmq::buffer(payload), zmq::send_flags::none);
}

GazepointEmulator::GazepointEmulator(int port) {
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  const int one = 1;
  ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || ::listen(listen_fd_, 4) != 0) {
    ::close(listen_fd_);
    throw std::runtime_error("gazepoint emulator: cannot listen on port " + std::to_string(port));
  }
  socklen_t length = sizeof address;
  ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
  thread_ = std::thread([this] { serve(); });
}

GazepointEmulator::~GazepointEmulator() {
  stop_.store(true);
  thread_.join();
  ::close(listen_fd_);
}

std::string GazepointEmulator::commandsReceived() {
  std::lock_guard lock(mutex_);
  return commands_;
}

void GazepointEmulator::send(const std::string& text) {
  std::lock_guard lock(mutex_);
  outgoing_.push_back(text);
}

void GazepointEmulator::serve() {
  int client = -1;
  std::string inbox;
  std::size_t piece = 1;
  while (!stop_.load()) {
    if (client < 0) {
      pollfd pfd{listen_fd_, POLLIN, 0};
      if (::poll(&pfd, 1, 20) <= 0) continue;
      client = ::accept(listen_fd_, nullptr, nullptr);
      if (client < 0) continue;
      const int one = 1;
      ::setsockopt(client, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);  // keep our pieces apart
      acked_.store(0);
      inbox.clear();
      {
        std::lock_guard lock(mutex_);
        outgoing_.clear();  // nothing queued for a previous client leaks into this one
        commands_.clear();
      }
      ++connections_;
    }
    if (drop_.exchange(false)) {
      ::close(client);
      client = -1;
      continue;
    }
    // Commands from the bridge: ACK every SET line.
    pollfd pfd{client, POLLIN, 0};
    if (::poll(&pfd, 1, 2) > 0) {
      char buffer[1024];
      const ssize_t n = ::recv(client, buffer, sizeof buffer, 0);
      if (n <= 0) {
        ::close(client);
        client = -1;
        continue;
      }
      inbox.append(buffer, static_cast<std::size_t>(n));
      for (std::size_t end; (end = inbox.find("\r\n")) != std::string::npos;) {
        const std::string line = inbox.substr(0, end);
        inbox.erase(0, end + 2);
        {
          std::lock_guard lock(mutex_);
          commands_ += line + "\n";
        }
        if (line.rfind("<SET ", 0) == 0) {
          std::string ack = "<ACK" + line.substr(4, line.size() - 4) + "\r\n";
          ::send(client, ack.data(), ack.size(), MSG_NOSIGNAL);
          ++acked_;
        }
      }
    }
    // Queued output in small pieces, so a record spans several TCP segments.
    std::string text;
    {
      std::lock_guard lock(mutex_);
      if (!outgoing_.empty()) {
        text = std::move(outgoing_.front());
        outgoing_.pop_front();
      }
    }
    for (std::size_t at = 0; at < text.size();) {
      const std::size_t n = std::min(piece, text.size() - at);
      if (::send(client, text.data() + at, n, MSG_NOSIGNAL) < 0) break;
      at += n;
      piece = piece % 13 + 1;
    }
  }
  if (client >= 0) ::close(client);
}

std::string gazepointRecord(double time_s, double x, double y, bool valid) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "<REC TIME=\"%.3f\" BPOGX=\"%.5f\" BPOGY=\"%.5f\" BPOGV=\"%d\" />\r\n", time_s,
                x, y, valid ? 1 : 0);
  return buffer;
}

}  // namespace gaze_bridge_test
