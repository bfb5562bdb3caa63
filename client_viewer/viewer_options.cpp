#include "viewer_options.h"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <map>

#include "cli/cli_conventions.h"
#include "net/curve_cli.h"

namespace viewer {

std::optional<int> parseOptions(int argc, char** argv, ViewerOptions& o) {
  CLI::App app{
      "sph_viewer: renders frames from sph_server, reports its camera pose (the screen the gaze "
      "refers to) and sends Control requests. Mouse: left drag orbits, right or middle drag (or "
      "shift + left) pans, wheel zooms. Keys: R resets the view, space pauses/resumes the server, "
      "H hides the panel, Esc quits."};
  cli::prepare(app, "sph_viewer",
               "3 timed out: no frame from the server within --timeout or --duration; 4 the snapshot could not "
               "be written; 5 --study: the server lacks a scene or setting the study names, or refused a request");
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
      ->check(cli::range(64, 8192))
      ->capture_default_str();
  app.add_option("--height", o.height, "Window height in screen coordinates")
      ->check(cli::range(64, 8192))
      ->capture_default_str();
  app.add_flag("--mouse-gaze", o.mouse_gaze, "Send the cursor as gaze (source_id \"mouse\")");
  std::array<float, 2> gaze_at{};
  auto* gaze_at_opt =
      app.add_option("--gaze-at", gaze_at, "Send a fixed gaze point x y (0..1, origin top left) instead of the mouse")
          ->check(cli::range(0, 1))
          ->excludes("--mouse-gaze");
  app.add_flag("!--no-panel", o.panel, "Hide the statistics and control panel");
  app.add_flag("!--no-vsync", o.vsync, "Render as fast as possible instead of at the display rate");
  app.add_option("--max-fps", o.max_fps,
                 "Render at most this many pictures a second (0: no cap); software GL sharing the server's cores "
                 "takes them from the simulation")
      ->check(cli::range(0, 1000))
      ->capture_default_str();
  std::map<std::string, RenderMode> renders{{"fluid", RenderMode::kFluid}, {"particles", RenderMode::kParticles}};
  app.add_option("--render", o.render,
                 "fluid (a liquid surface, the default) or particles (spheres by size class, for research)")
      ->transform(CLI::CheckedTransformer(renders, CLI::ignore_case).description("fluid|particles"));
  std::map<std::string, RenderDebug> debugs{{"none", RenderDebug::kNone},
                                            {"normals", RenderDebug::kNormals},
                                            {"depth", RenderDebug::kDepth},
                                            {"thickness", RenderDebug::kThickness}};
  app.add_option("--render-debug", o.render_debug,
                 "Encode a pass instead of shading: normals (view space as RGB), depth or thickness (metres as "
                 "24-bit fixed point; thickness in fluid mode only); see README")
      ->transform(CLI::CheckedTransformer(debugs, CLI::ignore_case).description("none|normals|depth|thickness"));
  app.add_option("--fluid-scale", o.fluid_scale,
                 "Fluid passes at 1/N of the resolution each way (default: 2 on software GL, 1 on a GPU)")
      ->check(cli::range(1, 4));
  std::map<std::string, ColourMode> colours{{"class", ColourMode::kSizeClass}, {"speed", ColourMode::kSpeed}};
  app.add_option("--colour,--color", o.colour,
                 "Particles mode colour: class (L0 blue, L1 red) or speed (needs velocities in frames)")
      ->transform(CLI::CheckedTransformer(colours, CLI::ignore_case).description("class|speed"));
  std::array<float, 3> eye{}, target{};
  auto* eye_opt = app.add_option("--eye", eye, "Camera eye x y z (default: the scene's camera)");
  auto* target_opt = app.add_option("--target", target, "Camera target x y z");
  app.add_option("--fov", o.fov_y_degrees, "Vertical field of view, degrees")
      ->check(cli::range(5, 150))
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
  auto* duration_opt = app.add_option("--duration", o.duration_s,
                                      "With --snapshot: take it after this many seconds of wall time (exit 3 "
                                      "if no frame came by then), not after --frames")
                           ->check(cli::range(0, 86400));
  auto* timeout_opt =
      app.add_option("--timeout", o.timeout_s, "Give up after this many seconds (exit 3; default 30 with --snapshot)")
          ->check(CLI::NonNegativeNumber);
  auto* panel_text_opt =
      app.add_option("--panel-text", o.panel_text, "With --snapshot: also write the panel's figures to this text file");
  std::string study_file;
  auto* study_opt = app.add_option("--study", study_file,
                                   "Run the blind comparison study this JSON file describes (client_viewer/README.md, "
                                   "\"User studies\") and exit");
  app.add_option("--study-out", o.study_out,
                 "With --study: the trials' CSV here, its summary beside it (default: <study name>_<seed>.csv)");
  app.add_flag("--report", o.report, "Print render rate and frame-arrival-to-pixels times on exit");
  if (auto code = cli::parse(app, argc, argv)) return *code;
  try {
    o.endpoints.curve = curve::loadClientFiles(curve_files);
  } catch (const std::exception& e) {
    if (curve::exitCodeFor(e) == cli::kExitFailure) {
      std::fprintf(stderr, "sph_viewer: %s\n", e.what());
      return cli::kExitFailure;
    }
    return cli::usageError(app, e.what());
  }
  if (gaze_at_opt->count() > 0) o.gaze_at = gaze_at;
  if (eye_opt->count() > 0) o.eye = eye;
  if (target_opt->count() > 0) o.target = target;
  if (o.eye.has_value() != o.target.has_value()) {
    return cli::usageError(app, "--eye and --target go together");
  }
  if (o.render_debug == RenderDebug::kThickness && o.render != RenderMode::kFluid) {
    return cli::usageError(app, "--render-debug thickness needs --render fluid");
  }
  if (panel_text_opt->count() > 0 && o.snapshot.empty()) return cli::usageError(app, "--panel-text needs --snapshot");
  if (study_opt->count() > 0) {
    if (!o.snapshot.empty()) return cli::usageError(app, "--study and --snapshot do not go together");
    try {
      o.study = loadStudyPlan(study_file);
    } catch (const StudyFileError& e) {
      return cli::usageError(app, e.what());
    }
  } else if (!o.study_out.empty()) {
    return cli::usageError(app, "--study-out needs --study");
  }
  if (o.viewer_id.empty()) o.viewer_id = "viewer-" + std::to_string(::getpid());
  if (!o.snapshot.empty()) {
    o.visible = visible_opt->count() > 0;
    if (timeout_opt->count() == 0) o.timeout_s = duration_opt->count() > 0 ? 0.0 : 30.0;  // --duration is its own limit
    if (o.frames == 0 && at_opt->count() == 0 && duration_opt->count() == 0) o.frames = 1;
  }
  return std::nullopt;
}

}  // namespace viewer
