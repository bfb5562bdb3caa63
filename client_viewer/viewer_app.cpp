#include "viewer_app.h"

#include <epoxy/gl.h>
// epoxy first: GLFW must not pull in the system GL header
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include "foveation_readout.h"
#include "png_image.h"

namespace viewer {

std::atomic<bool> g_stop_requested{false};

namespace {

constexpr auto kServerSilence = std::chrono::seconds(2);         // then "waiting for server" again
constexpr auto kMouseGazePeriod = std::chrono::milliseconds(8);  // ~120 Hz at most
constexpr auto kLogPeriod = std::chrono::seconds(5);             // the method's figures on stderr

double millisSince(std::chrono::steady_clock::time_point t, std::chrono::steady_clock::time_point now) {
  return std::chrono::duration<double, std::milli>(now - t).count();
}

std::int64_t systemMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// First frame without --eye/--target: use the pose the server's gaze projection used (the scene's
// camera, so recorded gaze lines up), else frame the box.
void initialiseCamera(OrbitCamera& camera, const DecodedFrame& frame) {
  Eigen::Vector3f centre(0.5f, 0.5f, 0.5f);
  if (frame.geometry.has_box) {
    const auto& g = frame.geometry;
    centre = 0.5f * Eigen::Vector3f(g.box_min.x + g.box_max.x, g.box_min.y + g.box_max.y, g.box_min.z + g.box_max.z);
  }
  if (frame.has_camera && frame.camera.view_size() == 16 && frame.camera.projection_size() == 16) {
    const Eigen::Map<const Eigen::Matrix4f> view(frame.camera.view().data());
    const Eigen::Map<const Eigen::Matrix4f> projection(frame.camera.projection().data());
    const Eigen::Vector3f eye = -view.block<3, 3>(0, 0).transpose() * view.block<3, 1>(0, 3);
    if (std::isfinite(projection(1, 1)) && projection(1, 1) > 0.0f) {
      camera.setFovY(2.0f * std::atan(1.0f / projection(1, 1)) * 180.0f / 3.14159265f);
    }
    if (camera.adoptView(view, std::max((centre - eye).norm(), 0.1f))) return;
  }
  if (frame.geometry.has_box) {
    const auto& g = frame.geometry;
    camera.frameBox({g.box_min.x, g.box_min.y, g.box_min.z}, {g.box_max.x, g.box_max.y, g.box_max.z});
  }
}

void drawCentredText(const char* text) {
  const ImVec2 size = ImGui::CalcTextSize(text);
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::GetForegroundDrawList()->AddText(ImVec2(0.5f * (display.x - size.x), 0.5f * (display.y - size.y)),
                                          IM_COL32(230, 230, 230, 255), text);
}

}  // namespace

ViewerApp::ViewerApp(const ViewerOptions& options)
    : options_(options),
      // tests find the window by its title
      window_(options.width, options.height, "sph_viewer " + options.viewer_id, options.visible,
              options.vsync && options.snapshot.empty()),
      client_(options.endpoints, options.viewer_id),
      events_(window_.get()),
      input_(window_.get()),
      imgui_(window_.get()),
      panel_(client_),
      show_panel_(options.panel),
      render_mode_(options.render) {
  client_.start();
  fluid_.setScale(options.fluid_scale > 0 ? options.fluid_scale : defaultFluidScale());
  camera_.setFovY(options.fov_y_degrees);
  if (options.eye) {
    camera_.setEyeTarget({(*options.eye)[0], (*options.eye)[1], (*options.eye)[2]},
                         {(*options.target)[0], (*options.target)[1], (*options.target)[2]});
    camera_ready_ = true;
  }
  initial_camera_ = camera_;
  if (options.study) {
    study_ = std::make_unique<StudyRunner>(*options.study, options.study_out, client_);
    show_panel_ = false;
  }
}

ExitCode ViewerApp::run() {
  std::fprintf(stderr, "sph_viewer: waiting for frames from %s\n", options_.endpoints.frames.c_str());
  started_ = Clock::now();
  last_fps_time_ = started_;
  last_render_ = started_ - std::chrono::hours(1);  // the first picture is due at once
  last_gaze_time_ = started_ - kMouseGazePeriod;
  GLFWwindow* window = window_.get();
  while (!glfwWindowShouldClose(window) && !g_stop_requested) {
    waitForRenderSlot();
    glfwPollEvents();
    const auto now = Clock::now();
    last_render_ = now;
    const bool new_frame = takeFrame();
    while (auto reply = client_.takeReply()) {
      if (study_) {
        study_->onReply(*reply, now);
      } else {
        panel_.showReply(*reply);
      }
    }
    if (study_) study_->update(now, frame_.get(), new_frame);
    handleKeys();

    Viewport vp;
    glfwGetFramebufferSize(window, &vp.fb_w, &vp.fb_h);
    glfwGetWindowSize(window, &vp.win_w, &vp.win_h);
    if (vp.fb_w <= 0 || vp.fb_h <= 0) {  // minimised: nothing to draw, keep the network going
      glfwWaitEventsTimeout(0.05);
      continue;
    }
    sendPose(vp);
    sendGaze(vp, now);
    drawScene(vp);
    drawPanel(now);
    logFigures(now);

    if (new_frame) ++frames_shown_;
    const bool frames_done = options_.frames > 0 && frames_shown_ >= options_.frames;
    const bool timed_out =
        options_.timeout_s > 0.0 && std::chrono::duration<double>(now - started_).count() > options_.timeout_s;
    const bool sim_time_reached = options_.snapshot_at_s >= 0.0 && frame_ && frame_->sim_time >= options_.snapshot_at_s;
    const bool duration_done =
        options_.duration_s > 0.0 && std::chrono::duration<double>(now - started_).count() >= options_.duration_s;
    const bool snapshot_now =
        !options_.snapshot.empty() && (frames_done || sim_time_reached || timed_out || duration_done);
    // No frame, no picture: an empty PNG would pass for the water (the exit code says what happened).
    if (snapshot_now && frames_shown_ > 0) writeSnapshot();
    target_.blitToWindow();
    glfwSwapBuffers(window);
    countRender(new_frame, now);
    if (timed_out && exit_code_ == ExitCode::kOk) {
      if (frames_shown_ == 0) {
        // The usual cause is no server at all: say where the viewer looked, not only that it gave up.
        std::fprintf(stderr,
                     "sph_viewer: no frame from a server at %s within %.1f s (is sph_server running there? "
                     "--frames-endpoint names another); exit code 3\n",
                     options_.endpoints.frames.c_str(), options_.timeout_s);
      } else {
        std::fprintf(stderr, "sph_viewer: timeout after %.1f s with %d of %d frames from %s; exit code 3\n",
                     options_.timeout_s, frames_shown_, options_.frames, options_.endpoints.frames.c_str());
      }
      exit_code_ = ExitCode::kTimeout;
    }
    if (duration_done && frames_shown_ == 0 && exit_code_ == ExitCode::kOk) {
      std::fprintf(stderr, "sph_viewer: no frame from a server at %s within %.1f s; exit code 3\n",
                   options_.endpoints.frames.c_str(), options_.duration_s);
      exit_code_ = ExitCode::kTimeout;
    }
    if (snapshot_now || frames_done || timed_out) break;
    if (study_ && study_->done()) {
      if (study_->failed()) exit_code_ = ExitCode::kStudyFailed;
      break;
    }
  }
  if (options_.report) report_.print(std::chrono::duration<double>(Clock::now() - started_).count());
  client_.stop();
  return exit_code_;
}

void ViewerApp::waitForRenderSlot() {
  if (!(options_.max_fps > 0.0)) return;
  const auto next =
      last_render_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / options_.max_fps));
  // Window events (input, close) still wake the loop; the network thread keeps draining frames.
  for (auto now = Clock::now(); now < next && !g_stop_requested; now = Clock::now()) {
    glfwWaitEventsTimeout(std::chrono::duration<double>(next - now).count());
    if (glfwWindowShouldClose(window_.get())) return;
  }
}

