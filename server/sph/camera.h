// The viewer's camera as the gaze method sees it: view and projection matrices (OpenGL conventions,
// column vectors, camera looking down -z) and a viewport in pixels. Screen coordinates are
// normalized to 0..1 with the origin at the top left, as gaze samples are (DESIGN.md section 6).
#pragma once

#include <Eigen/Core>

#include "sph/scene.h"

namespace sph {

struct ScreenCamera {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d projection = Eigen::Matrix4d::Identity();
  int viewport_width = 1280;
  int viewport_height = 720;
};

// gluLookAt / gluPerspective equivalents.
Eigen::Matrix4d lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                       const Eigen::Vector3d& up);
Eigen::Matrix4d perspective(double fov_y_degrees, double aspect, double near_plane,
                            double far_plane);
// The scene's default camera.
ScreenCamera cameraFromSpec(const CameraSpec& spec);
// False when a matrix entry is not finite or the viewport is empty.
bool isUsable(const ScreenCamera& camera);

// A sphere projected to the screen: centre normalized (0..1, origin top left) and radius as a
// fraction of the viewport width. `in_front` is false when the centre lies behind the eye.
struct ScreenDisc {
  double x = 0.0;
  double y = 0.0;
  double radius = 0.0;
  bool in_front = false;
};

// Precomputed rows of view-projection so the per-particle projection is a few multiply-adds.
class Projector {
 public:
  explicit Projector(const ScreenCamera& camera);
  ScreenDisc project(const Eigen::Vector3d& center, double radius) const;
  // The same projection in single precision, for the gaze decision over every particle each step
  // (a third of the cost of the double form there); agrees with project() to about 1e-6 of the width.
  ScreenDisc projectFast(const Eigen::Vector3f& center, float radius) const;
  double aspect() const { return aspect_; }  // width / height

 private:
  Eigen::Matrix4d view_projection_;
  Eigen::Vector4d view_depth_row_;  // row 2 of the view matrix: view-space z
  double focal_over_width_ = 1.0;   // projection(1,1) * height / 2 / width
  double aspect_ = 1.0;
  // Rows x, y, w of view-projection and the depth row, in float.
  Eigen::Vector4f row_x_, row_y_, row_w_, depth_row_;
  float focal_over_width_f_ = 1.0f;
};

}  // namespace sph
