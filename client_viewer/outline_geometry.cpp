#include "outline_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace viewer {

namespace {

constexpr int kCircleSegments = 64;
constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
constexpr Rgb kBoxColour{0.85f, 0.85f, 0.85f};
constexpr Rgb kObstacleColour{0.55f, 0.9f, 0.55f};
constexpr Rgb kGazeTracking{1.0f, 0.9f, 0.1f};
constexpr Rgb kGazeHolding{1.0f, 0.55f, 0.1f};
constexpr Rgb kRingColour{0.8f, 0.8f, 0.8f};

void segment(LineList& lines, float x0, float y0, float z0, float x1, float y1, float z1, Rgb c) {
  lines.push_back({x0, y0, z0, c.r, c.g, c.b});
  lines.push_back({x1, y1, z1, c.r, c.g, c.b});
}

// A circle in the plane spanned by unit axes a and b around centre (cx, cy, cz).
void circle(LineList& lines, float cx, float cy, float cz, float radius, const float a[3], const float b[3],
            Rgb colour) {
  for (int i = 0; i < kCircleSegments; ++i) {
    const float t0 = kTwoPi * static_cast<float>(i) / kCircleSegments;
    const float t1 = kTwoPi * static_cast<float>(i + 1) / kCircleSegments;
    const float c0 = std::cos(t0) * radius, s0 = std::sin(t0) * radius;
    const float c1 = std::cos(t1) * radius, s1 = std::sin(t1) * radius;
    segment(lines, cx + c0 * a[0] + s0 * b[0], cy + c0 * a[1] + s0 * b[1], cz + c0 * a[2] + s0 * b[2],
            cx + c1 * a[0] + s1 * b[0], cy + c1 * a[1] + s1 * b[1], cz + c1 * a[2] + s1 * b[2], colour);
  }
}

constexpr float kX[3] = {1, 0, 0};
constexpr float kY[3] = {0, 1, 0};
constexpr float kZ[3] = {0, 0, 1};

}  // namespace

void appendBox(LineList& lines, const Vec3f& lo, const Vec3f& hi, Rgb c) {
  const float xs[2] = {lo.x, hi.x};
  const float ys[2] = {lo.y, hi.y};
  const float zs[2] = {lo.z, hi.z};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      segment(lines, lo.x, ys[i], zs[j], hi.x, ys[i], zs[j], c);  // edges along x
      segment(lines, xs[i], lo.y, zs[j], xs[i], hi.y, zs[j], c);  // along y
      segment(lines, xs[i], ys[j], lo.z, xs[i], ys[j], hi.z, c);  // along z
    }
  }
}

void appendSphere(LineList& lines, const SphereShape& s, Rgb c) {
  circle(lines, s.center.x, s.center.y, s.center.z, s.radius, kX, kY, c);
  circle(lines, s.center.x, s.center.y, s.center.z, s.radius, kX, kZ, c);
  circle(lines, s.center.x, s.center.y, s.center.z, s.radius, kY, kZ, c);
}

void appendCylinder(LineList& lines, const CylinderShape& cyl, float y_floor, float y_roof, Rgb c) {
  circle(lines, cyl.x, y_floor, cyl.z, cyl.radius, kX, kZ, c);
  circle(lines, cyl.x, y_roof, cyl.z, cyl.radius, kX, kZ, c);
  const float dx[4] = {cyl.radius, -cyl.radius, 0, 0};
  const float dz[4] = {0, 0, cyl.radius, -cyl.radius};
  for (int i = 0; i < 4; ++i) {
    segment(lines, cyl.x + dx[i], y_floor, cyl.z + dz[i], cyl.x + dx[i], y_roof, cyl.z + dz[i], c);
  }
}

void appendGeometry(LineList& lines, const SceneGeometry& g, bool obstacles) {
  if (g.has_box) appendBox(lines, g.box_min, g.box_max, kBoxColour);
  if (!obstacles) return;
  for (const auto& s : g.spheres) appendSphere(lines, s, kObstacleColour);
  // Cylinders run floor to roof of the box; without a box give them a nominal metre.
  const float floor = g.has_box ? g.box_min.y : 0.0f;
  const float roof = g.has_box ? g.box_max.y : 1.0f;
  for (const auto& cyl : g.cylinders) appendCylinder(lines, cyl, floor, roof, kObstacleColour);
}

void appendScreenCircle(LineList& lines, float x, float y, float radius_of_width, float aspect, Rgb c, bool dashed) {
  // normalized top-left -> NDC; a radius of w*r pixels is 2r in NDC x and 2r*aspect in NDC y
  const float cx = 2.0f * x - 1.0f;
  const float cy = 1.0f - 2.0f * y;
  const float rx = 2.0f * radius_of_width;
  const float ry = rx * aspect;
  for (int i = 0; i < kCircleSegments; ++i) {
    if (dashed && (i % 2 == 1)) continue;
    const float t0 = kTwoPi * static_cast<float>(i) / kCircleSegments;
    const float t1 = kTwoPi * static_cast<float>(i + 1) / kCircleSegments;
    segment(lines, cx + rx * std::cos(t0), cy + ry * std::sin(t0), 0.0f, cx + rx * std::cos(t1), cy + ry * std::sin(t1),
            0.0f, c);
  }
}

void appendGazeOverlay(LineList& lines, const GazeOverlay& gaze, float aspect) {
  if (!gaze.drawable()) return;
  const Rgb colour = gaze.mode == gsph::v1::GAZE_MODE_TRACKING ? kGazeTracking : kGazeHolding;
  appendScreenCircle(lines, gaze.x, gaze.y, gaze.radius, aspect, colour);
  if (gaze.ring_radius > gaze.radius) {
    appendScreenCircle(lines, gaze.x, gaze.y, gaze.ring_radius, aspect, kRingColour, true);
  }
}

void appendFoveaRings(LineList& lines, const DecodedFrame& frame, float aspect) {
  const auto& radii = frame.foveation.ring_radii;
  const bool tracking = frame.gaze.mode == gsph::v1::GAZE_MODE_TRACKING;
  const std::size_t level_count = std::max(frame.colourLevelCount(), radii.size() + 1);
  for (std::size_t k = 0; k < radii.size(); ++k) {
    if (!(radii[k] > 0.0f)) continue;
    const LevelRgb c = levelColour(k + 1, level_count);
    appendScreenCircle(lines, frame.gaze.x, frame.gaze.y, radii[k], aspect, {c.r, c.g, c.b}, !tracking);
  }
}

void appendMethodOverlay(LineList& lines, const DecodedFrame& frame, float aspect) {
  if (frame.method == gsph::v1::METHOD_FOVEATED) {
    appendFoveaRings(lines, frame, aspect);
  } else if (frame.method == gsph::v1::METHOD_GAZE || frame.method == gsph::v1::METHOD_HYBRID) {
    appendGazeOverlay(lines, frame.gaze, aspect);
  }
}

void appendScreenCross(LineList& lines, float x, float y, float size_of_width, float aspect, Rgb c) {
  const float cx = 2.0f * x - 1.0f;
  const float cy = 1.0f - 2.0f * y;
  const float dx = 2.0f * size_of_width;
  const float dy = dx * aspect;
  segment(lines, cx - dx, cy, 0.0f, cx + dx, cy, 0.0f, c);
  segment(lines, cx, cy - dy, 0.0f, cx, cy + dy, 0.0f, c);
}

}  // namespace viewer
