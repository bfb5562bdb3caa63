#include "window_session.h"

#include <epoxy/gl.h>
// epoxy first: GLFW must not pull in the system GL header
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdio>

namespace viewer {

GlfwWindow::GlfwWindow(int width, int height, const std::string& title, bool visible, bool vsync) {
  glfwSetErrorCallback(
      [](int code, const char* text) { std::fprintf(stderr, "sph_viewer: GLFW error %d: %s\n", code, text); });
  if (!glfwInit()) {
    // A hidden window (--snapshot) still needs an X server: suggest the one thing that helps.
    throw WindowError(visible
                          ? "cannot start GLFW (no display?): run it under xvfb-run -a, e.g. with --snapshot FILE.png"
                          : "cannot start GLFW (no display?): --snapshot still needs an X server; run it under "
                            "xvfb-run -a");
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    glfwTerminate();
    throw WindowError("cannot open an OpenGL 3.3 core window");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(vsync ? 1 : 0);
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

ImGuiSession::ImGuiSession(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini litter in the working directory
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

ImGuiSession::~ImGuiSession() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

}  // namespace viewer
