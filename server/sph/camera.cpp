#include "sph/camera.h"

#include <Eigen/Geometry>
#include <cmath>

namespace sph {

Eigen::Matrix4d lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up) {
  const Eigen::Vector3d f = (target - eye).normalized();
  const Eigen::Vector3d s = f.cross(up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4d perspective(double fov_y_degrees, double aspect, double near_plane, double far_plane) {
  const double f = 1.0 / std::tan(fov_y_degrees * M_PI / 360.0);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
  m(2, 3) = 2.0 * far_plane * near_plane / (near_plane - far_plane);
  m(3, 2) = -1.0;
  return m;
}

ScreenCamera cameraFromSpec(const CameraSpec& spec) {
  ScreenCamera c;
  c.view = lookAt(spec.eye, spec.target, spec.up);
  c.viewport_width = spec.viewport_width;
  c.viewport_height = spec.viewport_height;
  c.projection = perspective(spec.fov_y_degrees, static_cast<double>(spec.viewport_width) / spec.viewport_height,
                             spec.near_plane, spec.far_plane);
  return c;
}

bool isUsable(const ScreenCamera& camera) {
  return camera.view.allFinite() && camera.projection.allFinite() && camera.viewport_width > 0 &&
         camera.viewport_height > 0 && camera.projection(1, 1) != 0.0;
}

Projector::Projector(const ScreenCamera& camera)
    : view_projection_(camera.projection * camera.view),
      view_depth_row_(camera.view.row(2).transpose()),
      aspect_(static_cast<double>(camera.viewport_width) / camera.viewport_height) {
  // A sphere of radius r at view depth z covers r * P11 / z of the half-height in NDC, i.e.
  // r * P11 * H / (2 z) pixels, i.e. r * P11 / (2 z aspect) of the width.
  focal_over_width_ = camera.projection(1, 1) / (2.0 * aspect_);
  for (int k = 0; k < 4; ++k) {
    fast_.row_x[k] = static_cast<float>(view_projection_(0, k));
    fast_.row_y[k] = static_cast<float>(view_projection_(1, k));
    fast_.row_w[k] = static_cast<float>(view_projection_(3, k));
    fast_.depth_row[k] = static_cast<float>(-view_depth_row_[k]);
  }
  fast_.focal_over_width = static_cast<float>(focal_over_width_);
}

ScreenDisc Projector::project(const Eigen::Vector3d& center, double radius) const {
  ScreenDisc d;
  const Eigen::Vector4d p(center.x(), center.y(), center.z(), 1.0);
  const Eigen::Vector4d clip = view_projection_ * p;
  const double depth = -view_depth_row_.dot(p);  // distance in front of the eye along -z
  if (!(clip.w() > 0.0) || !(depth > 0.0)) return d;
  d.in_front = true;
  d.x = 0.5 * (clip.x() / clip.w() + 1.0);
  d.y = 0.5 * (1.0 - clip.y() / clip.w());  // NDC y points up; screen y points down
  d.radius = radius * focal_over_width_ / depth;
  return d;
}

}  // namespace sph
