#include "depth_filter.h"

#include <string>

#include "glsl_common.h"
#include "texture_target.h"

namespace viewer {

namespace {

const char* const kFragmentShader = R"(
uniform sampler2D u_depth;
uniform vec2 u_axis;  // (1, 0) or (0, 1)
uniform float u_radius_m;
uniform float u_threshold_m;
uniform float u_clamp_m;
uniform float u_focal_px;
out float o_depth;

// One side's sample: a farther one than the range counts as lying a little behind the centre; an
// accepted one widens the range. `in_front` flags one nearer than the range.
float accept(float z, float centre, inout float lo, inout float hi, out bool in_front) {
  in_front = z < lo;
  if (z > hi) return centre + u_clamp_m;
  lo = min(lo, z - u_threshold_m);
  hi = max(hi, z + u_threshold_m);
  return z;
}

void main() {
  vec2 size = vec2(textureSize(u_depth, 0));
  vec2 uv = gl_FragCoord.xy / size;
  float centre = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
  float radius_px = u_radius_m * u_focal_px / centre;
  // Samples at most MAX_STRIDE texels apart (bilinear filtering averages what lies between), at
  // most MAX_TAPS a side; Gaussian weights with the radius at 3 sigma.
  int taps = int(clamp(ceil(radius_px / MAX_STRIDE), 1.0, float(MAX_TAPS)));
  vec2 step = u_axis * (radius_px / float(taps)) / size;
  float sum = centre;
  float weights = 1.0;
  float lo_a = centre - u_threshold_m, hi_a = centre + u_threshold_m;
  float lo_b = lo_a, hi_b = hi_a;
  for (int i = 1; i <= taps; ++i) {
    float t = float(i) / float(taps);
    vec2 ua = uv + float(i) * step, ub = uv - float(i) * step;
    float za = texture(u_depth, ua).r, zb = texture(u_depth, ub).r;
    // Past the picture's edge a sample is its mirror reflected through the centre in 1 / depth,
    // which is linear across the screen on a plane: the edge neither tilts nor roughens the surface.
    bool off_a = any(greaterThan(ua, vec2(1.0))), off_b = any(lessThan(ub, vec2(0.0)));
    za = off_a ? 1.0 / max(2.0 / centre - 1.0 / zb, 1e-6) : za;
    zb = off_b ? 1.0 / max(2.0 / centre - 1.0 / za, 1e-6) : zb;
    bool a_front, b_front;
    float a = accept(za, centre, lo_a, hi_a, a_front);
    float b = accept(zb, centre, lo_b, hi_b, b_front);
    // A sample in front drops its mirror too: the kernel stays symmetric, so a surface in front
    // does not tilt the one behind it.
    float w = (a_front || b_front || (off_a && off_b)) ? 0.0 : exp(-4.5 * t * t);
    sum += w * (a + b);
    weights += 2.0 * w;
  }
  o_depth = centre >= kFar ? centre : sum / weights;
}
)";

std::string fragmentSource() {
  const std::string limits = "#define MAX_TAPS " + std::to_string(DepthFilter::kMaxTaps) + "\n#define MAX_STRIDE " +
                             std::to_string(DepthFilter::kMaxStride) + "\n";
  return glslSource({kGlslCommon, limits.c_str(), kFragmentShader});
}

}  // namespace

DepthFilter::DepthFilter()
    : program_(glslSource({kGlslCommon, kFullscreenVertexShader}).c_str(), fragmentSource().c_str(), "depth filter") {}

void DepthFilter::pass(GLuint source, bool horizontal, const DepthFilterSettings& s,
                       const FullscreenTriangle& triangle) const {
  glUseProgram(program_.id());
  bindTexture(program_.uniform("u_depth"), 0, source);
  glUniform2f(program_.uniform("u_axis"), horizontal ? 1.0f : 0.0f, horizontal ? 0.0f : 1.0f);
  glUniform1f(program_.uniform("u_radius_m"), s.radius_m);
  glUniform1f(program_.uniform("u_threshold_m"), s.threshold_m);
  glUniform1f(program_.uniform("u_clamp_m"), s.clamp_m);
  glUniform1f(program_.uniform("u_focal_px"), s.focal_px);
  triangle.draw();
}

}  // namespace viewer
