#include "viewer_options.h"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <map>

#include "net/curve_cli.h"

namespace viewer {

std::optional<int> parseOptions(int argc, char** argv, ViewerOptions& o) {
  CLI::App app{
      "sph_viewer: renders frames from sph_server, reports its camera pose (the screen the gaze "
      "refers to) and sends Control requests. Mouse: left drag orbits, right or middle drag (or "
      "shift + left) pans, wheel zooms. Keys: R resets the view, space pauses/resumes the server, "
      "H hides the panel, Esc quits."};
  app.get_formatter()->column_width(34);
  app.add_option("--frames-endpoint", o.endpoints.frames, "Frame PUB socket of the server (SUB, newest only)")
      ->capture_default_str();
  app.add_option("--gaze-endpoint", o.endpoints.gaze, "Gaze input of the server (--mouse-gaze sends here)")
      ->capture_default_str();
  app.add_option("--pose-endpoint", o.endpoints.pose, "Camera pose input of the server")->capture_default_str();
  app.add_option("--control-endpoint", o.endpoints.control, "Control ROUTER of the server (DEALER here)")
      ->capture_default_str();
  curve::ClientFiles curve_files;
  curve::addClientOptions(app, curve_files);
  app.add_option("--viewer-id", o.viewer_id, "Id sent with every camera pose (default viewer-<pid>)");
  app.add_option("--width", o.width, "Window width in screen coordinates")
      ->check(CLI::Range(64, 8192))
      ->capture_default_str();
  app.add_option("--height", o.height, "Window height in screen coordinates")
      ->check(CLI::Range(64, 8192))
      ->capture_default_str();
  app.add_flag("--mouse-gaze", o.mouse_gaze, "Send the cursor as gaze (source_id \"mouse\")");
  std::array<float, 2> gaze_at{};
  auto* gaze_at_opt =
      app.add_option("--gaze-at", gaze_at, "Send a fixed gaze point x y (0..1, origin top left) instead of the mouse")
          ->check(CLI::Range(0.0f, 1.0f))
          ->excludes("--mouse-gaze");
  app.add_flag("!--no-panel", o.panel, "Hide the statistics and control panel");
  app.add_flag("!--no-vsync", o.vsync, "Render as fast as possible instead of at the display rate");
  std::map<std::string, RenderMode> renders{{"fluid", RenderMode::kFluid}, {"particles", RenderMode::kParticles}};
  app.add_option("--render", o.render,
                 "fluid (a liquid surface, the default) or particles (spheres by size class, for research)")
      ->transform(CLI::CheckedTransformer(renders, CLI::ignore_case));
  std::map<std::string, RenderDebug> debugs{{"none", RenderDebug::kNone},
                                            {"normals", RenderDebug::kNormals},
                                            {"depth", RenderDebug::kDepth},
                                            {"thickness", RenderDebug::kThickness}};
  app.add_option("--render-debug", o.render_debug,
                 "Encode a pass instead of shading: normals (view space as RGB), depth or thickness (metres as "
                 "24-bit fixed point; thickness in fluid mode only); see README")
      ->transform(CLI::CheckedTransformer(debugs, CLI::ignore_case));
  app.add_option("--fluid-scale", o.fluid_scale,
                 "Fluid passes at 1/N of the resolution each way (default: 2 on software GL, 1 on a GPU)")
      ->check(CLI::Range(1, 4));
  std::map<std::string, ColourMode> colours{{"class", ColourMode::kSizeClass}, {"speed", ColourMode::kSpeed}};
  app.add_option("--colour,--color", o.colour,
                 "Particles mode colour: class (SMALL blue, LARGE red) or speed (needs velocities in frames)")
      ->transform(CLI::CheckedTransformer(colours, CLI::ignore_case));
  std::array<float, 3> eye{}, target{};
  auto* eye_opt = app.add_option("--eye", eye, "Camera eye x y z (default: the scene's camera)");
  auto* target_opt = app.add_option("--target", target, "Camera target x y z");
  app.add_option("--fov", o.fov_y_degrees, "Vertical field of view, degrees")
      ->check(CLI::Range(5.0f, 150.0f))
      ->capture_default_str();
  app.add_option("--snapshot", o.snapshot, "Write the picture to this PNG and exit (hidden window)");
  bool visible_flag = false;
  auto* visible_opt = app.add_flag("--visible", visible_flag, "Show the window even with --snapshot");
  app.add_option("--frames", o.frames, "Server frames to show before the snapshot or exit (0: no limit)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  auto* at_opt = app.add_option("--snapshot-at", o.snapshot_at_s,
                                "With --snapshot: take it at the first frame of at least this sim time (s), not "
                                "after --frames")
                     ->check(CLI::NonNegativeNumber);
  auto* timeout_opt =
      app.add_option("--timeout", o.timeout_s, "Give up after this many seconds (exit 3; default 30 with --snapshot)")
          ->check(CLI::NonNegativeNumber);
  app.add_flag("--report", o.report, "Print render rate and frame-arrival-to-pixels times on exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    o.endpoints.curve = curve::loadClientFiles(curve_files);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph_viewer: %s\n", e.what());
    return 2;
  }
  if (gaze_at_opt->count() > 0) o.gaze_at = gaze_at;
  if (eye_opt->count() > 0) o.eye = eye;
  if (target_opt->count() > 0) o.target = target;
  if (o.eye.has_value() != o.target.has_value()) {
    std::fprintf(stderr, "sph_viewer: --eye and --target go together\n");
    return 2;
  }
  if (o.render_debug == RenderDebug::kThickness && o.render != RenderMode::kFluid) {
    std::fprintf(stderr, "sph_viewer: --render-debug thickness needs --render fluid\n");
    return 2;
  }
  if (o.viewer_id.empty()) o.viewer_id = "viewer-" + std::to_string(::getpid());
  if (!o.snapshot.empty()) {
    o.visible = visible_opt->count() > 0;
    if (timeout_opt->count() == 0) o.timeout_s = 30.0;
    if (o.frames == 0 && at_opt->count() == 0) o.frames = 1;
  }
  return std::nullopt;
}

}  // namespace viewer
