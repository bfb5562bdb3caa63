#include "orbit_camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sph/camera.h"

namespace viewer {

namespace {
constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kMaxPitch = 89.0f * kPi / 180.0f;  // keep away from the pole: lookAt needs up != forward
constexpr float kOrbitRadiansPerPixel = 0.006f;
constexpr float kZoomPerStep = 0.9f;
constexpr float kMinDistance = 0.05f;
constexpr float kMaxDistance = 500.0f;
}  // namespace

// The same matrices the server projects gaze with (sph/camera.h), in the float GL wants.
Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up) {
  return sph::lookAt(eye.cast<double>(), target.cast<double>(), up.cast<double>()).cast<float>();
}

Eigen::Matrix4f perspective(float fov_y_degrees, float aspect, float near_plane, float far_plane) {
  return sph::perspective(fov_y_degrees, aspect, near_plane, far_plane).cast<float>();
}

void OrbitCamera::setEyeTarget(const Eigen::Vector3f& eye, const Eigen::Vector3f& target) {
  const Eigen::Vector3f offset = eye - target;
  const float d = offset.norm();
  if (!(d > 1e-6f) || !std::isfinite(d)) return;
  target_ = target;
  distance_ = std::clamp(d, kMinDistance, kMaxDistance);
  pitch_ = std::clamp(std::asin(std::clamp(offset.y() / d, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
  yaw_ = std::atan2(offset.x(), offset.z());
}

void OrbitCamera::frameBox(const Eigen::Vector3f& box_min, const Eigen::Vector3f& box_max) {
  target_ = 0.5f * (box_min + box_max);
  const float radius = std::max(0.5f * (box_max - box_min).norm(), 0.05f);
  // distance at which a sphere around the box fits the vertical field of view, plus a margin
  distance_ = std::clamp(1.1f * radius / std::sin(fov_y_degrees_ * kPi / 360.0f), kMinDistance, kMaxDistance);
  yaw_ = 0.0f;
  pitch_ = 0.35f;
}

bool OrbitCamera::adoptView(const Eigen::Matrix4f& view, float target_distance) {
  if (!view.allFinite() || !(target_distance > 0.0f)) return false;
  const Eigen::Matrix3f r = view.block<3, 3>(0, 0);
  if (!((r * r.transpose() - Eigen::Matrix3f::Identity()).cwiseAbs().maxCoeff() < 1e-3f)) return false;
  // eye = -R^T t; the camera looks along -z, i.e. world direction -(row 2 of R)
  const Eigen::Vector3f eye = -r.transpose() * view.block<3, 1>(0, 3);
  const Eigen::Vector3f forward = -r.row(2).transpose();
  setEyeTarget(eye, eye + forward * target_distance);
  return true;
}

void OrbitCamera::orbit(float dx_pixels, float dy_pixels) {
  yaw_ -= dx_pixels * kOrbitRadiansPerPixel;
  pitch_ = std::clamp(pitch_ + dy_pixels * kOrbitRadiansPerPixel, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float dx_pixels, float dy_pixels, int viewport_height) {
  if (viewport_height <= 0) return;
  // world size of one pixel at the target's depth, so the target follows the cursor
  const float metres_per_pixel =
      2.0f * distance_ * std::tan(fov_y_degrees_ * kPi / 360.0f) / static_cast<float>(viewport_height);
  const Eigen::Matrix4f v = view();
  const Eigen::Vector3f right = v.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3f up = v.block<1, 3>(1, 0).transpose();
  target_ += (-dx_pixels * right + dy_pixels * up) * metres_per_pixel;
}

void OrbitCamera::zoom(float wheel_steps) {
  distance_ = std::clamp(distance_ * std::pow(kZoomPerStep, wheel_steps), kMinDistance, kMaxDistance);
}

void OrbitCamera::setClipPlanes(float near_plane, float far_plane) {
  if (near_plane > 0.0f && far_plane > near_plane) {
    near_ = near_plane;
    far_ = far_plane;
  }
}

Eigen::Vector3f OrbitCamera::eye() const {
  const float c = std::cos(pitch_);
  return target_ + distance_ * Eigen::Vector3f(c * std::sin(yaw_), std::sin(pitch_), c * std::cos(yaw_));
}

Eigen::Matrix4f OrbitCamera::view() const { return lookAt(eye(), target_, Eigen::Vector3f::UnitY()); }

Eigen::Matrix4f OrbitCamera::projection(float aspect) const {
  return perspective(fov_y_degrees_, aspect > 0.0f ? aspect : 1.0f, near_, far_);
}

}  // namespace viewer
