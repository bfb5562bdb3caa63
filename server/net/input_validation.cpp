#include "net/input_validation.h"

#include <Eigen/LU>
#include <climits>
#include <cmath>

namespace net {
namespace {

constexpr std::uint32_t kVersion = gsph::v1::PROTOCOL_VERSION_CURRENT;

bool inUnitRange(float v) { return std::isfinite(v) && v >= 0.0f && v <= 1.0f; }

// Protobuf's parser reads at most INT_MAX bytes; our sockets cap far below that anyway.
bool parseBytes(google::protobuf::MessageLite& m, const void* data, std::size_t size) {
  return size <= static_cast<std::size_t>(INT_MAX) && m.ParseFromArray(data, static_cast<int>(size));
}

std::string versionError(std::uint32_t v) {
  return "protocol_version " + std::to_string(v) + " (expected " + std::to_string(kVersion) + ")";
}

Eigen::Matrix4d matrixFrom(const google::protobuf::RepeatedField<float>& values) {
  Eigen::Matrix4d m;
  for (int i = 0; i < 16; ++i) m(i % 4, i / 4) = values.Get(i);  // column-major
  return m;
}

std::string checkMatrix(const google::protobuf::RepeatedField<float>& values, const char* name) {
  if (values.size() != 16) {
    return std::string(name) + " has " + std::to_string(values.size()) + " values (expected 16)";
  }
  for (float v : values) {
    if (!std::isfinite(v)) return std::string(name) + " has a value that is not finite";
  }
  const double det = matrixFrom(values).determinant();
  if (!std::isfinite(det) || std::abs(det) < 1e-12) return std::string(name) + " is singular";
  return {};
}

}  // namespace

std::string parseGazeSample(const void* data, std::size_t size, gsph::v1::GazeSample& out) {
  if (!parseBytes(out, data, size)) return "unparseable GazeSample";
  if (out.protocol_version() != kVersion) return versionError(out.protocol_version());
  if (out.source_id().size() > kMaxIdLength) return "source_id too long";
  if (!inUnitRange(out.confidence())) return "confidence not finite or outside 0..1";
  if (out.valid() && !out.lost()) {
    if (!inUnitRange(out.x()) || !inUnitRange(out.y())) return "x, y not finite or outside 0..1";
  }
  return {};
}

std::string parseCameraPose(const void* data, std::size_t size, gsph::v1::CameraPose& out) {
  if (!parseBytes(out, data, size)) return "unparseable CameraPose";
  if (out.protocol_version() != kVersion) return versionError(out.protocol_version());
  if (out.viewer_id().size() > kMaxIdLength) return "viewer_id too long";
  if (std::string e = checkMatrix(out.view(), "view"); !e.empty()) return e;
  if (std::string e = checkMatrix(out.projection(), "projection"); !e.empty()) return e;
  const auto in_range = [](std::uint32_t px) {
    return px >= 1 && px <= static_cast<std::uint32_t>(kMaxViewportPixels);
  };
  if (!in_range(out.viewport_width()) || !in_range(out.viewport_height())) {
    return "viewport outside 1.." + std::to_string(kMaxViewportPixels) + " pixels";
  }
  return {};
}

std::string parseControl(const void* data, std::size_t size, gsph::v1::Control& out) {
  if (!parseBytes(out, data, size)) return "unparseable Control";
  if (out.protocol_version() != kVersion) return versionError(out.protocol_version());
  if (out.command_case() == gsph::v1::Control::COMMAND_NOT_SET) return "no command";
  return {};
}

sph::ScreenCamera toScreenCamera(const gsph::v1::CameraPose& pose) {
  sph::ScreenCamera camera;
  camera.view = matrixFrom(pose.view());
  camera.projection = matrixFrom(pose.projection());
  camera.viewport_width = static_cast<int>(pose.viewport_width());
  camera.viewport_height = static_cast<int>(pose.viewport_height());
  return camera;
}

void fromScreenCamera(const sph::ScreenCamera& camera, gsph::v1::CameraPose& out) {
  out.set_protocol_version(kVersion);
  out.clear_view();
  out.clear_projection();
  for (int i = 0; i < 16; ++i) out.add_view(static_cast<float>(camera.view(i % 4, i / 4)));
  for (int i = 0; i < 16; ++i) out.add_projection(static_cast<float>(camera.projection(i % 4, i / 4)));
  out.set_viewport_width(static_cast<std::uint32_t>(camera.viewport_width));
  out.set_viewport_height(static_cast<std::uint32_t>(camera.viewport_height));
}

}  // namespace net
