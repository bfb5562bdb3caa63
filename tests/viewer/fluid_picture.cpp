#include "fluid_picture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "viewer_process.h"

namespace viewer_test {

using namespace std::chrono_literals;

std::optional<Snapshot> takeSnapshot(TestServer& server, std::vector<std::string> args, const std::string& dir,
                                     const std::string& id) {
  const std::string png = dir + "/" + id + ".png";
  const std::string log = dir + "/" + id + ".log";
  const auto endpoints = server.endpointArgs();
  args.insert(args.end(), endpoints.begin(), endpoints.end());
  args.insert(args.end(), {"--viewer-id", id, "--snapshot", png, "--frames", "2", "--timeout", "150"});
  auto viewer = startViewer(args, log);
  const auto code = viewer->waitExit(200s);
  if (!code || *code != 0) {
    ADD_FAILURE() << id << ": the viewer did not exit 0:\n" << readFile(log);
    return std::nullopt;
  }
  Snapshot shot;
  std::string error;
  if (!viewer::readPng(png, shot.image, error)) {
    ADD_FAILURE() << id << ": " << error;
    return std::nullopt;
  }
  if (!server.waitForPose([&](const auto& p) { return p.viewer_id() == id; }, 20s, &shot.pose)) {
    ADD_FAILURE() << id << ": no camera pose from the viewer";
    return std::nullopt;
  }
  return shot;
}

std::optional<Vec3d> decodeNormal(const viewer::RgbaImage& image, int x, int y) {
  const auto* p = image.at(x, y);
  if (p[0] == 0 && p[1] == 0 && p[2] == 0) return std::nullopt;
  Vec3d n{p[0] / 127.5 - 1.0, p[1] / 127.5 - 1.0, p[2] / 127.5 - 1.0};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  return Vec3d{n[0] / length, n[1] / length, n[2] / length};
}

std::optional<double> decodeMetres(const viewer::RgbaImage& image, int x, int y) {
  const auto* p = image.at(x, y);
  if (p[0] == 255 && p[1] == 255 && p[2] == 255) return std::nullopt;
  return (p[0] * 65536.0 + p[1] * 256.0 + p[2]) / 65536.0;
}

double angleDegrees(const Vec3d& a, const Vec3d& b) {
  const double c = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
}

Vec3d toView(const gsph::v1::CameraPose& pose, const Vec3d& w) {
  const auto& v = pose.view();  // column-major
  return {v[0] * w[0] + v[4] * w[1] + v[8] * w[2], v[1] * w[0] + v[5] * w[1] + v[9] * w[2],
          v[2] * w[0] + v[6] * w[1] + v[10] * w[2]};
}

Vec3d worldPoint(const gsph::v1::CameraPose& pose, int x, int y, double depth) {
  const double ndc_x = (x + 0.5) / pose.viewport_width() * 2.0 - 1.0;
  const double ndc_y = 1.0 - (y + 0.5) / pose.viewport_height() * 2.0;
  const auto& p = pose.projection();
  const Vec3d view_point{ndc_x * depth / p[0], ndc_y * depth / p[5], -depth};
  // world = R^T (view_point - t), R and t from the column-major view matrix.
  const auto& v = pose.view();
  const Vec3d q{view_point[0] - v[12], view_point[1] - v[13], view_point[2] - v[14]};
  return {v[0] * q[0] + v[1] * q[1] + v[2] * q[2], v[4] * q[0] + v[5] * q[1] + v[6] * q[2],
          v[8] * q[0] + v[9] * q[1] + v[10] * q[2]};
}

void appendPool(std::vector<TestParticle>& out, double x0, double x1, double z0, double z1, double top, int layers,
                double radius, std::uint8_t size_class, bool from_x1) {
  const double spacing = kSpacingPerRadius * radius;
  const int columns = static_cast<int>(std::floor((x1 - x0 - 2.0 * radius) / spacing)) + 1;
  const int rows = static_cast<int>(std::floor((z1 - z0 - 2.0 * radius) / spacing)) + 1;
  for (int k = 0; k < layers; ++k) {
    const double y = top - radius - k * spacing;
    for (int i = 0; i < columns; ++i) {
      const double x = from_x1 ? x1 - radius - i * spacing : x0 + radius + i * spacing;
      for (int j = 0; j < rows; ++j) {
        const double z = z0 + radius + j * spacing;
        out.push_back({static_cast<float>(x), static_cast<float>(y), static_cast<float>(z), size_class});
      }
    }
  }
}

}  // namespace viewer_test
