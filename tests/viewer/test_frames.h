// Hand-made Frames for the viewer tests: a few particles at chosen places, either encoding.
#pragma once

#include <cstdint>
#include <vector>

#include "proto/sph.pb.h"

namespace viewer_test {

struct TestParticle {
  float x, y, z;
  std::uint8_t level;  // size level: 0 the finest, 2.. need level_radii
};

struct FrameSpec {
  std::vector<TestParticle> particles;
  float radius_small = 0.04f;
  float radius_large = 0.05f;
  std::vector<float> level_radii;  // sent as given when not empty (else a two-class frame)
  bool quantized = false;
  float box_lo = -1.0f;  // geometry and quantization box, a cube
  float box_hi = 1.0f;
  bool with_box = true;
  bool with_gaze = false;
  float gaze_x = 0.5f, gaze_y = 0.5f, gaze_radius = 0.1f, gaze_ring = 0.0f;
  bool with_velocities = false;
  std::vector<std::uint8_t> neighbor_counts;  // sent as given when not empty
};

gsph::v1::Frame makeFrame(const FrameSpec& spec, std::uint64_t sequence);

// A reproducible cloud of n particles inside the box, half of each class.
std::vector<TestParticle> particleCloud(std::size_t n, float lo, float hi);

}  // namespace viewer_test
