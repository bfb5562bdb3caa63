#include "net/zap_handler.h"

#include <pthread.h>
#include <spdlog/spdlog.h>

#include <vector>

#include "net/curve_sockets.h"
#include "net/log_throttle.h"

namespace curve {
namespace {

constexpr auto kPollInterval = std::chrono::milliseconds(100);  // how soon the thread sees stop

// ZMTP metadata (RFC 23 / 27): a one-byte name length, the name, a four-byte big-endian value
// length, the value.
void appendProperty(std::string& out, const std::string& name, const std::string& value) {
  out += static_cast<char>(name.size());
  out += name;
  const auto n = static_cast<std::uint32_t>(value.size());
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((n >> shift) & 0xFF);
  out += value;
}

}  // namespace

ZapHandler::ZapHandler(zmq::context_t& context, AllowList keys, std::chrono::milliseconds log_interval)
    : keys_(std::move(keys)), log_interval_(log_interval), socket_(context, zmq::socket_type::rep) {
  socket_.set(zmq::sockopt::linger, 0);
  socket_.bind("inproc://zeromq.zap.01");
  thread_ = std::thread([this] { run(); });
}

ZapHandler::~ZapHandler() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void ZapHandler::run() {
  pthread_setname_np(pthread_self(), "sph-zap");
  net::LogThrottle refusals(log_interval_);
  std::vector<zmq::message_t> request;
  while (!stop_.load()) {
    try {
      zmq::pollitem_t item{socket_.handle(), 0, ZMQ_POLLIN, 0};
      if (zmq::poll(&item, 1, kPollInterval) <= 0) continue;
      request.clear();
      bool more = true;
      while (more) {
        zmq::message_t part;
        if (!socket_.recv(part, zmq::recv_flags::dontwait)) break;
        more = part.more();
        // RFC 27 has 7 frames for CURVE; a longer request is malformed (and libzmq never sends one).
        if (request.size() < 8) request.push_back(std::move(part));
      }
      const std::uint64_t before = refused_.load();
      answer(request);
      if (refused_.load() != before) {
        if (const std::uint64_t n = refusals.note()) {
          const std::string domain = request.size() > 2 ? request[2].to_string() : "?";
          const std::string address = request.size() > 3 ? request[3].to_string() : "?";
          spdlog::warn("refused {} connection(s) with an unknown key or no CURVE (latest: {} on the {} socket)", n,
                       address, domain);
        }
      }
    } catch (const zmq::error_t& e) {
      if (e.num() == ETERM) break;
      spdlog::error("ZAP handler: {}", e.what());
    }
  }
}

void ZapHandler::answer(std::vector<zmq::message_t>& request) {
  // Request: version, request id, domain, address, identity, mechanism, credentials...
  // Reply: version, request id, status code, status text, user id, metadata.
  std::string status = "400";
  std::string text = "unknown key";
  std::string user;
  std::string metadata;
  if (request.size() >= 7 && request[0].to_string() == "1.0" && request[5].to_string() == "CURVE" &&
      request[6].size() == 32) {
    const auto it = keys_.find(z85Encode(static_cast<const unsigned char*>(request[6].data())));
    if (it != keys_.end()) {
      status = "200";
      text = "OK";
      user = it->second.name;
      appendProperty(metadata, kRoleProperty, roleName(it->second.role));
    }
  } else {
    text = "CURVE required";
  }
  (status == "200" ? accepted_ : refused_).fetch_add(1);
  const auto more = zmq::send_flags::sndmore;
  socket_.send(zmq::str_buffer("1.0"), more);
  if (request.size() > 1) {
    socket_.send(request[1], more);
  } else {
    socket_.send(zmq::message_t(), more);
  }
  socket_.send(zmq::buffer(status), more);
  socket_.send(zmq::buffer(text), more);
  socket_.send(zmq::buffer(user), more);
  socket_.send(zmq::buffer(metadata), zmq::send_flags::none);
}

}  // namespace curve
