// Independent reference for the camera matrices (double precision, written out from the
// gluLookAt / gluPerspective definitions), column-major like the wire format.
#pragma once

#include <array>
#include <cmath>

namespace viewer_test {

using Vec3d = std::array<double, 3>;
using Mat4d = std::array<double, 16>;  // column-major

inline Mat4d referenceLookAt(const Vec3d& eye, const Vec3d& target) {
  auto sub = [](Vec3d a, Vec3d b) { return Vec3d{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  auto cross = [](Vec3d a, Vec3d b) {
    return Vec3d{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto dot = [](Vec3d a, Vec3d b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto norm = [&](Vec3d a) {
    const double l = std::sqrt(dot(a, a));
    return Vec3d{a[0] / l, a[1] / l, a[2] / l};
  };
  const Vec3d f = norm(sub(target, eye));
  const Vec3d s = norm(cross(f, {0, 1, 0}));
  const Vec3d u = cross(s, f);
  // rows s, u, -f; translation -R eye
  return {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, -dot(s, eye), -dot(u, eye), dot(f, eye), 1};
}

inline Mat4d referencePerspective(double fov_y_degrees, double aspect, double n, double f) {
  const double c = 1.0 / std::tan(fov_y_degrees * M_PI / 360.0);
  return {c / aspect, 0, 0, 0, 0, c, 0, 0, 0, 0, (f + n) / (n - f), -1, 0, 0, 2 * f * n / (n - f), 0};
}

// World point -> pixel (origin top left) through column-major view and projection.
inline std::array<double, 2> projectToPixel(const float* view, const float* projection, const Vec3d& p, int width,
                                            int height) {
  double v[4], c[4];
  for (int r = 0; r < 4; ++r) {
    v[r] = view[r] * p[0] + view[4 + r] * p[1] + view[8 + r] * p[2] + view[12 + r];
  }
  for (int r = 0; r < 4; ++r) {
    c[r] = projection[r] * v[0] + projection[4 + r] * v[1] + projection[8 + r] * v[2] + projection[12 + r] * v[3];
  }
  const double x = c[0] / c[3], y = c[1] / c[3];
  return {(x + 1.0) * 0.5 * width, (1.0 - y) * 0.5 * height};
}

}  // namespace viewer_test
