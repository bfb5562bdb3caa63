#include "fluid_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace viewer {

namespace {

// Filter settings in particle radii (of the larger class in the frame). A 3-sigma radius of 3.5
// radii (sigma 1.17 radii) flattens the bumps of spheres 1.6 radii apart (the presets' lattice)
// to a degree or two of slope; larger costs taps. The range is wide enough for a layer of
// particles behind another and for steep views, narrow enough to keep a splash in front apart
// from the body behind it.
constexpr float kFilterRadii = 3.5f;
constexpr float kThresholdRadii = 6.0f;
constexpr float kClampRadii = 1.0f;
// The surface pass draws this fraction of the picture's height beyond each of its edges, so the
// filter near an edge has the surface beyond it to average rather than nothing (most of the
// kernel's weight at the nearest water of the window tests' views).
constexpr float kGuardFraction = 0.04f;

int scaled(int size, int scale) { return std::max(1, (size + scale - 1) / scale); }

}  // namespace

int defaultFluidScale() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer == nullptr) return 1;
  for (const char* software : {"llvmpipe", "softpipe", "swrast"}) {
    if (std::strstr(renderer, software) != nullptr) return 2;
  }
  return 1;
}

void FluidRenderer::drawSurface(const ParticleBuffers& particles, const Eigen::Matrix4f& view,
                                const Eigen::Matrix4f& projection, const SurfaceSize& size) {
  // The frustum widened to cover the guard band: x and y of clip space shrink by picture / band.
  Eigen::Matrix4f widened = projection;
  widened.row(0) *= static_cast<float>(size.width) / static_cast<float>(size.width + 2 * size.guard);
  widened.row(1) *= static_cast<float>(size.height) / static_cast<float>(size.height + 2 * size.guard);
  const int gw = size.width + 2 * size.guard, gh = size.height + 2 * size.guard;
  if (surface_target_.bind(gw, gh) || scene_depth_stale_) {
    passes_.fillSceneDepth({backdrop_.depth(), static_cast<float>(scale_), static_cast<float>(size.guard)}, widened,
                           triangle_);
    scene_depth_stale_ = false;
  }
  passes_.drawSurface(particles, view, widened);

  const float r = particles.largestRadius();
  const DepthFilterSettings settings{kFilterRadii * r, kThresholdRadii * r, kClampRadii * r,
                                     projection(1, 1) * static_cast<float>(size.height) / 2.0f};
  filtered_target_.bind(gw, gh);
  filter_.pass(surface_target_.texture(0), true, settings, triangle_);
  smoothed_target_.bind(gw, gh);
  filter_.pass(filtered_target_.texture(0), false, settings, triangle_);
}

void FluidRenderer::draw(const ParticleBuffers& particles, const Eigen::Matrix4f& view,
                         const Eigen::Matrix4f& projection, RenderTarget& target, RenderDebug debug) {
  const int width = target.width(), height = target.height();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  if (backdrop_.update(view, projection, width, height, triangle_)) scene_depth_stale_ = true;
  const SurfaceSize size{scaled(width, scale_), scaled(height, scale_),
                         static_cast<int>(std::ceil(kGuardFraction * static_cast<float>(scaled(height, scale_))))};
  drawSurface(particles, view, projection, size);

  water_target_.bind(size.width, size.height);
  composite_.shade({smoothed_target_.texture(0), surface_target_.texture(1), backdrop_.colour(), backdrop_.depth(),
                    kThresholdRadii * particles.largestRadius(), static_cast<float>(size.guard)},
                   view, projection, debug, triangle_);

  target.bind(width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);  // the present pass writes every pixel's depth
  composite_.present({water_target_.texture(0), water_target_.texture(1), backdrop_.colour(), scale_}, projection,
                     debug, triangle_);
  glDepthFunc(GL_LESS);
  if (debug == RenderDebug::kNone) passes_.drawDroplets(particles, view, projection);
}

}  // namespace viewer
