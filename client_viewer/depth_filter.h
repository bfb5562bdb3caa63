// Smooths the particle depth into a surface: the narrow-range filter of Truong & Yuksel 2018 ("A
// Narrow-Range Filter for Screen-Space Fluid Rendering", PACMCGIT 1(1)), run separably (one
// horizontal and one vertical pass, as they do). A Gaussian over screen space whose samples are
// taken only from a narrow depth range about the pixel's own: a sample nearer than the range is a
// different surface in front, and is ignored together with its mirror sample so the filter stays
// symmetric; a sample farther than the range (the background, a surface behind) counts as lying a
// little behind the pixel, which rounds the silhouettes off; every accepted sample widens the range,
// so slopes are followed.
//
// The kernel's radius is given in world units and converted to pixels at each pixel's depth, so a
// surface is smoothed by the same amount near and far, and L1 and L0 particles (one radius
// for both, from the larger class) merge into one surface without a seam. The samples are bilinear
// and at most kMaxStride texels apart, so each averages what lies between it and the next and the
// spheres' bumps do not alias into the result; past kMaxTaps a side they spread out instead, which
// bounds the cost of close views.
#pragma once

#include <epoxy/gl.h>

#include "fullscreen_pass.h"
#include "gl_program.h"

namespace viewer {

struct DepthFilterSettings {
  float radius_m = 0.0f;     // kernel radius (3 sigma), metres
  float threshold_m = 0.0f;  // half width of the accepted depth range, metres
  float clamp_m = 0.0f;      // how far behind the pixel a farther sample counts, metres
  float focal_px = 0.0f;     // texels per metre at 1 m depth: projection(1,1) * texture height / 2
};

class DepthFilter {
 public:
  static constexpr int kMaxTaps = 24;        // samples per side and pass
  static constexpr float kMaxStride = 2.0f;  // texels between samples

  DepthFilter();
  // One 1D pass from `source` (a GL_LINEAR texture) into the bound framebuffer; `horizontal` picks
  // the axis.
  void pass(GLuint source, bool horizontal, const DepthFilterSettings& settings,
            const FullscreenTriangle& triangle) const;

 private:
  GlProgram program_;
};

}  // namespace viewer
