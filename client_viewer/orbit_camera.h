// The viewer's camera: orbit about a target, zoom by distance, pan the target. Produces the OpenGL
// view and projection matrices (column-major) that are both drawn with and sent to the server as the
// CameraPose, so the screen the gaze refers to is exactly the screen the user sees.
#pragma once

#include <Eigen/Core>

namespace viewer {

// gluLookAt / gluPerspective equivalents (right-handed, camera looks down -z, depth -1..1).
Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up);
Eigen::Matrix4f perspective(float fov_y_degrees, float aspect, float near_plane, float far_plane);

class OrbitCamera {
 public:
  // Places the eye at `eye` looking at `target` (world up is +y).
  void setEyeTarget(const Eigen::Vector3f& eye, const Eigen::Vector3f& target);
  // Frames an axis-aligned box: looks at its centre from the front (+z), a little from above.
  void frameBox(const Eigen::Vector3f& box_min, const Eigen::Vector3f& box_max);
  // Adopts a camera given as a view matrix (e.g. the scene's default pose from the server); the
  // orbit target is put `target_distance` in front of the eye. False (and nothing changes) when the
  // matrix is not a finite rigid transform.
  bool adoptView(const Eigen::Matrix4f& view, float target_distance);

  // Mouse gestures in pixels: drag to orbit, drag to pan, wheel steps to zoom.
  void orbit(float dx_pixels, float dy_pixels);
  void pan(float dx_pixels, float dy_pixels, int viewport_height);
  void zoom(float wheel_steps);

  void setFovY(float degrees) { fov_y_degrees_ = degrees; }
  void setClipPlanes(float near_plane, float far_plane);

  Eigen::Vector3f eye() const;
  const Eigen::Vector3f& target() const { return target_; }
  float distance() const { return distance_; }
  float fovY() const { return fov_y_degrees_; }
  Eigen::Matrix4f view() const;
  Eigen::Matrix4f projection(float aspect) const;

 private:
  Eigen::Vector3f target_ = Eigen::Vector3f(0.5f, 0.3f, 0.4f);
  float distance_ = 2.5f;
  float yaw_ = 0.0f;     // radians about +y; 0 looks from +z towards -z
  float pitch_ = 0.35f;  // radians above the horizon
  float fov_y_degrees_ = 45.0f;
  float near_ = 0.02f;
  float far_ = 100.0f;
};

}  // namespace viewer
