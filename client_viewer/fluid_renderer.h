// Fluid mode: the particles drawn as one liquid surface in screen space (van der Laan, Green & Sainz
// 2009, "Screen Space Fluid Rendering with Curvature Flow", I3D; Green 2010; the depth filter of
// Truong & Yuksel 2018). No mesh: per picture
//   1. the backdrop (sky, ground, floor, walls, obstacles) with its depth, kept while the camera
//      stands still (scene_backdrop.h);
//   2. the particles' nearest sphere depth and 3. their summed thickness (fluid_particle_passes.h);
//   4. the depth smoothed by a narrow-range filter whose radius is in world units (depth_filter.h);
//   5. shading: normals, Fresnel, refraction, absorption, highlight; 6. the water over the backdrop
//      (fluid_composite.h);
//   7. spray droplets, when the frame's neighbour counts mark some particles as spray.
// Passes 2 to 5 run at 1 / scale of the picture's resolution each way, so that software GL, which
// pays for every pixel of every pass, keeps a usable frame rate.
// client_viewer/README.md describes the passes and their settings.
#pragma once

#include <Eigen/Core>

#include "depth_filter.h"
#include "fluid_composite.h"
#include "fluid_particle_passes.h"
#include "fullscreen_pass.h"
#include "particle_buffers.h"
#include "render_settings.h"
#include "render_target.h"
#include "scene_backdrop.h"
#include "texture_target.h"

namespace viewer {

class FluidRenderer {
 public:
  // `scale`: 1 full resolution, 2 half (see defaultFluidScale()).
  explicit FluidRenderer(int scale = 1) : scale_(scale) {}
  void setScale(int scale) {
    scale_ = scale;
    scene_depth_stale_ = true;
  }
  void setGeometry(const SceneGeometry& geometry) { backdrop_.setGeometry(geometry); }
  // Draws the water into `target` and leaves it bound, with the picture's depth in its depth buffer
  // (depth test on, GL_LESS, blending off).
  void draw(const ParticleBuffers& particles, const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection,
            RenderTarget& target, RenderDebug debug);

 private:
  struct SurfaceSize {
    int width, height;  // the picture at the surface passes' scale
    int guard;          // texels drawn beyond each edge
  };
  void drawSurface(const ParticleBuffers& particles, const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection,
                   const SurfaceSize& size);

  int scale_;
  bool scene_depth_stale_ = true;  // the surface target's depth buffer no longer the backdrop's
  FullscreenTriangle triangle_;
  SceneBackdrop backdrop_;
  FluidParticlePasses passes_;
  DepthFilter filter_;
  FluidComposite composite_;
  // The surface passes' targets hold a guard band around the picture (fluid_renderer.cpp).
  TextureTarget surface_target_{{{GL_R32F, GL_LINEAR}, {GL_R32F, GL_LINEAR}}};  // raw depth, thickness
  TextureTarget filtered_target_{{{GL_R32F, GL_LINEAR}}};                       // between the filter passes
  TextureTarget smoothed_target_{{{GL_R32F, GL_LINEAR}}};
  TextureTarget water_target_{{{GL_RGBA8, GL_LINEAR}, {GL_R32F, GL_NEAREST}}};
};

// The fluid passes' scale for the current context: 2 on software GL (llvmpipe, softpipe, swrast),
// whose cost grows with every pixel of every pass, 1 on a GPU.
int defaultFluidScale();

}  // namespace viewer
