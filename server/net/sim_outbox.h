// The simulation thread's end of the pipes to the network thread: two inproc PAIR sockets, written
// without ever blocking. A full frame pipe (the network thread is behind) drops the frame and counts
// it, so the step never waits; control replies have their own pipe so frames cannot crowd them out.
#pragma once

#include <cstdint>
#include <string>
#include <zmq.hpp>

#include "net/input_mailbox.h"
#include "proto/sph.pb.h"

namespace net {

class SimOutbox {
 public:
  SimOutbox(zmq::context_t& context, const std::string& frame_pipe, const std::string& reply_pipe);

  // False when the pipe is full and the frame was dropped.
  bool offerFrame(zmq::message_t&& frame);
  void sendReply(const ControlRequest& request, const gsph::v1::ControlReply& reply);

  std::uint64_t framesDropped() const { return frames_dropped_; }

 private:
  zmq::socket_t frames_;
  zmq::socket_t replies_;
  std::uint64_t frames_dropped_ = 0;
};

}  // namespace net
