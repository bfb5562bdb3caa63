#include "test_publisher.h"

namespace viewer_test {

namespace {

std::string bindEphemeral(zmq::socket_t& s) {
  s.bind("tcp://127.0.0.1:*");
  return s.get(zmq::sockopt::last_endpoint);
}

template <typename T>
bool waitFor(std::mutex& mutex, const std::vector<T>& items, const std::function<bool(const T&)>& predicate,
             std::chrono::milliseconds timeout, T* out) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    {
      std::lock_guard lock(mutex);
      for (auto it = items.rbegin(); it != items.rend(); ++it) {
        if (predicate(*it)) {
          if (out != nullptr) *out = *it;
          return true;
        }
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}
}  // namespace

TestServer::TestServer(gsph::v1::Frame frame, const std::string& frames_endpoint, std::uint64_t first_sequence,
                       std::chrono::milliseconds publish_period, std::uint64_t max_frames)
    : frame_(std::move(frame)), sequence_(first_sequence), publish_period_(publish_period), frames_left_(max_frames) {
  for (zmq::socket_t* s : {&frames_, &pose_, &gaze_, &control_}) s->set(zmq::sockopt::linger, 0);
  if (frames_endpoint.empty()) {
    frames_endpoint_ = bindEphemeral(frames_);
  } else {
    frames_.bind(frames_endpoint);
    frames_endpoint_ = frames_endpoint;
  }
  pose_.set(zmq::sockopt::subscribe, "");
  gaze_.set(zmq::sockopt::subscribe, "");
  pose_endpoint_ = bindEphemeral(pose_);
  gaze_endpoint_ = bindEphemeral(gaze_);
  control_endpoint_ = bindEphemeral(control_);
  thread_ = std::thread([this] { run(); });
}

TestServer::~TestServer() {
  running_ = false;
  thread_.join();
}

std::vector<std::string> TestServer::endpointArgs() const {
  return {"--frames-endpoint", frames_endpoint_, "--pose-endpoint",    pose_endpoint_,
          "--gaze-endpoint",   gaze_endpoint_,   "--control-endpoint", control_endpoint_};
}

void TestServer::replaceFrame(gsph::v1::Frame frame) {
  std::lock_guard lock(mutex_);
  frame_ = std::move(frame);
}

std::size_t TestServer::posesReceived() const {
  std::lock_guard lock(mutex_);
  return poses_.size();
}

std::vector<gsph::v1::Control> TestServer::controlsReceived() const {
  std::lock_guard lock(mutex_);
  return controls_;
}

bool TestServer::waitForPose(const std::function<bool(const gsph::v1::CameraPose&)>& predicate,
                             std::chrono::milliseconds timeout, gsph::v1::CameraPose* out) {
  return waitFor(mutex_, poses_, predicate, timeout, out);
}

bool TestServer::waitForGaze(const std::function<bool(const gsph::v1::GazeSample&)>& predicate,
                             std::chrono::milliseconds timeout, gsph::v1::GazeSample* out) {
  return waitFor(mutex_, gaze_samples_, predicate, timeout, out);
}

void TestServer::run() {
  auto next_publish = std::chrono::steady_clock::now();
  std::string bytes;
  while (running_) {
    zmq::pollitem_t items[] = {{frames_.handle(), 0, ZMQ_POLLIN, 0},
                               {pose_.handle(), 0, ZMQ_POLLIN, 0},
                               {gaze_.handle(), 0, ZMQ_POLLIN, 0},
                               {control_.handle(), 0, ZMQ_POLLIN, 0}};
    zmq::poll(items, 4, std::chrono::milliseconds(5));
    zmq::message_t m;
    if ((items[0].revents & ZMQ_POLLIN) && frames_.recv(m, zmq::recv_flags::dontwait)) {
      // XPUB: first byte 1 = subscribe; the viewer subscribes to everything.
      if (m.size() >= 1 && static_cast<const char*>(m.data())[0] == 1) subscribed_ = true;
    }
    if ((items[1].revents & ZMQ_POLLIN) && pose_.recv(m, zmq::recv_flags::dontwait)) {
      gsph::v1::CameraPose pose;
      if (pose.ParseFromArray(m.data(), static_cast<int>(m.size()))) {
        std::lock_guard lock(mutex_);
        poses_.push_back(pose);
      }
    }
    if ((items[2].revents & ZMQ_POLLIN) && gaze_.recv(m, zmq::recv_flags::dontwait)) {
      gsph::v1::GazeSample sample;
      if (sample.ParseFromArray(m.data(), static_cast<int>(m.size()))) {
        std::lock_guard lock(mutex_);
        gaze_samples_.push_back(sample);
      }
    }
    if (items[3].revents & ZMQ_POLLIN) {
      zmq::message_t identity, payload;
      if (control_.recv(identity, zmq::recv_flags::dontwait) && identity.more() &&
          control_.recv(payload, zmq::recv_flags::dontwait)) {
        gsph::v1::Control request;
        gsph::v1::ControlReply reply;
        reply.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
        if (request.ParseFromArray(payload.data(), static_cast<int>(payload.size()))) {
          reply.set_request_id(request.request_id());
          reply.set_ok(true);
          reply.mutable_status()->set_scene("viewer_test");
          reply.mutable_status()->add_scenes("viewer_test");
          std::lock_guard lock(mutex_);
          controls_.push_back(request);
        }
        reply.SerializeToString(&bytes);
        control_.send(identity, zmq::send_flags::sndmore | zmq::send_flags::dontwait);
        control_.send(zmq::buffer(bytes), zmq::send_flags::dontwait);
      }
    }
    const auto now = std::chrono::steady_clock::now();
    if (subscribed_ && frames_left_ > 0 && now >= next_publish) {
      --frames_left_;
      {
        std::lock_guard lock(mutex_);
        frame_.set_sim_time(0.01 * static_cast<double>(sequence_));  // as makeFrame numbers them
        frame_.set_sequence(sequence_++);
        frame_.SerializeToString(&bytes);
      }
      frames_.send(zmq::buffer(bytes), zmq::send_flags::dontwait);
      next_publish = now + publish_period_;
    }
  }
}

}  // namespace viewer_test
