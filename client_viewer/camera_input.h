// Mouse and keyboard to camera: left drag orbits, right/middle drag (or shift + left) pans, the
// wheel zooms. Ignores the mouse while the panel has it.
#pragma once

#include <GLFW/glfw3.h>

#include "orbit_camera.h"

namespace viewer {

class CameraInput {
 public:
  explicit CameraInput(GLFWwindow* window);
  // Applies the mouse movement since the last call and `wheel_steps` of scrolling;
  // `panel_has_mouse` from ImGui's WantCaptureMouse.
  void update(OrbitCamera& camera, bool panel_has_mouse, double wheel_steps);

 private:
  GLFWwindow* window_;
  double last_x_ = 0.0;
  double last_y_ = 0.0;
  bool dragging_ = false;
};

// Events that must not be missed between two polls (a quick key tap, wheel steps), collected by
// GLFW callbacks, installed by the constructor. Make it before ImGui installs its callbacks: ImGui
// chains to these. Must not move (the window keeps a pointer to it).
struct WindowEvents {
  explicit WindowEvents(GLFWwindow* window);
  WindowEvents(const WindowEvents&) = delete;
  WindowEvents& operator=(const WindowEvents&) = delete;
  double wheel_steps = 0.0;
  int keys_pressed[16] = {};
  int key_count = 0;
  bool takeKey(int key);  // true if `key` was pressed since the last take
};

}  // namespace viewer
