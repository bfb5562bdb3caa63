// Particles as shaded sphere impostors: one camera-facing quad per particle (instanced) placed at
// the sphere's front; the fragment shader discards outside the disc and shades a sphere normal.
// Radius per class from the frame (true size on screen).
#pragma once

#include <Eigen/Core>

#include "decoded_frame.h"
#include "gl_program.h"

namespace viewer {

enum class ColourMode { kSizeClass, kSpeed };

class ParticleRenderer {
 public:
  ParticleRenderer();
  ~ParticleRenderer();
  ParticleRenderer(const ParticleRenderer&) = delete;
  ParticleRenderer& operator=(const ParticleRenderer&) = delete;

  // Copies the frame's particles to the GPU (called once per new frame, not per redraw).
  void upload(const DecodedFrame& frame);
  void draw(const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection, ColourMode mode) const;

 private:
  GlProgram program_;
  GLuint vao_ = 0;
  GLuint quad_buffer_ = 0;
  GLuint centre_buffer_ = 0;
  GLuint attribute_buffer_ = 0;  // (class, speed) per particle
  GLsizei count_ = 0;
  float radius_[2] = {0.0f, 0.0f};
  float max_speed_ = 1.0f;
  bool has_speed_ = false;
  std::vector<float> staging_;  // reused between uploads
};

}  // namespace viewer
