#include "gazepoint_source.h"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace gaze_bridge {

namespace {

constexpr std::int64_t kMinBackoffNs = 100'000'000;
constexpr std::int64_t kMaxBackoffNs = 2'000'000'000;
constexpr std::int64_t kConnectTimeoutNs = 2'000'000'000;

void sleepMs(int ms) {
  if (ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(ms));
}

}  // namespace

GazepointSource::GazepointSource(const GazepointParams& params) : params_(params) {
  if (params_.port < 1 || params_.port > 65535) throw std::invalid_argument("gazepoint port must be 1..65535");
  if (!(std::isfinite(params_.tracker_timeout_s) && params_.tracker_timeout_s > 0.0)) {
    throw std::invalid_argument("tracker timeout must be > 0 s");
  }
}

GazepointSource::~GazepointSource() {
  if (fd_ >= 0) ::close(fd_);
}

void GazepointSource::disconnect(const std::string& why) {
  if (state_ == State::kStreaming) spdlog::warn("gazepoint {}:{}: {}; reconnecting", params_.host, params_.port, why);
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  state_ = State::kIdle;
  splitter_.clear();
  next_attempt_ns_ = steadyNowNs() + backoff_ns_;
  backoff_ns_ = std::min(backoff_ns_ * 2, kMaxBackoffNs);
}

void GazepointSource::startConnect() {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* result = nullptr;
  const std::string port = std::to_string(params_.port);
  if (::getaddrinfo(params_.host.c_str(), port.c_str(), &hints, &result) != 0 || result == nullptr) {
    if (!logged_refused_) spdlog::warn("gazepoint: cannot resolve host '{}'", params_.host);
    logged_refused_ = true;
    disconnect("unresolved");
    return;
  }
  fd_ = ::socket(result->ai_family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  int rc = -1;
  if (fd_ >= 0) rc = ::connect(fd_, result->ai_addr, result->ai_addrlen);
  ::freeaddrinfo(result);
  if (fd_ < 0 || (rc != 0 && errno != EINPROGRESS)) {
    disconnect(std::string("connect: ") + std::strerror(errno));
    return;
  }
  const int one = 1;
  ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);  // our SET commands are tiny
  state_ = State::kConnecting;
  connect_started_ns_ = steadyNowNs();
}

bool GazepointSource::sendAll(const std::string& text) {
  std::size_t done = 0;
  const std::int64_t give_up = steadyNowNs() + kConnectTimeoutNs;
  while (done < text.size()) {
    const ssize_t n = ::send(fd_, text.data() + done, text.size() - done, MSG_NOSIGNAL);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n < 0 && (errno == EAGAIN || errno == EINTR) && steadyNowNs() < give_up) {
      pollfd pfd{fd_, POLLOUT, 0};
      ::poll(&pfd, 1, 10);
    } else {
      return false;
    }
  }
  return true;
}

void GazepointSource::finishConnect(int timeout_ms) {
  pollfd pfd{fd_, POLLOUT, 0};
  const int ready = ::poll(&pfd, 1, timeout_ms);
  if (ready == 0) {
    if (steadyNowNs() - connect_started_ns_ > kConnectTimeoutNs) disconnect("connect timed out");
    return;
  }
  int error = 0;
  socklen_t length = sizeof error;
  if (ready < 0 || ::getsockopt(fd_, SOL_SOCKET, SO_ERROR, &error, &length) != 0 || error != 0) {
    if (!logged_refused_) {
      spdlog::warn("gazepoint {}:{}: {} (retrying quietly)", params_.host, params_.port,
                   std::strerror(error != 0 ? error : errno));
      logged_refused_ = true;
    }
    disconnect("connect failed");
    return;
  }
  for (const std::string& command : openGazeStartCommands()) {
    if (!sendAll(command)) {
      disconnect("sending SET commands failed");
      return;
    }
  }
  state_ = State::kStreaming;
  last_data_ns_ = steadyNowNs();
  backoff_ns_ = kMinBackoffNs;
  logged_refused_ = false;
  ++connects_;
  spdlog::info("gazepoint: connected to {}:{}", params_.host, params_.port);
}

void GazepointSource::readRecords(std::vector<TrackerSample>& out, int timeout_ms) {
  pollfd pfd{fd_, POLLIN, 0};
  const int ready = ::poll(&pfd, 1, timeout_ms);
  const std::int64_t now = steadyNowNs();
  if (ready <= 0) {
    if (now - last_data_ns_ > static_cast<std::int64_t>(params_.tracker_timeout_s * 1e9)) {
      disconnect("no data for " + std::to_string(params_.tracker_timeout_s) + " s");
    }
    return;
  }
  char buffer[16 * 1024];
  const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
  if (n == 0) {
    disconnect("tracker closed the connection");
    return;
  }
  if (n < 0) {
    if (errno != EAGAIN && errno != EINTR) disconnect(std::string("recv: ") + std::strerror(errno));
    return;
  }
  last_data_ns_ = now;
  splitter_.feed(buffer, static_cast<std::size_t>(n));
  while (splitter_.nextLine(line_)) {
    if (line_.empty()) continue;
    if (!parseOpenGazeTag(line_, tag_)) {
      ++malformed_;
      continue;
    }
    OpenGazeRecord record;
    if (parseOpenGazeRecord(tag_, record)) {
      TrackerSample sample;
      sample.tracker_time_s = std::isfinite(record.time_s) ? record.time_s : static_cast<double>(now) * 1e-9;
      sample.x = record.x;
      sample.y = record.y;
      sample.valid = record.valid;
      sample.confidence = record.valid ? 1.0f : 0.0f;  // Open Gaze reports validity, not confidence
      sample.arrival_ns = now;
      out.push_back(sample);
    } else if (tag_.name == "REC") {
      ++malformed_;  // a REC without usable BPOG fields
    } else if (tag_.name == "NACK") {
      spdlog::warn("gazepoint refused a command: {}", line_);
    } else if (tag_.name == "ACK") {
      spdlog::debug("gazepoint: {}", line_);
    }
  }
}

void GazepointSource::poll(std::vector<TrackerSample>& out, int timeout_ms) {
  timeout_ms = std::max(timeout_ms, 0);
  switch (state_) {
    case State::kIdle: {
      const std::int64_t wait_ns = next_attempt_ns_ - steadyNowNs();
      if (wait_ns > 0) {
        sleepMs(static_cast<int>(std::min<std::int64_t>(wait_ns / 1'000'000 + 1, timeout_ms)));
        return;
      }
      startConnect();
      if (state_ == State::kConnecting) finishConnect(timeout_ms);
      return;
    }
    case State::kConnecting:
      finishConnect(timeout_ms);
      return;
    case State::kStreaming:
      readRecords(out, timeout_ms);
      return;
  }
}

}  // namespace gaze_bridge
