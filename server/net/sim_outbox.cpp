#include "net/sim_outbox.h"

namespace net {

SimOutbox::SimOutbox(zmq::context_t& context, const std::string& frame_pipe, const std::string& reply_pipe)
    : frames_(context, zmq::socket_type::pair), replies_(context, zmq::socket_type::pair) {
  frames_.set(zmq::sockopt::linger, 0);
  frames_.set(zmq::sockopt::sndhwm, 2);
  replies_.set(zmq::sockopt::linger, 0);
  // Replies are small and rare; a deep queue means none is lost while the network thread catches up.
  replies_.set(zmq::sockopt::sndhwm, 10000);
  frames_.connect(frame_pipe);
  replies_.connect(reply_pipe);
}

bool SimOutbox::offerFrame(zmq::message_t&& frame) {
  if (frames_.send(frame, zmq::send_flags::dontwait)) return true;
  ++frames_dropped_;
  return false;
}

void SimOutbox::sendReply(const ControlRequest& request, const gsph::v1::ControlReply& reply) {
  const auto more = zmq::send_flags::dontwait | zmq::send_flags::sndmore;
  const std::string bytes = reply.SerializeAsString();
  if (!replies_.send(zmq::buffer(request.identity), more)) return;
  if (request.has_delimiter) (void)replies_.send(zmq::message_t(), more);
  (void)replies_.send(zmq::buffer(bytes), zmq::send_flags::dontwait);
}

}  // namespace net
