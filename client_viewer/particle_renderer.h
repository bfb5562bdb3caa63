// Particles mode: each particle a shaded sphere impostor, one camera-facing quad per particle
// (instanced) placed at the sphere's front; the fragment shader discards outside the disc and shades
// a sphere normal. Radius per size level from the frame (true size on screen), colour per level or
// by speed. Also writes the impostors' normals or depths for --render-debug (render_settings.h), to
// compare with the fluid surface.
#pragma once

#include <Eigen/Core>

#include "gl_program.h"
#include "particle_buffers.h"
#include "render_settings.h"

namespace viewer {

enum class ColourMode { kSizeClass, kSpeed };

class ParticleRenderer {
 public:
  ParticleRenderer();
  void draw(const ParticleBuffers& particles, const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection,
            ColourMode mode, RenderDebug debug) const;

 private:
  GlProgram program_;
};

}  // namespace viewer
