// Loopback emulators of the two real tracker protocols, speaking just enough of each for the bridge:
//  - PupilEmulator: Pupil Remote (REP answering "SUB_PORT") and the IPC backbone's PUB, on which the
//    test publishes "surfaces.<name>" messages with msgpack payloads (several gaze samples each).
//  - GazepointEmulator: an Open Gaze API TCP server that ACKs SET commands and writes whatever the test
//    queues, cut into small pieces so records arrive split across reads; it can drop its client.
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>
#include <zmq.hpp>

namespace gaze_bridge_test {

struct PupilGaze {
  double x = 0, y = 0;  // Pupil's norm_pos: origin bottom-left
  double confidence = 1.0;
  bool on_surf = true;
  double timestamp = 0.0;
};

// msgpack payload of a surfaces.<name> message.
std::string packSurfaceMessage(const std::string& surface, const std::vector<PupilGaze>& gaze);

class PupilEmulator {
 public:
  // remote_port 0: any free port.
  PupilEmulator(zmq::context_t& context, int remote_port = 0);
  ~PupilEmulator();
  int remotePort() const { return remote_port_; }
  int pubPort() const { return pub_port_; }
  int portRequests() const { return port_requests_.load(); }
  // Sends a two-part message: topic, msgpack payload.
  void publish(const std::string& topic, const std::string& payload);

 private:
  void serveRemote();
  zmq::socket_t pub_;
  zmq::socket_t remote_;
  int remote_port_ = 0;
  int pub_port_ = 0;
  std::atomic<bool> stop_{false};
  std::atomic<int> port_requests_{0};
  std::thread thread_;
};

class GazepointEmulator {
 public:
  // port 0: any free port; a given port is re-bound (SO_REUSEADDR) to emulate a restart.
  explicit GazepointEmulator(int port = 0);
  ~GazepointEmulator();
  int port() const { return port_; }
  // Connections accepted so far, and SET commands ACKed on the current connection.
  int connections() const { return connections_.load(); }
  int acked() const { return acked_.load(); }
  std::string commandsReceived();
  // Queues text for the current client; it is written in pieces of 1, 2, 3, ... 13 bytes.
  void send(const std::string& text);
  // Closes the current client connection (the listener stays).
  void dropClient() { drop_.store(true); }

 private:
  void serve();
  int listen_fd_ = -1;
  int port_ = 0;
  std::atomic<bool> stop_{false};
  std::atomic<bool> drop_{false};
  std::atomic<int> connections_{0};
  std::atomic<int> acked_{0};
  std::mutex mutex_;
  std::deque<std::string> outgoing_;
  std::string commands_;
  std::thread thread_;
};

// `<REC TIME=".." BPOGX=".." BPOGY=".." BPOGV=".." />\r\n`
std::string gazepointRecord(double time_s, double x, double y, bool valid);

}  // namespace gaze_bridge_test
