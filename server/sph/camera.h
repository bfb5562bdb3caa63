// The viewer's camera as the gaze method sees it: view and projection matrices (OpenGL conventions,
// column vectors, camera looking down -z) and a viewport in pixels. Screen coordinates are
// normalized to 0..1 with the origin at the top left, as gaze samples are (docs/design.md section 6).
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
Eigen::Matrix4d lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up);
Eigen::Matrix4d perspective(double fov_y_degrees, double aspect, double near_plane, double far_plane);
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

// The same in single precision (Projector::projectFast). `in_front` is 0 or 1: GCC 12 does not
// vectorise a loop over a struct with a bool member.
struct FastScreenDisc {
  float x = 0.0f;
  float y = 0.0f;
  float radius = 0.0f;
  int in_front = 0;
};

// Projector's rows in single precision, for the gaze decision over every particle each step;
// agrees with Projector::project to about 1e-6 of the width. Plain floats, inline and branch-free,
// so that a loop over the particles vectorises (behind the eye, x, y and radius are meaningless;
// in_front says so).
struct FastProjection {
  float row_x[4], row_y[4], row_w[4], depth_row[4];
  float focal_over_width = 1.0f;

  FastScreenDisc project(float x, float y, float z, float radius) const {
    const auto dot = [&](const float(&row)[4]) { return row[0] * x + row[1] * y + row[2] * z + row[3]; };
    const float w = dot(row_w);
    const float depth = dot(depth_row);
    const float inv_w = 1.0f / w;
    FastScreenDisc d;
    d.in_front = (w > 0.0f) & (depth > 0.0f);
    d.x = 0.5f * (dot(row_x) * inv_w + 1.0f);
    d.y = 0.5f * (1.0f - dot(row_y) * inv_w);
    d.radius = radius * focal_over_width / depth;
    return d;
  }
};

// Precomputed rows of view-projection so the per-particle projection is a few multiply-adds.
class Projector {
 public:
  explicit Projector(const ScreenCamera& camera);
  ScreenDisc project(const Eigen::Vector3d& center, double radius) const;
  // The same projection in single precision (FastProjection).
  FastScreenDisc projectFast(const Eigen::Vector3f& c, float radius) const {
    return fast_.project(c.x(), c.y(), c.z(), radius);
  }
  const FastProjection& fast() const { return fast_; }
  double aspect() const { return aspect_; }  // width / height

 private:
  Eigen::Matrix4d view_projection_;
  Eigen::Vector4d view_depth_row_;  // row 2 of the view matrix: view-space z
  double focal_over_width_ = 1.0;   // projection(1,1) * height / 2 / width
  double aspect_ = 1.0;
  FastProjection fast_;
};

}  // namespace sph
