#include "fluid_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace viewer {

namespace {

// Filter settings in particle radii (of the larger class in the frame). A 3-sigma radius of 4.5
// radii (sigma 1.5 radii) flattens the bumps of spheres 2 radii apart to well under a degree of
// slope; the range is wide enough for a layer of particles behind another (2 radii) and for steep
// views, narrow enough to keep a splash in front apart from the body behind it.
constexpr float kFilterRadii = 4.5f;
constexpr float kThresholdRadii = 6.0f;
constexpr float kClampRadii = 1.0f;
// The surface passes draw this fraction of the picture's height beyond each of its edges, so the
// filter near an edge has the surface beyond it to average rather than nothing.
constexpr float kGuardFraction = 0.06f;

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
  surface_target_.bind(gw, gh);
  passes_.drawSurface(particles, view, widened,
                      {backdrop_.depth(), static_cast<float>(scale_), static_cast<float>(size.guard)});

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
  backdrop_.update(view, projection, width, height, triangle_);
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
