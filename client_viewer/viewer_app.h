// The window and its loop: takes the newest frame from the network thread, draws it offscreen
// (water or particles, outlines, gaze overlay, panel), shows it, and feeds camera pose and mouse
// gaze back.
#pragma once

#include <epoxy/gl.h>
// epoxy first: GLFW (camera_input.h) must not pull in the system GL header

#include <atomic>
#include <chrono>
#include <memory>

#include "camera_input.h"
#include "fluid_renderer.h"
#include "line_renderer.h"
#include "network_client.h"
#include "orbit_camera.h"
#include "particle_buffers.h"
#include "particle_renderer.h"
#include "render_target.h"
#include "stats_panel.h"
#include "study_runner.h"
#include "timing_report.h"
#include "viewer_options.h"
#include "window_session.h"

namespace viewer {

// Set from a signal handler to close the window at the next iteration.
extern std::atomic<bool> g_stop_requested;

// The process exit codes of sph_viewer (also in its --help and README).
enum class ExitCode : int {
  kOk = 0,
  kStartFailed = 1,     // no display, no OpenGL 3.3, or an endpoint that cannot be connected
  kUsage = 2,           // bad command line (viewer_options.cpp)
  kTimeout = 3,         // --timeout passed before --frames frames arrived (a snapshot is still written)
  kSnapshotFailed = 4,  // the snapshot PNG could not be written
  kStudyFailed = 5      // --study: the server lacks a scene or setting the study names, or refused a request
};

class ViewerApp {
 public:
  // Opens the window and connects; throws WindowError or std::exception (ExitCode::kStartFailed).
  explicit ViewerApp(const ViewerOptions& options);
  ExitCode run();

 private:
  using Clock = std::chrono::steady_clock;
  struct Viewport {
    int fb_w = 0, fb_h = 0, win_w = 0, win_h = 0;
    float aspect() const { return static_cast<float>(fb_w) / static_cast<float>(fb_h); }
  };

  // With --max-fps: waits (handling window events) until the next picture is due.
  void waitForRenderSlot();
  bool takeFrame();  // true when a new frame arrived
  void handleKeys();
  void sendPose(const Viewport& vp);
  void sendGaze(const Viewport& vp, Clock::time_point now);
  void drawScene(const Viewport& vp);
  void drawOutlines();
  void drawPanel(Clock::time_point now);
  void writeSnapshot();
  // Every few seconds the method's figures (foveation_readout.h) on stderr.
  void logFigures(Clock::time_point now);
  // A study hides everything that would tell its participant what is shown.
  bool hideCues() const { return study_ != nullptr; }
  void handleStudyKeys(Clock::time_point now);
  void countRender(bool new_frame, Clock::time_point now);

  const ViewerOptions& options_;
  // Declared in order of creation; destroyed in reverse, the GL objects while the context lives.
  GlfwWindow window_;
  NetworkClient client_;
  WindowEvents events_;  // installed before ImGui, which chains to its callbacks
  CameraInput input_;
  ImGuiSession imgui_;
  ParticleBuffers particle_buffers_;
  ParticleRenderer particles_;
  FluidRenderer fluid_;
  LineRenderer lines_;
  RenderTarget target_;
  StatsPanel panel_;
  std::unique_ptr<StudyRunner> study_;  // --study

  OrbitCamera camera_;
  OrbitCamera initial_camera_;
  bool camera_ready_ = false;
  bool show_panel_ = true;
  RenderMode render_mode_ = RenderMode::kFluid;  // the panel switches it
  std::shared_ptr<const DecodedFrame> frame_;
  LineList world_lines_, overlay_lines_;
  LineList box_lines_;  // fluid mode: its backdrop draws the obstacles solid
  Eigen::Matrix4f view_ = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f projection_ = Eigen::Matrix4f::Identity();
  TimingReport report_;
  ViewerRates rates_;
  int frames_shown_ = 0;
  Clock::time_point started_;
  Clock::time_point last_fps_time_;
  Clock::time_point last_render_;  // when the last picture started (--max-fps)
  int renders_since_fps_ = 0;
  Clock::time_point last_gaze_time_;
  Clock::time_point next_log_{};
  ExitCode exit_code_ = ExitCode::kOk;
};

// Runs the viewer; prints why it could not start. Returns the exit code as an int for main().
int runViewer(const ViewerOptions& options);

}  // namespace viewer
