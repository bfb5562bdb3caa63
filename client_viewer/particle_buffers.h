// The newest frame's particles on the GPU, shared by both render modes and every pass that draws
// them: a unit quad and, per particle (instanced), its centre and (size level, speed, neighbour
// count), and the radius of every size level. Uploaded once per frame.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <vector>

#include "decoded_frame.h"

namespace viewer {

// Neighbour count given to every particle when the frame carries none: not spray.
inline constexpr float kUnknownNeighbours = 255.0f;

// What a vertex shader declares to read the particles: a_corner (the quad corner, -1..1),
// a_centre (world), a_attrs (size level, speed, neighbours), u_radius (metres per level, set with
// ParticleBuffers::setRadii), asLevel() and levelRadius() of the particle. No #version line: put
// kGlslCommon (glsl_common.h) before it.
extern const char* const kGlslParticleAttributes;

class ParticleBuffers {
 public:
  ParticleBuffers();
  ~ParticleBuffers();
  ParticleBuffers(const ParticleBuffers&) = delete;
  ParticleBuffers& operator=(const ParticleBuffers&) = delete;

  void upload(const DecodedFrame& frame);
  // One instanced quad per particle, with the program in use.
  void draw() const;

  GLsizei count() const { return count_; }
  // Sets u_radius of the program in use to the frame's radius per size level.
  void setRadii(GLint location) const;
  float largestRadius() const;  // of the levels present in the frame
  float maxSpeed() const { return max_speed_; }
  bool hasSpeed() const { return has_speed_; }
  bool hasNeighbourCounts() const { return has_counts_; }
  // The levels the colour map spreads over (DecodedFrame::colourLevelCount).
  std::size_t levelCount() const { return level_count_; }

 private:
  GLuint vao_ = 0;
  GLuint quad_buffer_ = 0;
  GLuint centre_buffer_ = 0;
  GLuint attribute_buffer_ = 0;
  GLsizei count_ = 0;
  std::array<float, kMaxSizeLevels> radius_{};  // metres per size level, 0 beyond the frame's
  std::array<bool, kMaxSizeLevels> has_level_{};
  float max_speed_ = 1.0f;
  bool has_speed_ = false;
  bool has_counts_ = false;
  std::size_t level_count_ = 2;
  std::vector<float> staging_;  // reused between uploads
};

}  // namespace viewer
