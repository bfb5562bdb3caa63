// The window's resources, each released by its owner's destructor in reverse order of creation:
// GLFW and an OpenGL 3.3 core window, then Dear ImGui on that window. Construction throws
// WindowError with a message for the user when a resource cannot be had.
#pragma once

#include <stdexcept>
#include <string>

struct GLFWwindow;

namespace viewer {

struct WindowError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// glfwInit + one window with a current OpenGL 3.3 core context; glfwTerminate on destruction.
class GlfwWindow {
 public:
  GlfwWindow(int width, int height, const std::string& title, bool visible, bool vsync);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;
  GLFWwindow* get() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
};

// ImGui's context and its GLFW + OpenGL 3 backends on `window`.
class ImGuiSession {
 public:
  explicit ImGuiSession(GLFWwindow* window);
  ~ImGuiSession();
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

}  // namespace viewer