bool ViewerApp::takeFrame() {
  auto incoming = client_.takeNewestFrame();
  if (!incoming) return false;
  frame_ = std::move(incoming);
  particle_buffers_.upload(*frame_);
  fluid_.setGeometry(frame_->geometry);
  world_lines_.clear();
  appendGeometry(world_lines_, frame_->geometry);
  box_lines_.clear();
  appendGeometry(box_lines_, frame_->geometry, /*obstacles=*/false);
  if (!camera_ready_) {
    initialiseCamera(camera_, *frame_);
    initial_camera_ = camera_;
    camera_ready_ = true;
  }
  return true;
}

void ViewerApp::handleKeys() {
  // Keys handled here rather than in a callback so they see this frame's state.
  ImGuiIO& io = ImGui::GetIO();
  if (study_) {
    // The participant answers and may stop; the camera stays where the study began.
    handleStudyKeys(Clock::now());
    events_.key_count = 0;
    return;
  }
  if (!io.WantCaptureKeyboard) {
    if (events_.takeKey(GLFW_KEY_R)) camera_ = initial_camera_;
    if (events_.takeKey(GLFW_KEY_SPACE)) panel_.togglePause(frame_.get());
    if (events_.takeKey(GLFW_KEY_H)) show_panel_ = !show_panel_;
    if (events_.takeKey(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(window_.get(), GLFW_TRUE);
  }
  events_.key_count = 0;
  input_.update(camera_, io.WantCaptureMouse, std::exchange(events_.wheel_steps, 0.0));
}

void ViewerApp::handleStudyKeys(Clock::time_point now) {
  if (events_.takeKey(GLFW_KEY_1) || events_.takeKey(GLFW_KEY_KP_1) || events_.takeKey(GLFW_KEY_S)) {
    study_->answer(1, now);
  }
  if (events_.takeKey(GLFW_KEY_2) || events_.takeKey(GLFW_KEY_KP_2) || events_.takeKey(GLFW_KEY_D)) {
    study_->answer(2, now);
  }
  if (events_.takeKey(GLFW_KEY_ESCAPE)) study_->stop();
}

void ViewerApp::sendPose(const Viewport& vp) {
  view_ = camera_.view();
  projection_ = camera_.projection(vp.aspect());
  PoseData pose;
  std::copy(view_.data(), view_.data() + 16, pose.view.begin());
  std::copy(projection_.data(), projection_.data() + 16, pose.projection.begin());
  pose.viewport_width = static_cast<std::uint32_t>(vp.fb_w);
  pose.viewport_height = static_cast<std::uint32_t>(vp.fb_h);
  client_.setPose(pose);
}

void ViewerApp::sendGaze(const Viewport& vp, Clock::time_point now) {
  overlay_lines_.clear();
  if (frame_ && !hideCues()) appendMethodOverlay(overlay_lines_, *frame_, vp.aspect());
  if (options_.gaze_at && now - last_gaze_time_ >= kMouseGazePeriod) {
    client_.setGaze((*options_.gaze_at)[0], (*options_.gaze_at)[1], true);
    last_gaze_time_ = now;
  }
  if (options_.mouse_gaze && now - last_gaze_time_ >= kMouseGazePeriod) {
    double cx = 0.0, cy = 0.0;
    glfwGetCursorPos(window_.get(), &cx, &cy);
    const float gx = vp.win_w > 0 ? static_cast<float>(cx / vp.win_w) : -1.0f;
    const float gy = vp.win_h > 0 ? static_cast<float>(cy / vp.win_h) : -1.0f;
    const bool inside = gx >= 0.0f && gx <= 1.0f && gy >= 0.0f && gy <= 1.0f;
    client_.setGaze(gx, gy, inside);
    last_gaze_time_ = now;
    if (inside) appendScreenCross(overlay_lines_, gx, gy, 0.008f, vp.aspect(), {0.3f, 1.0f, 0.3f});
  }
}

void ViewerApp::drawScene(const Viewport& vp) {
  target_.bind(vp.fb_w, vp.fb_h);
  const RenderDebug debug = options_.render_debug;
  if (study_ && study_->screen() != StudyRunner::Screen::kFrames) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);  // blank between the intervals and for the question
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    return;
  }
  if (frame_ && render_mode_ == RenderMode::kFluid) {
    fluid_.draw(particle_buffers_, view_, projection_, target_, debug);
  } else {
    if (debug == RenderDebug::kNone) {
      glClearColor(0.07f, 0.08f, 0.10f, 1.0f);
    } else {
      // Debug pictures mark "no particle" as the fluid composite does: black for normals, else white.
      const float c = debug == RenderDebug::kNormals ? 0.0f : 1.0f;
      glClearColor(c, c, c, 1.0f);
    }
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    if (frame_) particles_.draw(particle_buffers_, view_, projection_, options_.colour, debug);
  }
  if (debug == RenderDebug::kNone) drawOutlines();
}

