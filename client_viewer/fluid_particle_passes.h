// The fluid mode's passes over the particles, each drawing every particle as a sphere impostor of
// its own class radius (van der Laan, Green & Sainz 2009, section 3):
//  - surface: into two attachments at once, the nearest sphere surface per pixel in metres along
//    the view axis (MIN blending, so no gl_FragDepth, and the overlap of two spheres is resolved
//    exactly), and the chord length through each sphere, summed (additive blending) as thickness;
//    depth-tested against the backdrop (an obstacle in front of the water hides it);
//  - droplets: spray particles, left out of the surface, as small shaded spheres.
// A particle is spray when the frame's neighbour counts say it has at most kSprayMaxNeighbours;
// without counts every particle belongs to the surface.
#pragma once

#include <Eigen/Core>

#include "fullscreen_pass.h"
#include "gl_program.h"
#include "particle_buffers.h"

namespace viewer {

// SPH particles inside the liquid have some 30-60 neighbours, those on its surface about half as
// many, and one in a sheet a single particle thick still about six; a particle with this many or
// fewer has left the body of water.
inline constexpr int kSprayMaxNeighbours = 3;
// The surface pass draws each sphere this much larger than the particle. In thin sheets the
// particles lie further apart than in the bulk and the gaps between them show as holes; larger
// closes more of them but costs fragments, the fluid mode's largest cost on software GL
// (docs/performance.md, "Viewer"), so the spheres keep their true size.
inline constexpr float kSurfaceRadiusScale = 1.0f;
// Droplets are drawn smaller than the particle: a lone particle stands for a blob of spray whose
// volume the simulation spreads over its whole kernel.
inline constexpr float kDropletRadiusScale = 0.6f;

// The backdrop's depth texture, and where a pixel of the pass that reads it falls on it: backdrop
// pixel = (pass pixel - guard) * scale (the surface pass draws a guard band around the picture).
struct SceneDepth {
  GLuint texture;
  float scale;
  float guard;
};

class FluidParticlePasses {
 public:
  FluidParticlePasses();
  // The backdrop's depth into the bound framebuffer's depth buffer, for drawSurface to test
  // against; needed again only when the backdrop or the framebuffer changed.
  void fillSceneDepth(const SceneDepth& scene, const Eigen::Matrix4f& projection,
                      const FullscreenTriangle& triangle) const;
  // Into the bound framebuffer: attachment 0 depth, attachment 1 thickness, both cleared here; what
  // lies behind the backdrop (its depth buffer) is left out. One pass where the context blends each
  // attachment its own way (GL 4.0, ARB_draw_buffers_blend), else one pass per attachment.
  void drawSurface(const ParticleBuffers& particles, const Eigen::Matrix4f& view,
                   const Eigen::Matrix4f& projection) const;
  // Depth-tested against the composite's depth; writes colour and depth.
  void drawDroplets(const ParticleBuffers& particles, const Eigen::Matrix4f& view,
                    const Eigen::Matrix4f& projection) const;

 private:
  void draw(const GlProgram& program, const ParticleBuffers& particles, const Eigen::Matrix4f& view,
            const Eigen::Matrix4f& projection, bool spray) const;
  GlProgram surface_;
  GlProgram droplets_;
  GlProgram scene_depth_;
  bool blend_per_attachment_;
};

}  // namespace viewer
