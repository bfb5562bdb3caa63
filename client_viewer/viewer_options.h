// Command-line options of sph_viewer (CLI11). Every option is listed by --help.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "network_client.h"
#include "particle_renderer.h"
#include "render_settings.h"
#include "study_plan.h"

namespace viewer {

struct ViewerOptions {
  Endpoints endpoints;
  std::string viewer_id;  // default "viewer-<pid>"
  int width = 1280;
  int height = 720;
  bool mouse_gaze = false;
  std::optional<std::array<float, 2>> gaze_at;  // a fixed gaze point (demos, screenshots)
  bool panel = true;
  bool vsync = true;
  double max_fps = 0.0;  // renders at most this many pictures a second (0: no cap beyond vsync)
  RenderMode render = RenderMode::kFluid;
  RenderDebug render_debug = RenderDebug::kNone;
  int fluid_scale = 0;  // fluid passes at 1 / this resolution; 0: by the GL (defaultFluidScale())
  ColourMode colour = ColourMode::kSizeClass;  // particles mode
  // Camera: the scene's pose from the first frame unless --eye/--target are given.
  std::optional<std::array<float, 3>> eye;
  std::optional<std::array<float, 3>> target;
  float fov_y_degrees = 45.0f;
  // Headless / scripted runs
  std::string snapshot;         // PNG path; implies a hidden window unless --visible
  std::string panel_text;       // with --snapshot: the panel's figures as text here too
  bool visible = true;          // resolved: false for --snapshot unless --visible was given
  int frames = 0;               // server frames to show before the snapshot / exit (0: run until closed)
  double snapshot_at_s = -1.0;  // with --snapshot: at the first frame of this sim time instead (< 0: off)
  double duration_s = 0.0;      // with --snapshot: take it after this much wall time (0: off)
  double timeout_s = 0.0;       // give up after this long (0: never; --snapshot defaults to 30)
  bool report = false;          // print render rate and frame-arrival-to-pixels figures on exit
  // A blind comparison study (--study): the plan, checked, and where its results go.
  std::optional<StudyPlan> study;
  std::string study_out;
};

// Parses argv. Returns std::nullopt to go on, or an exit code (0 after --help, 2 on a bad option)
// after printing to stdout/stderr.
std::optional<int> parseOptions(int argc, char** argv, ViewerOptions& options);

}  // namespace viewer