void ViewerApp::drawOutlines() {
  lines_.draw(render_mode_ == RenderMode::kFluid ? box_lines_ : world_lines_, projection_ * view_);
  glDisable(GL_DEPTH_TEST);
  lines_.draw(overlay_lines_, Eigen::Matrix4f::Identity());
}

void ViewerApp::drawPanel(Clock::time_point now) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const NetworkStats stats = client_.stats();
  if (frame_) rates_.frame_age_ms = static_cast<float>(systemMicros() - frame_->send_time_us) / 1000.0f;
  if (show_panel_) panel_.draw(frame_.get(), stats, rates_, options_.mouse_gaze || options_.gaze_at, render_mode_);
  if (study_) {
    // Only the study's own words: a restart's silence is part of the blank, not news.
    if (!study_->prompt().empty()) drawCentredText(study_->prompt().c_str());
  } else if (!stats.last_frame_arrival) {
    drawCentredText(("waiting for server at " + options_.endpoints.frames).c_str());
  } else if (now - *stats.last_frame_arrival > kServerSilence) {
    drawCentredText("server silent: waiting for server (reconnecting)");
  }
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void ViewerApp::writeSnapshot() {
  RgbaImage image{target_.width(), target_.height(), target_.readPixels()};
  std::string error;
  if (!writePng(options_.snapshot, image, error)) {
    std::fprintf(stderr, "sph_viewer: %s\n", error.c_str());
    exit_code_ = ExitCode::kSnapshotFailed;
    return;
  }
  std::fprintf(stderr, "sph_viewer: wrote %s (%dx%d, %d frames)\n", options_.snapshot.c_str(), image.width,
               image.height, frames_shown_);
  if (!options_.panel_text.empty() && frame_) {
    // The panel's figures as text, from the frame the picture shows, for scripts and tests.
    std::FILE* out = std::fopen(options_.panel_text.c_str(), "w");
    if (out == nullptr) {
      std::fprintf(stderr, "sph_viewer: cannot write %s\n", options_.panel_text.c_str());
      exit_code_ = ExitCode::kSnapshotFailed;
      return;
    }
    std::fprintf(out, "particles %zu: %s\n", frame_->particleCount(), levelCountsText(*frame_).c_str());
    for (const std::string& line : foveationLines(*frame_)) std::fprintf(out, "%s\n", line.c_str());
    std::fclose(out);
  }
}

