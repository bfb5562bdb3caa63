// Encodes the simulation's state as a gsph.v1.Frame. One Frame object is reused for every frame:
// its byte fields keep their capacity, so after the first frame encoding allocates nothing (a
// fresh message per frame costs page faults on every frame; docs/performance.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>
#include <zmq.hpp>

#include "proto/sph.pb.h"
#include "sph/adaptive/method.h"
#include "sph/simulation.h"

namespace net {

enum class PositionEncoding { Float32, Quantized16 };

// The gaze a step used, as the frame reports it (GazeUsed in the schema).
struct GazeEcho {
  gsph::v1::GazeMode mode = gsph::v1::GAZE_MODE_NONE;
  double x = 0.5;
  double y = 0.5;
  double radius = 0.0;
  double ring_radius = 0.0;
  double age_s = 0.0;
  bool has_sample = false;  // a sample has been handed to the controller
  std::uint64_t sample_sequence = 0;
  std::int64_t sample_bridge_time_us = 0;
  std::string source_id;
};

// The foveated method's figures a frame carries beside q, g and the ratio (sph.proto, Frame).
struct FoveationEcho {
  float periphery_gain_ceiling = 0.0f;
  std::uint32_t visible = 0;
  std::uint32_t over_budget = 0;
  float fovea_width_arcmin = 0.0f;
  float fovea_mar_arcmin = 0.0f;
  std::vector<float> ring_radii;  // where levels 1.. begin around the gaze, viewport widths
};

// What the frame says beyond the particle state.
struct FrameInfo {
  std::uint64_t sequence = 0;
  std::string scene;
  sph::Method method = sph::Method::Regular;
  bool paused = false;
  double steps_per_second = 0.0;
  float quality = 0.0f;         // the foveated method's q in force; 0 for the others
  float periphery_gain = 0.0f;  // and its periphery gain (the real-time governor's); 0 for the others
  float realtime_ratio = 0.0f;  // simulated over wall seconds lately; 0 when not measured
  GazeEcho gaze;
  const gsph::v1::CameraPose* camera = nullptr;  // the pose the projection uses; nullptr: none
  // What the foveated method did (Frame's fields of the same names); zero and empty for the others.
  FoveationEcho foveation;
};

gsph::v1::Method toProtoMethod(sph::Method m);
// False for METHOD_UNSPECIFIED and values the schema does not name.
bool fromProtoMethod(int value, sph::Method& out);
gsph::v1::GazeMode toProtoGazeMode(sph::GazeMode m);

// The simulation's particles per level, L0 first, one entry per level of the run, into a Frame or
// a ServerStatus; and the deprecated pair they replace, for clients of the previous version
// (sph.proto).
template <class Message>
void setLevelCounts(const sph::Simulation& sim, Message& out) {
  const auto by_level = sim.particles().countByLevel();
  out.clear_level_counts();
  for (int k = 0; k < sim.params().levels; ++k) {
    out.add_level_counts(static_cast<std::uint32_t>(by_level[static_cast<std::size_t>(k)]));
  }
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  out.set_large_count(static_cast<std::uint32_t>(by_level[1]));
  out.set_small_count(static_cast<std::uint32_t>(by_level[0]));
#pragma GCC diagnostic pop
}

class FrameEncoder {
 public:
  explicit FrameEncoder(PositionEncoding encoding = PositionEncoding::Float32, bool velocities = false)
      : encoding_(encoding), velocities_(velocities) {}

  void setEncoding(PositionEncoding encoding) { encoding_ = encoding; }
  PositionEncoding encoding() const { return encoding_; }
  void setVelocities(bool on) { velocities_ = on; }
  // Off by default: the field then costs neither the encoder nor the wire anything.
  void setNeighborCounts(bool on) { neighbor_counts_ = on; }

  // Fills the reused Frame from `sim` and `info`; the returned reference stays valid until the next call.
  const gsph::v1::Frame& encode(const sph::Simulation& sim, const FrameInfo& info);
  // The last encoded frame serialized into one message: one allocation, written in place.
  zmq::message_t serialize();

 private:
  void encodePositions(const sph::Simulation& sim);
  void encodeNeighborCounts(const sph::Simulation& sim);

  PositionEncoding encoding_;
  bool velocities_;
  bool neighbor_counts_ = false;
  gsph::v1::Frame frame_;
};

// Decodes a frame's positions (either encoding) into x, y, z triples; for tests and tools.
std::vector<float> decodePositions(const gsph::v1::Frame& frame);

}  // namespace net
