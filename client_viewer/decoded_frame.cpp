#include "decoded_frame.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace viewer {

// The wire formats are little-endian; memcpy into host floats is only right on a little-endian host.
static_assert(std::endian::native == std::endian::little, "viewer assumes a little-endian host");

namespace {

constexpr std::size_t kFloatStride = 12;     // 3 x float32
constexpr std::size_t kQuantizedStride = 6;  // 3 x uint16

Vec3f toVec(const gsph::v1::Vec3& v) { return {v.x(), v.y(), v.z()}; }

bool finite(const Vec3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool decodeGeometry(const gsph::v1::Geometry& g, SceneGeometry& out, std::string& error) {
  out = {};
  if (g.has_box()) {
    out.has_box = true;
    out.box_min = toVec(g.box().min());
    out.box_max = toVec(g.box().max());
    if (!finite(out.box_min) || !finite(out.box_max)) {
      error = "geometry box is not finite";
      return false;
    }
  }
  for (const auto& s : g.spheres()) {
    SphereShape shape{toVec(s.center()), s.radius()};
    if (!finite(shape.center) || !std::isfinite(shape.radius) || shape.radius < 0.0f) {
      error = "geometry sphere is not finite or has a negative radius";
      return false;
    }
    out.spheres.push_back(shape);
  }
  for (const auto& c : g.cylinders()) {
    CylinderShape shape{c.x(), c.z(), c.radius()};
    if (!std::isfinite(shape.x) || !std::isfinite(shape.z) || !std::isfinite(shape.radius) || shape.radius < 0.0f) {
      error = "geometry cylinder is not finite or has a negative radius";
      return false;
    }
    out.cylinders.push_back(shape);
  }
  return true;
}

bool decodeFloatPositions(const std::string& bytes, std::size_t n, std::vector<Vec3f>& out, std::string& error) {
  if (bytes.size() != n * kFloatStride) {
    error = "float32 positions hold " + std::to_string(bytes.size()) + " bytes, expected " +
            std::to_string(n * kFloatStride) + " for " + std::to_string(n) + " particles";
    return false;
  }
  out.resize(n);
  if (n > 0) std::memcpy(out.data(), bytes.data(), bytes.size());
  for (const auto& p : out) {
    if (!finite(p)) {
      error = "a float32 position is not finite";
      return false;
    }
  }
  return true;
}

bool decodeQuantizedPositions(const gsph::v1::Frame& frame, std::size_t n, std::vector<Vec3f>& out,
                              std::string& error) {
  const std::string& bytes = frame.positions();
  if (bytes.size() != n * kQuantizedStride) {
    error = "quantized16 positions hold " + std::to_string(bytes.size()) + " bytes, expected " +
            std::to_string(n * kQuantizedStride) + " for " + std::to_string(n) + " particles";
    return false;
  }
  if (!frame.has_quantization_box()) {
    error = "quantized16 positions without a quantization_box";
    return false;
  }
  const Vec3f lo = toVec(frame.quantization_box().min());
  const Vec3f hi = toVec(frame.quantization_box().max());
  if (!finite(lo) || !finite(hi) || hi.x < lo.x || hi.y < lo.y || hi.z < lo.z) {
    error = "quantization_box is not finite or has max < min";
    return false;
  }
  // value v maps to min + v / 65535 * (max - min) per axis (proto/sph.proto)
  const float sx = (hi.x - lo.x) / 65535.0f;
  const float sy = (hi.y - lo.y) / 65535.0f;
  const float sz = (hi.z - lo.z) / 65535.0f;
  out.resize(n);
  const auto* raw = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::size_t i = 0; i < n; ++i) {
    std::uint16_t q[3];
    std::memcpy(q, raw + i * kQuantizedStride, kQuantizedStride);
    out[i] = {lo.x + static_cast<float>(q[0]) * sx, lo.y + static_cast<float>(q[1]) * sy,
              lo.z + static_cast<float>(q[2]) * sz};
  }
  return true;
}

bool validRadius(float r) { return std::isfinite(r) && r >= 0.0f; }

// The radius of every level the frame declares: level_radii, or the two thesis classes from a
// server that predates it.
bool decodeLevelRadii(const gsph::v1::Frame& frame, DecodedFrame& out, std::string& error) {
  out.radius_small = frame.radius_small();
  out.radius_large = frame.radius_large();
  if (!validRadius(out.radius_small) || !validRadius(out.radius_large)) {
    error = "particle radii must be finite and non-negative";
    return false;
  }
  const auto& radii = frame.level_radii();
  if (radii.empty()) {
    out.level_radii = {out.radius_small, out.radius_large};
    return true;
  }
  if (static_cast<std::size_t>(radii.size()) > kMaxSizeLevels) {
    error = "level_radii declares " + std::to_string(radii.size()) + " size levels, at most " +
            std::to_string(kMaxSizeLevels) + " are allowed";
    return false;
  }
  out.level_radii.assign(radii.begin(), radii.end());
  for (std::size_t level = 0; level < out.level_radii.size(); ++level) {
    if (!validRadius(out.level_radii[level])) {
      error = "level_radii[" + std::to_string(level) + "] must be finite and non-negative";
      return false;
    }
  }
  return true;
}

// Counts the particles per level; a level byte the frame does not declare refuses the frame.
bool decodeLevels(const gsph::v1::Frame& frame, bool declared, DecodedFrame& out, std::string& error) {
  out.classes.assign(frame.size_classes().begin(), frame.size_classes().end());
  out.level_counts.assign(out.level_radii.size(), 0);
  for (std::uint8_t c : out.classes) {
    if (c >= out.level_counts.size()) {
      // Worded as before level_radii for two-class frames, so old and new viewers report alike.
      error = declared ? "size level " + std::to_string(c) + " is beyond the " +
                             std::to_string(out.level_counts.size()) + " levels of level_radii"
                       : "size class " + std::to_string(c) + " is neither L0 (0) nor L1 (1)";
      return false;
    }
    ++out.level_counts[c];
  }
  return true;
}

// Figures that are not finite read as 0 and rings beyond the declared levels are dropped: they are
// what the panel and the overlay show, never what the water is drawn from.
void decodeFoveation(const gsph::v1::Frame& frame, FoveationFigures& out) {
  const auto finite = [](float v) { return std::isfinite(v) ? v : 0.0f; };
  out.quality = finite(frame.quality());
  out.periphery_gain = finite(frame.periphery_gain());
  out.periphery_gain_ceiling = finite(frame.periphery_gain_ceiling());
  out.realtime_ratio = finite(frame.realtime_ratio());
  out.visible = frame.visible_count();
  out.over_budget = std::min(frame.over_budget_count(), frame.visible_count());
  out.fovea_width_arcmin = finite(frame.fovea_width_arcmin());
  out.fovea_mar_arcmin = finite(frame.fovea_mar_arcmin());
  out.ring_radii.clear();
  for (int k = 0; k < frame.fovea_ring_radii_size() && out.ring_radii.size() + 1 < kMaxSizeLevels; ++k) {
    const float r = frame.fovea_ring_radii(k);
    out.ring_radii.push_back(std::isfinite(r) && r > 0.0f ? r : 0.0f);
  }
}

}  // namespace

