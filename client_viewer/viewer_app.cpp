#include "viewer_app.h"

#include <epoxy/gl.h>
// epoxy first: GLFW must not pull in the system GL header
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>

#include "camera_input.h"
#include "line_renderer.h"
#include "particle_renderer.h"
#include "png_image.h"
#include "render_target.h"
#include "stats_panel.h"
#include "timing_report.h"

namespace viewer {

std::atomic<bool> g_stop_requested{false};

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kServerSilence = std::chrono::seconds(2);         // then "waiting for server" again
constexpr auto kMouseGazePeriod = std::chrono::milliseconds(8);  // ~120 Hz at most

double millisSince(Clock::time_point t, Clock::time_point now) {
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

int runViewer(const ViewerOptions& options) {
  glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); });
  if (!glfwInit()) {
    std::fprintf(stderr, "sph_viewer: cannot start GLFW (no display? run under xvfb-run, or use --snapshot there)\n");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
  const std::string title = "sph_viewer " + options.viewer_id;  // tests find the window by it
  GLFWwindow* window = glfwCreateWindow(options.width, options.height, title.c_str(), nullptr, nullptr);
  if (window == nullptr) {
    std::fprintf(stderr, "sph_viewer: cannot open an OpenGL 3.3 core window\n");
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(options.vsync && options.snapshot.empty() ? 1 : 0);

  int exit_code = 0;
  {
    NetworkClient client(options.endpoints, options.viewer_id);
    try {
      client.start();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sph_viewer: cannot connect: %s\n", e.what());
      glfwDestroyWindow(window);
      glfwTerminate();
      return 1;
    }
    WindowEvents events;
    events.install(window);
    CameraInput input(window);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini litter in the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    ParticleRenderer particles;
    LineRenderer lines;
    RenderTarget target;
    StatsPanel panel(client);
    OrbitCamera camera;
    camera.setFovY(options.fov_y_degrees);
    bool camera_ready = false;
    if (options.eye) {
      camera.setEyeTarget({(*options.eye)[0], (*options.eye)[1], (*options.eye)[2]},
                          {(*options.target)[0], (*options.target)[1], (*options.target)[2]});
      camera_ready = true;
    }
    OrbitCamera initial_camera = camera;
    bool show_panel = options.panel;

    std::shared_ptr<const DecodedFrame> frame;
    LineList world_lines, overlay_lines;
    TimingReport report;
    ViewerRates rates;
    int frames_shown = 0;
    const auto started = Clock::now();
    auto last_fps_time = started;
    int renders_since_fps = 0;
    auto last_gaze_time = started - kMouseGazePeriod;
    bool snapshot_done = false;

    while (!glfwWindowShouldClose(window) && !g_stop_requested) {
      glfwPollEvents();
      const auto now = Clock::now();
      bool new_frame = false;
      if (auto incoming = client.takeNewestFrame()) {
        frame = std::move(incoming);
        particles.upload(*frame);
        world_lines.clear();
        appendGeometry(world_lines, frame->geometry);
        new_frame = true;
        if (!camera_ready) {
          initialiseCamera(camera, *frame);
          initial_camera = camera;
          camera_ready = true;
        }
      }
      while (auto reply = client.takeReply()) panel.showReply(*reply);

      // Keys handled here rather than in a callback so they see this frame's state.
      ImGuiIO& io = ImGui::GetIO();
      if (!io.WantCaptureKeyboard) {
        if (events.takeKey(GLFW_KEY_R)) camera = initial_camera;
        if (events.takeKey(GLFW_KEY_SPACE)) panel.togglePause(frame.get());
        if (events.takeKey(GLFW_KEY_H)) show_panel = !show_panel;
        if (events.takeKey(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(window, GLFW_TRUE);
      }
      events.key_count = 0;
      input.update(camera, io.WantCaptureMouse, std::exchange(events.wheel_steps, 0.0));

      int fb_w = 0, fb_h = 0, win_w = 0, win_h = 0;
      glfwGetFramebufferSize(window, &fb_w, &fb_h);
      glfwGetWindowSize(window, &win_w, &win_h);
      if (fb_w <= 0 || fb_h <= 0) {  // minimised: nothing to draw, keep the network going
        glfwWaitEventsTimeout(0.05);
        continue;
      }
      const float aspect = static_cast<float>(fb_w) / static_cast<float>(fb_h);
      const Eigen::Matrix4f view = camera.view();
      const Eigen::Matrix4f projection = camera.projection(aspect);
      PoseData pose;
      std::copy(view.data(), view.data() + 16, pose.view.begin());
      std::copy(projection.data(), projection.data() + 16, pose.projection.begin());
      pose.viewport_width = static_cast<std::uint32_t>(fb_w);
      pose.viewport_height = static_cast<std::uint32_t>(fb_h);
      client.setPose(pose);

      overlay_lines.clear();
      if (frame) appendGazeOverlay(overlay_lines, frame->gaze, aspect);
      if (options.gaze_at && now - last_gaze_time >= kMouseGazePeriod) {
        client.setGaze((*options.gaze_at)[0], (*options.gaze_at)[1], true);
        last_gaze_time = now;
      }
      if (options.mouse_gaze && now - last_gaze_time >= kMouseGazePeriod) {
        double cx = 0.0, cy = 0.0;
        glfwGetCursorPos(window, &cx, &cy);
        const float gx = win_w > 0 ? static_cast<float>(cx / win_w) : -1.0f;
        const float gy = win_h > 0 ? static_cast<float>(cy / win_h) : -1.0f;
        const bool inside = gx >= 0.0f && gx <= 1.0f && gy >= 0.0f && gy <= 1.0f;
        client.setGaze(gx, gy, inside);
        last_gaze_time = now;
        if (inside) appendScreenCross(overlay_lines, gx, gy, 0.008f, aspect, {0.3f, 1.0f, 0.3f});
      }

      target.bind(fb_w, fb_h);
      glClearColor(0.07f, 0.08f, 0.10f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glEnable(GL_DEPTH_TEST);
      if (frame) particles.draw(view, projection, options.colour);
      lines.draw(world_lines, projection * view);
      glDisable(GL_DEPTH_TEST);
      lines.draw(overlay_lines, Eigen::Matrix4f::Identity());

      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      const NetworkStats stats = client.stats();
      if (frame) rates.frame_age_ms = static_cast<float>(systemMicros() - frame->send_time_us) / 1000.0f;
      if (show_panel) panel.draw(frame.get(), stats, rates, options.mouse_gaze || options.gaze_at);
      if (!stats.last_frame_arrival) {
        drawCentredText(("waiting for server at " + options.endpoints.frames).c_str());
      } else if (now - *stats.last_frame_arrival > kServerSilence) {
        drawCentredText("server silent: waiting for server (reconnecting)");
      }
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

      if (new_frame) ++frames_shown;
      const bool frames_done = options.frames > 0 && frames_shown >= options.frames;
      const bool timed_out =
          options.timeout_s > 0.0 && std::chrono::duration<double>(now - started).count() > options.timeout_s;
      if (!options.snapshot.empty() && (frames_done || timed_out)) {
        RgbaImage image{target.width(), target.height(), target.readPixels()};
        std::string error;
        if (!writePng(options.snapshot, image, error)) {
          std::fprintf(stderr, "sph_viewer: %s\n", error.c_str());
          exit_code = 4;
        } else {
          std::fprintf(stderr, "sph_viewer: wrote %s (%dx%d, %d frames)\n", options.snapshot.c_str(), image.width,
                       image.height, frames_shown);
        }
        snapshot_done = true;
      }
      target.blitToWindow();
      glfwSwapBuffers(window);
      report.addRender();
      if (new_frame) {
        // On Mesa's software path the picture is complete when SwapBuffers has handed it to the X
        // server, so this is frame-arrival-to-pixels there.
        const double ms = millisSince(frame->arrival, Clock::now());
        rates.arrival_to_pixels_ms = static_cast<float>(ms);
        report.addArrivalToPixels(ms);
      }
      ++renders_since_fps;
      if (now - last_fps_time >= std::chrono::milliseconds(500)) {
        rates.render_fps =
            static_cast<float>(renders_since_fps / std::chrono::duration<double>(now - last_fps_time).count());
        renders_since_fps = 0;
        last_fps_time = now;
      }
      if (timed_out && exit_code == 0) {
        std::fprintf(stderr, "sph_viewer: timeout after %.1f s with %d of %d frames\n", options.timeout_s, frames_shown,
                     options.frames);
        exit_code = 3;
      }
      if (snapshot_done || frames_done || timed_out) break;
    }
    if (options.report) report.print(std::chrono::duration<double>(Clock::now() - started).count());
    client.stop();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }  // GL objects die here, while the context is still current
  glfwDestroyWindow(window);
  glfwTerminate();
  return exit_code;
}

}  // namespace viewer
