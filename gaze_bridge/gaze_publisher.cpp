#include "gaze_publisher.h"

#include <stdexcept>

#include "tracker_sample.h"

namespace gaze_bridge {

GazePublisher::GazePublisher(zmq::context_t& context, const PublisherParams& params, std::string source_id)
    : socket_(context, params.socket == PublisherSocket::kPub ? zmq::socket_type::pub : zmq::socket_type::push) {
  socket_.set(zmq::sockopt::linger, 0);
  // A few samples of queue at most: the server wants the freshest gaze, not a backlog.
  socket_.set(zmq::sockopt::sndhwm, 16);
  socket_.set(zmq::sockopt::reconnect_ivl, 100);
  socket_.set(zmq::sockopt::reconnect_ivl_max, 1000);
  socket_.set(zmq::sockopt::heartbeat_ivl, 1000);
  socket_.set(zmq::sockopt::heartbeat_timeout, 3000);
  if (params.socket == PublisherSocket::kPush) {
    // Queue only on live connections, so samples do not pile up for a server that is down.
    socket_.set(zmq::sockopt::immediate, 1);
  }
  if (params.curve) curve::makeCurveClient(socket_, *params.curve);
  try {
    socket_.connect(params.endpoint);
  } catch (const zmq::error_t& error) {
    throw std::runtime_error("gaze endpoint '" + params.endpoint + "': " + error.what());
  }
  message_.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
  message_.set_source_id(std::move(source_id));
}

bool GazePublisher::send(const ProcessedSample& sample, std::int64_t& bridge_time_us) {
  message_.set_sequence(++sequence_);
  message_.set_tracker_time_s(sample.tracker_time_s);
  message_.set_x(static_cast<float>(sample.x));
  message_.set_y(static_cast<float>(sample.y));
  message_.set_valid(sample.valid);
  message_.set_confidence(sample.confidence);
  message_.set_lost(sample.lost);
  message_.set_fixation(sample.fixation);
  bridge_time_us = systemNowUs();
  message_.set_bridge_time_us(bridge_time_us);
  message_.SerializeToString(&buffer_);
  zmq::send_result_t result;
  try {
    result = socket_.send(zmq::buffer(buffer_), zmq::send_flags::dontwait);
  } catch (const zmq::error_t&) {
    result = std::nullopt;  // EINTR or a context being shut down: drop this sample
  }
  if (!result) {
    ++dropped_;
    return false;
  }
  ++sent_;
  return true;
}

}  // namespace gaze_bridge
