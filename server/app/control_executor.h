// Applies one checked control request (status, pause, resume, reset, load scene, set method, set
// parameters) to the simulation thread's state and builds its reply. Runs on the simulation thread
// between steps. Every error comes back as a reply with an ErrorCode and leaves the state unchanged.
#pragma once

#include <functional>
#include <string>

#include "app/sim_session.h"
#include "proto/sph.pb.h"

namespace app {

// Run settings that control requests may change (besides the session itself).
struct RunSettings {
  bool paused = false;
  bool free_run = false;  // step as fast as possible instead of following wall time
  double publish_hz = 60.0;
  bool quantized = false;  // POSITION_ENCODING_QUANTIZED16 instead of FLOAT32
};

// The one range of publish_hz, for the command line and set_parameters alike: below 0.001 Hz (a
// frame every 17 minutes) is no stream at all, and 1/hz must stay a representable duration.
inline constexpr double kMinPublishHz = 1e-3;
inline constexpr double kMaxPublishHz = 1000.0;
// "" when `hz` is in [kMinPublishHz, kMaxPublishHz], else the error naming publish_hz.
std::string publishHzError(double hz);

struct ControlTarget {
  SimSession& session;
  RunSettings& settings;
  // Fills the counters only the simulation loop and the network thread know (steps/s, subscribers...).
  std::function<void(gsph::v1::ServerStatus&)> fill_counters;
};

// What the loop must do after a request: re-anchor sim time to wall time (the scene restarted,
// pause ended or pacing changed).
struct ControlEffects {
  bool restart_clock = false;
};

gsph::v1::ControlReply executeControl(const gsph::v1::Control& request, ControlTarget& target, ControlEffects& effects);

// The full status: session state, settings, current parameter values and the counters.
void fillStatus(ControlTarget& target, gsph::v1::ServerStatus& status);

}  // namespace app
