// gaze_bridge's command line (CLI11): every option lands in BridgeOptions; makeSource builds the named
// source. Kept apart from main() so tests can parse command lines without starting a process.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <zmq.hpp>

#include "bridge.h"
#include "gaze/fixation_model.h"
#include "gazepoint_source.h"
#include "net/curve_setup.h"
#include "pupil_source.h"

namespace gaze_bridge {

struct BridgeOptions {
  std::string source = "synthetic";  // synthetic | replay | pupil | gazepoint | tobii
  BridgeParams bridge;
  PupilParams pupil;
  GazepointParams gazepoint;
  double tracker_timeout_s = 2.0;
  std::string replay_path;
  double replay_speed = 1.0;
  bool replay_once = false;
  gaze::FixationModelParams synthetic;
  std::string socket = "pub";  // pub | push
  bool no_filter = false;
  double duration_s = 0.0;  // 0: until SIGINT/SIGTERM
  std::string log_level = "info";
  curve::ClientFiles curve;  // read into bridge.publisher.curve by finishBridgeOptions
};

void addBridgeOptions(CLI::App& app, BridgeOptions& options);

// Completes the parameters after parsing (socket kind, filter switch, timeouts) and checks them;
// throws std::invalid_argument with a message for the user.
void finishBridgeOptions(BridgeOptions& options);

// Builds the chosen source; throws std::invalid_argument (unknown or unavailable source) or
// gaze::GazeFormatError (bad recording).
std::unique_ptr<GazeSource> makeSource(zmq::context_t& context, const BridgeOptions& options);

}  // namespace gaze_bridge