bool DecodedFrame::hasExtraLevels() const {
  for (std::size_t level = kClassLarge + 1; level < level_counts.size(); ++level) {
    if (level_counts[level] > 0) return true;
  }
  return false;
}

std::size_t DecodedFrame::colourLevelCount() const {
  if (method == gsph::v1::METHOD_FOVEATED) return level_radii.size();
  std::size_t used = 2;
  for (std::size_t level = 0; level < level_counts.size(); ++level) {
    if (level_counts[level] > 0) used = std::max(used, level + 1);
  }
  return std::min(used, std::max<std::size_t>(level_radii.size(), 2));
}

bool GazeOverlay::drawable() const {
  return (mode == gsph::v1::GAZE_MODE_TRACKING || mode == gsph::v1::GAZE_MODE_HOLDING) && radius > 0.0f;
}

bool decodeFrame(const gsph::v1::Frame& frame, DecodedFrame& out, std::string& error) {
  if (frame.protocol_version() != gsph::v1::PROTOCOL_VERSION_CURRENT) {
    error = "unknown protocol_version " + std::to_string(frame.protocol_version());
    return false;
  }
  const std::size_t n = frame.particle_count();
  switch (frame.encoding()) {
    case gsph::v1::POSITION_ENCODING_FLOAT32:
      if (!decodeFloatPositions(frame.positions(), n, out.positions, error)) return false;
      break;
    case gsph::v1::POSITION_ENCODING_QUANTIZED16:
      if (!decodeQuantizedPositions(frame, n, out.positions, error)) return false;
      break;
    default:
      error = "unknown position encoding " + std::to_string(static_cast<int>(frame.encoding()));
      return false;
  }
  if (frame.size_classes().size() != n) {
    error = "size_classes holds " + std::to_string(frame.size_classes().size()) +
            " bytes, expected one per particle (" + std::to_string(n) + ")";
    return false;
  }
  if (!decodeLevelRadii(frame, out, error)) return false;
  if (!decodeLevels(frame, !frame.level_radii().empty(), out, error)) return false;
  out.speeds.clear();
  if (!frame.velocities().empty()) {
    std::vector<Vec3f> velocities;
    if (!decodeFloatPositions(frame.velocities(), n, velocities, error)) {
      error = "velocities: " + error;
      return false;
    }
    out.speeds.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3f& v = velocities[i];
      out.speeds[i] = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    }
  }
  const std::string& counts = frame.neighbor_counts();
  if (!counts.empty() && counts.size() != n) {
    error = "neighbor_counts holds " + std::to_string(counts.size()) + " bytes, expected none or one per particle (" +
            std::to_string(n) + ")";
    return false;
  }
  out.neighbor_counts.assign(counts.begin(), counts.end());
  if (!decodeGeometry(frame.geometry(), out.geometry, error)) return false;

  out.sequence = frame.sequence();
  out.step = frame.step();
  out.sim_time = frame.sim_time();
  out.send_time_us = frame.send_time_us();
  out.scene = frame.scene();
  out.method = frame.method();
  out.paused = frame.paused();
  out.timings = frame.timings();
  out.steps_per_second = frame.steps_per_second();
  const auto& g = frame.gaze();
  out.gaze = {g.mode(), g.x(), g.y(), g.radius(), g.ring_radius(), g.age_ms()};
  if (!std::isfinite(out.gaze.x) || !std::isfinite(out.gaze.y) || !std::isfinite(out.gaze.radius) ||
      !std::isfinite(out.gaze.ring_radius)) {
    out.gaze.mode = gsph::v1::GAZE_MODE_UNSPECIFIED;  // not drawable; the frame itself is fine
  }
  decodeFoveation(frame, out.foveation);
  out.has_camera = frame.has_camera();
  out.camera = frame.camera();
  out.encoding = frame.encoding();
  return true;
}

bool decodeFrameBytes(const void* data, std::size_t size, DecodedFrame& out, std::string& error) {
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    error = "frame of " + std::to_string(size) + " bytes is too large to parse";
    return false;
  }
  gsph::v1::Frame frame;
  if (!frame.ParseFromArray(data, static_cast<int>(size))) {
    error = "frame bytes do not parse as gsph.v1.Frame";
    return false;
  }
  out.wire_bytes = size;
  return decodeFrame(frame, out, error);
}

}  // namespace viewer
