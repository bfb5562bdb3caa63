// A Frame from the server checked and unpacked into what the renderer and the panel need: positions
// as floats whatever the wire encoding, one size level byte per particle, optional speeds. Decoding
// happens on the network thread, so the render thread only ever uploads a finished frame.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "proto/sph.pb.h"

namespace viewer {

struct Vec3f {
  float x = 0.0f;
  float y = 0.0f;
  float z = 0.0f;
};

struct SphereShape {
  Vec3f center;
  float radius = 0.0f;
};

struct CylinderShape {
  float x = 0.0f;
  float z = 0.0f;
  float radius = 0.0f;
};

struct SceneGeometry {
  bool has_box = false;
  Vec3f box_min;
  Vec3f box_max;
  std::vector<SphereShape> spheres;
  std::vector<CylinderShape> cylinders;
};

// The gaze the server's step used, in the server's screen units (normalized, origin top left).
struct GazeOverlay {
  gsph::v1::GazeMode mode = gsph::v1::GAZE_MODE_UNSPECIFIED;
  float x = 0.0f;
  float y = 0.0f;
  float radius = 0.0f;       // fraction of viewport width
  float ring_radius = 0.0f;  // fraction of viewport width; <= radius means no ring
  float age_ms = 0.0f;
  bool drawable() const;
};

// What the foveated method did in the frame's step (sph.proto, Frame); zero / empty for the others.
struct FoveationFigures {
  float quality = 0.0f;                 // q in force
  float periphery_gain = 0.0f;          // g in force
  float periphery_gain_ceiling = 0.0f;  // the most the real-time governor may use
  float realtime_ratio = 0.0f;          // simulated over wall seconds lately; 0: not measured
  std::uint32_t visible = 0;            // particles the eye sees
  std::uint32_t over_budget = 0;        // of those, wider than the perceptual budget allows
  float fovea_width_arcmin = 0.0f;      // the particle under the gaze; 0: the gaze is on no water
  float fovea_mar_arcmin = 0.0f;        // the eye's acuity there
  // Where levels 1, 2, ... begin around the gaze point, viewport widths (finite, >= 0).
  std::vector<float> ring_radii;
  bool atCeiling() const { return periphery_gain_ceiling > 0.0f && periphery_gain >= periphery_gain_ceiling; }
};

// Size levels: the thesis's two classes are levels 0 and 1; the foveated method adds coarser ones.
inline constexpr std::uint8_t kClassSmall = 0;
inline constexpr std::uint8_t kClassLarge = 1;
// The most levels a frame may declare in level_radii; the shaders hold one radius per level.
inline constexpr std::size_t kMaxSizeLevels = 16;

struct DecodedFrame {
  // Wire facts
  std::uint64_t sequence = 0;
  std::int64_t step = 0;
  double sim_time = 0.0;
  std::int64_t send_time_us = 0;
  std::string scene;
  gsph::v1::Method method = gsph::v1::METHOD_UNSPECIFIED;
  bool paused = false;
  gsph::v1::PhaseTimings timings;
  float steps_per_second = 0.0f;
  GazeOverlay gaze;
  FoveationFigures foveation;
  bool has_camera = false;
  gsph::v1::CameraPose camera;  // the pose the server's gaze projection used
  SceneGeometry geometry;
  float radius_small = 0.0f;
  float radius_large = 0.0f;
  // Per size level, index = level byte: the frame's level_radii, or {radius_small, radius_large}
  // from servers that send none. level_counts has as many entries.
  std::vector<float> level_radii;
  std::vector<std::uint32_t> level_counts;
  gsph::v1::PositionEncoding encoding = gsph::v1::POSITION_ENCODING_UNSPECIFIED;

  // Per particle
  std::vector<Vec3f> positions;
  std::vector<std::uint8_t> classes;          // size level, < level_radii.size()
  std::vector<float> speeds;                  // empty when the frame carries no velocities
  std::vector<std::uint8_t> neighbor_counts;  // empty when the frame carries none (server option)

  // Local facts
  std::chrono::steady_clock::time_point arrival;  // when the bytes left the socket
  std::size_t wire_bytes = 0;

  std::size_t particleCount() const { return positions.size(); }
  // Any particle of a level beyond L0 and L1 (the foveated method's coarser levels).
  bool hasExtraLevels() const;
  // The levels the colour map spreads over: every declared one under foveated; under the thesis's
  // methods, which make L0 and L1 only, those two (or more where the frame has particles there),
  // so their two levels get the map's two ends.
  std::size_t colourLevelCount() const;
};

// Fills `out` from `frame`. On failure returns false, sets `error` to a human-readable reason and
// leaves `out` in an unspecified state (callers decode into a fresh object and keep their last good
// frame). Checks: protocol version, encoding, byte lengths against particle_count, level bytes
// against the levels declared (level_radii, at most kMaxSizeLevels; else L0 and L1 only),
// finite positions, radii and quantization box, optional per-particle fields one entry per particle.
bool decodeFrame(const gsph::v1::Frame& frame, DecodedFrame& out, std::string& error);

// Parses wire bytes and decodes; the same contract as decodeFrame.
bool decodeFrameBytes(const void* data, std::size_t size, DecodedFrame& out, std::string& error);

}  // namespace viewer
