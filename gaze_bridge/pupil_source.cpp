#include "pupil_source.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "pupil_decode.h"

namespace gaze_bridge {

namespace {

constexpr std::int64_t kMinBackoffNs = 100'000'000;
constexpr std::int64_t kMaxBackoffNs = 2'000'000'000;
constexpr std::int64_t kRemoteReplyTimeoutNs = 1'000'000'000;
// Surface messages carry base data; a few MiB is far above any real one.
constexpr std::int64_t kMaxSurfaceMessageBytes = 4 * 1024 * 1024;

void configure(zmq::socket_t& socket) {
  socket.set(zmq::sockopt::linger, 0);
  socket.set(zmq::sockopt::reconnect_ivl, 100);
  socket.set(zmq::sockopt::reconnect_ivl_max, 1000);
}

}  // namespace

PupilSource::PupilSource(zmq::context_t& context, const PupilParams& params)
    : context_(context), params_(params), topic_("surfaces." + params.surface) {
  if (params_.remote_port < 1 || params_.remote_port > 65535)
    throw std::invalid_argument("pupil port must be 1..65535");
  if (params_.surface.empty()) throw std::invalid_argument("pupil surface name must not be empty");
  if (!(std::isfinite(params_.tracker_timeout_s) && params_.tracker_timeout_s > 0.0)) {
    throw std::invalid_argument("tracker timeout must be > 0 s");
  }
}

void PupilSource::restart(const std::string& why) {
  if (state_ == State::kStreaming && receiving_) {
    spdlog::warn("pupil: {}; asking Pupil Remote again", why);
  } else if (!logged_unreachable_) {
    spdlog::warn("pupil: {} (retrying quietly)", why);
    logged_unreachable_ = true;
  }
  remote_.reset();
  sub_.reset();
  state_ = State::kIdle;
  receiving_ = false;
  next_attempt_ns_ = steadyNowNs() + backoff_ns_;
  backoff_ns_ = std::min(backoff_ns_ * 2, kMaxBackoffNs);
}

void PupilSource::askPort() {
  remote_ = std::make_unique<zmq::socket_t>(context_, zmq::socket_type::req);
  configure(*remote_);
  remote_->set(zmq::sockopt::maxmsgsize, std::int64_t{256});
  try {
    remote_->connect("tcp://" + params_.host + ":" + std::to_string(params_.remote_port));
    if (!remote_->send(zmq::str_buffer("SUB_PORT"), zmq::send_flags::dontwait)) {
      restart("Pupil Remote not reachable");
      return;
    }
  } catch (const zmq::error_t& error) {
    restart(std::string("Pupil Remote: ") + error.what());
    return;
  }
  state_ = State::kAwaitingPort;
  request_sent_ns_ = steadyNowNs();
}

void PupilSource::awaitPort(int timeout_ms) {
  zmq::pollitem_t item{remote_->handle(), 0, ZMQ_POLLIN, 0};
  zmq::poll(&item, 1, std::chrono::milliseconds(timeout_ms));
  if (!(item.revents & ZMQ_POLLIN)) {
    if (steadyNowNs() - request_sent_ns_ > kRemoteReplyTimeoutNs) {
      restart("no answer from Pupil Remote at " + params_.host + ":" + std::to_string(params_.remote_port));
    }
    return;
  }
  zmq::message_t reply;
  if (!remote_->recv(reply, zmq::recv_flags::dontwait)) return;
  const std::string_view text(static_cast<const char*>(reply.data()), reply.size());
  int port = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), port);
  if (error != std::errc() || end != text.data() + text.size() || port < 1 || port > 65535) {
    restart("Pupil Remote answered SUB_PORT with '" + std::string(text.substr(0, 32)) + "'");
    return;
  }
  remote_.reset();
  sub_ = std::make_unique<zmq::socket_t>(context_, zmq::socket_type::sub);
  configure(*sub_);
  sub_->set(zmq::sockopt::maxmsgsize, kMaxSurfaceMessageBytes);
  sub_->set(zmq::sockopt::rcvhwm, 1000);
  sub_->set(zmq::sockopt::subscribe, topic_);
  sub_->connect("tcp://" + params_.host + ":" + std::to_string(port));
  state_ = State::kStreaming;
  receiving_ = false;
  last_data_ns_ = steadyNowNs();
  ++subscriptions_;
  spdlog::info("pupil: subscribed to '{}' on {}:{}", topic_, params_.host, port);
}

void PupilSource::receive(std::vector<TrackerSample>& out, int timeout_ms) {
  zmq::pollitem_t item{sub_->handle(), 0, ZMQ_POLLIN, 0};
  zmq::poll(&item, 1, std::chrono::milliseconds(timeout_ms));
  const std::int64_t now = steadyNowNs();
  if (!(item.revents & ZMQ_POLLIN)) {
    if (now - last_data_ns_ > static_cast<std::int64_t>(params_.tracker_timeout_s * 1e9)) {
      restart("no surface data for " + std::to_string(params_.tracker_timeout_s) + " s");
    }
    return;
  }
  // Drain what is queued, one multipart message (topic, msgpack payload, optional raw frames) at a time.
  zmq::message_t topic, payload, extra;
  while (sub_->recv(topic, zmq::recv_flags::dontwait)) {
    bool have_payload = false;
    if (topic.more()) {
      (void)sub_->recv(payload, zmq::recv_flags::none);  // parts of a message arrive together
      have_payload = true;
      for (bool more = payload.more(); more;) {
        (void)sub_->recv(extra, zmq::recv_flags::none);
        more = extra.more();
      }
    }
    // The subscription is a prefix match ("surfaces.screen" also matches "surfaces.screen2").
    if (topic.to_string_view() != topic_) continue;
    if (!have_payload) {
      ++malformed_;
      continue;
    }
    std::size_t skipped = 0;
    const std::string problem = decodePupilSurfaceMessage(payload.data(), payload.size(), now, out, skipped);
    malformed_ += skipped + (problem.empty() ? 0 : 1);
    if (!problem.empty()) spdlog::debug("pupil: dropped a message: {}", problem);
    last_data_ns_ = now;
    if (!receiving_) {
      receiving_ = true;
      backoff_ns_ = kMinBackoffNs;
      logged_unreachable_ = false;
      spdlog::info("pupil: receiving gaze on '{}'", topic_);
    }
  }
}

void PupilSource::poll(std::vector<TrackerSample>& out, int timeout_ms) {
  timeout_ms = std::max(timeout_ms, 0);
  switch (state_) {
    case State::kIdle: {
      const std::int64_t wait_ns = next_attempt_ns_ - steadyNowNs();
      if (wait_ns > 0) {
        const auto ms = std::min<std::int64_t>(wait_ns / 1'000'000 + 1, timeout_ms);
        std::this_thread::sleep_for(std::chrono::milliseconds(ms));
        return;
      }
      askPort();
      if (state_ == State::kAwaitingPort) awaitPort(timeout_ms);
      return;
    }
    case State::kAwaitingPort:
      awaitPort(timeout_ms);
      return;
    case State::kStreaming:
      receive(out, timeout_ms);
      return;
  }
}

}  // namespace gaze_bridge
