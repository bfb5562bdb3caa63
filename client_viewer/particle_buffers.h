// The newest frame's particles on the GPU, shared by both render modes and every pass that draws
// them. They live in two buffer textures, read by the vertex shaders through gl_VertexID, and each
// particle is drawn as two triangles of a quad (non-instanced): software GL (llvmpipe) runs its
// vertex pipeline once per instance of an instanced draw, which for 4-vertex instances cost more
// than all the pixels (docs/performance.md, "Viewer").
#pragma once

#include <epoxy/gl.h>

#include <vector>

#include "decoded_frame.h"

namespace viewer {

// Neighbour count given to every particle when the frame carries none: not spray.
inline constexpr float kUnknownNeighbours = 255.0f;

// What a vertex shader declares to read the particles: u_particles (x, y, z, size class) and
// u_attributes (speed, neighbours), and
//   int particleIndex()    the particle this vertex belongs to
//   vec2 quadCorner()      the vertex's corner of the particle's quad, -1..1
// No #version line: put kGlslCommon (glsl_common.h) before it.
extern const char* const kGlslParticleFetch;

class ParticleBuffers {
 public:
  ParticleBuffers();
  ~ParticleBuffers();
  ParticleBuffers(const ParticleBuffers&) = delete;
  ParticleBuffers& operator=(const ParticleBuffers&) = delete;

  void upload(const DecodedFrame& frame);
  // Binds the buffer textures to `program` (texture units 6 and 7) and draws every particle's quad.
  void draw(GLuint program) const;

  GLsizei count() const { return count_; }
  const float* radii() const { return radius_; }  // [SMALL, LARGE], metres
  float largestRadius() const;                    // of the classes present in the frame
  float maxSpeed() const { return max_speed_; }
  bool hasSpeed() const { return has_speed_; }
  bool hasNeighbourCounts() const { return has_counts_; }

 private:
  GLuint vao_ = 0;  // empty: the core profile draws only with one bound
  GLuint buffers_[2] = {0, 0};
  GLuint textures_[2] = {0, 0};
  GLsizei count_ = 0;
  float radius_[2] = {0.0f, 0.0f};
  bool has_class_[2] = {false, false};
  float max_speed_ = 1.0f;
  bool has_speed_ = false;
  bool has_counts_ = false;
  std::vector<float> particles_;   // staging, reused: x, y, z, class
  std::vector<float> attributes_;  // staging, reused: speed, neighbours
};

}  // namespace viewer