void ViewerApp::logFigures(Clock::time_point now) {
  // A study's log names trials only: an operator's terminal in the participant's view is a cue.
  if (!frame_ || study_ || now < next_log_) return;
  next_log_ = now + kLogPeriod;
  std::fprintf(stderr, "sph_viewer: %s\n", foveationLogLine(*frame_).c_str());
}

void ViewerApp::countRender(bool new_frame, Clock::time_point now) {
  report_.addRender();
  if (new_frame) {
    // On Mesa's software path the picture is complete when SwapBuffers has handed it to the X
    // server, so this is frame-arrival-to-pixels there.
    const double ms = millisSince(frame_->arrival, Clock::now());
    rates_.arrival_to_pixels_ms = static_cast<float>(ms);
    report_.addArrivalToPixels(ms);
  }
  ++renders_since_fps_;
  if (now - last_fps_time_ >= std::chrono::milliseconds(500)) {
    rates_.render_fps =
        static_cast<float>(renders_since_fps_ / std::chrono::duration<double>(now - last_fps_time_).count());
    renders_since_fps_ = 0;
    last_fps_time_ = now;
  }
}

int runViewer(const ViewerOptions& options) {
  try {
    ViewerApp app(options);
    return static_cast<int>(app.run());
  } catch (const StudyOutputError& e) {
    std::fprintf(stderr, "sph_viewer: %s\n", e.what());
  } catch (const WindowError& e) {
    std::fprintf(stderr, "sph_viewer: %s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph_viewer: cannot connect: %s\n", e.what());
  }
  return static_cast<int>(ExitCode::kStartFailed);
}

}  // namespace viewer
