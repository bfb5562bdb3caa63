// The simulation thread: owns the SimSession and the encoder, steps in wall-clock time (or free-run),
// applies control requests and camera poses between steps, hands the freshest gaze to the controller
// just before each adaptive step, and publishes frames at the configured rate through SimOutbox.
// It never touches a network socket, so nothing a peer does can make a step wait.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/control_executor.h"
#include "app/publish_pacer.h"
#include "app/realtime_governor.h"
#include "app/sim_session.h"
#include "net/frame_encoder.h"
#include "net/input_mailbox.h"
#include "net/log_throttle.h"
#include "net/net_loop.h"
#include "net/sim_outbox.h"

namespace app {

struct SimLoopOptions {
  std::string scene = "dambreak";
  std::string scene_dir;
  std::optional<sph::Method> method;  // none: the scene's default method
  std::string preset;                 // thesis, pbf, dfsph; empty: each scene's own
  // Checkpoints (sph/checkpoint.h): continue from this one at the start; write one when the loop
  // ends (a stop signal or max_steps). Empty: neither.
  std::string load_state;
  std::string save_state;
  // Adaptive settings by key (sph/param_table.h) over each scene's own "adaptive" block.
  std::map<std::string, double> adaptive_overrides;
  // Simulation parameters by key over every loaded scene's (--param; SimSession::useSimParameters).
  std::map<std::string, double> sim_parameters;
  RunSettings settings;
  bool velocities = false;
  bool neighbor_counts = false;  // per-particle neighbour counts in frames (viewer's spray)
  int threads = 2;
  std::string camera_source;   // empty: the most recent pose from any viewer
  std::int64_t max_steps = 0;  // stop after this many steps of this run (0: run until stopped)
  // Milliseconds added to every step, as a slower machine would take them (tests of the real-time
  // governor at its ceiling; 0: none).
  double slow_step_ms = 0.0;
  double status_interval_s = 5.0;  // periodic one-line status (0: off)
  // At most one line per interval for each kind of refused input (control refusals here, rejected
  // messages in net::RejectionLog).
  std::chrono::milliseconds log_interval{1000};
  // Bound beyond loopback without CURVE (--insecure): said in every status line and ServerStatus.
  bool insecure = false;
  // The foveated method trades its periphery gain to keep simulated time in step with wall time
  // (realtime_governor.h); not in free-run.
  bool realtime_governor = true;
};

// Counters the status line, the control replies and the tests read from other threads.
struct SimCounters {
  std::atomic<std::int64_t> steps{0};
  std::atomic<std::uint64_t> frames_published{0};
  std::atomic<std::uint64_t> frames_dropped{0};
  std::atomic<float> steps_per_second{0.0f};
};

class SimLoop {
 public:
  // Loads the scene (throws when it cannot) in the calling thread.
  SimLoop(zmq::context_t& context, const SimLoopOptions& options, net::InputMailbox& mailbox, const net::NetLoop& net,
          const net::RejectionLog& rejections);
  ~SimLoop();
  SimLoop(const SimLoop&) = delete;
  SimLoop& operator=(const SimLoop&) = delete;

  void start();
  void stop();
  // True once max_steps were run (the last frame is published first).
  bool finished() const { return finished_.load(); }
  const SimCounters& counters() const { return counters_; }
  // After stop(): false when options.save_state was set and the checkpoint could not be written.
  bool stateSaved() const { return state_saved_.load(); }
  // One line: steps/s, particles, subscribers, gaze age, frames, drops, rejected input.
  std::string statusLine() const;

 private:
  using Clock = std::chrono::steady_clock;

  void run();
  void saveState();  // options_.save_state, from the simulation thread as the loop ends
  void handleControls();
  void applyCamera();
  void feedGaze(sph::AdaptiveController& controller);
  // A gaze sample has arrived that no step has used (and the method uses gaze).
  bool gazeWaiting() const;
  void restartClock(Clock::time_point now);
  Clock::time_point nextStepTime() const;
  void publish(Clock::time_point now);
  void fillCounters(gsph::v1::ServerStatus& status) const;
  // For a published frame the eye was measured for (SimSession::measureEye): where the foveated
  // method's gaze point fell, and how much of the visible water was over the perceptual budget
  // (the window's counts).
  void countFoveatedFrame();
  void updateRates(Clock::time_point now);
  void refreshStatusLine(Clock::time_point now);
  // After each governor window: the foveated method's periphery gain for the next.
  void govern(Clock::time_point now, bool running);
  // Logs the governor reaching its ceiling gain, and leaving it, once each time.
  void noteCeiling();

  SimLoopOptions options_;
  net::InputMailbox& mailbox_;
  const net::NetLoop& net_;
  const net::RejectionLog& rejections_;
  net::SimOutbox outbox_;
  net::FrameEncoder encoder_;
  RunSettings settings_;
  SimSession session_;
  ControlTarget control_target_;
  std::vector<net::ControlRequest> requests_;

  // Gaze handed to the controller (echoed in frames), camera pose in use.
  net::GazeEcho gaze_echo_;
  std::uint64_t applied_pose_version_ = 0;
  gsph::v1::CameraPose camera_msg_;

  // Pacing: sim time follows wall time from the anchor on.
  Clock::time_point anchor_wall_{};
  double anchor_sim_ = 0.0;
  PublishPacer pacer_;
  Clock::time_point last_fed_gaze_{};  // arrival of the sample last handed to the controller
  bool step_used_new_gaze_ = false;
  net::LogThrottle refusal_log_;
  Clock::time_point next_status_{};
  Clock::time_point rate_window_start_{};
  std::int64_t rate_window_steps_ = 0;
  // foveated, since the last logged status line: steps, those whose gaze point fell on visible
  // water, and of those the ones that found it at the finest level (AdaptiveStats::fovea_level).
  std::int64_t gaze_frames_ = 0;
  std::int64_t gaze_on_water_frames_ = 0;
  std::int64_t gaze_finest_frames_ = 0;
  // foveated, since the last logged status line: the largest share of the visible particles over
  // the perceptual budget in a step (AdaptiveStats::over_budget).
  double worst_over_budget_ = 0.0;
  // The real-time governor's window: where it started (wall, sim) and the steps' wall time in it.
  RealtimeGovernor governor_;
  Clock::time_point governor_window_start_{};
  double governor_window_sim_ = 0.0;
  Clock::duration governor_busy_{};
  std::atomic<float> realtime_ratio_{0.0f};
  bool at_ceiling_ = false;  // the governor's gain at its ceiling, as last logged
  std::uint64_t frame_sequence_ = 0;

  SimCounters counters_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> finished_{false};
  // The status line is written here and read by other threads (logs, final status).
  mutable std::mutex status_mutex_;
  std::string status_line_;
  std::thread thread_;
  std::atomic<bool> state_saved_{true};
};

}  // namespace app
