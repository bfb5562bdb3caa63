#include "camera_input.h"

namespace viewer {

WindowEvents::WindowEvents(GLFWwindow* window) {
  // GLFW has one user pointer per window; it holds this object.
  glfwSetWindowUserPointer(window, this);
  glfwSetScrollCallback(window, [](GLFWwindow* w, double /*x*/, double y) {
    static_cast<WindowEvents*>(glfwGetWindowUserPointer(w))->wheel_steps += y;
  });
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int /*scancode*/, int action, int /*mods*/) {
    auto* self = static_cast<WindowEvents*>(glfwGetWindowUserPointer(w));
    if (action == GLFW_PRESS && self->key_count < 16) self->keys_pressed[self->key_count++] = key;
  });
}

bool WindowEvents::takeKey(int key) {
  for (int i = 0; i < key_count; ++i) {
    if (keys_pressed[i] == key) {
      keys_pressed[i] = keys_pressed[--key_count];
      return true;
    }
  }
  return false;
}

CameraInput::CameraInput(GLFWwindow* window) : window_(window) { glfwGetCursorPos(window, &last_x_, &last_y_); }

void CameraInput::update(OrbitCamera& camera, bool panel_has_mouse, double wheel_steps) {
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window_, &x, &y);
  const float dx = static_cast<float>(x - last_x_);
  const float dy = static_cast<float>(y - last_y_);
  last_x_ = x;
  last_y_ = y;

  const bool left = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  const bool right = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  const bool middle = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  const bool shift =
      glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  const bool any = left || right || middle;
  // A drag that starts over the panel belongs to the panel until the button is released.
  if (!any) {
    dragging_ = false;
  } else if (!dragging_ && !panel_has_mouse) {
    dragging_ = true;
  }
  if (dragging_ && (dx != 0.0f || dy != 0.0f)) {
    if (right || middle || (left && shift)) {
      int fb_w = 0, fb_h = 0, win_w = 0, win_h = 0;
      glfwGetFramebufferSize(window_, &fb_w, &fb_h);
      glfwGetWindowSize(window_, &win_w, &win_h);
      camera.pan(dx, dy, win_h > 0 ? win_h : fb_h);
    } else {
      camera.orbit(dx, dy);
    }
  }
  if (wheel_steps != 0.0 && !panel_has_mouse) camera.zoom(static_cast<float>(wheel_steps));
}

}  // namespace viewer
