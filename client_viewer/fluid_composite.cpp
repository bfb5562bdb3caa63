#include "fluid_composite.h"

#include "glsl_common.h"
#include "texture_target.h"

namespace viewer {

namespace {

const char* const kShadeShader = R"(
uniform sampler2D u_surface;
uniform sampler2D u_thickness;
uniform sampler2D u_backdrop;
uniform sampler2D u_backdrop_depth;
uniform vec2 u_proj_scale;  // projection (0,0), (1,1)
uniform mat3 u_view_to_world;
uniform int u_debug;        // 0 shaded, 1 normals, 2 depth, 3 thickness (render_settings.h)
uniform float u_step_m;     // a neighbour farther behind than this is another surface
uniform float u_guard;      // texels of u_surface and u_thickness beyond each edge of the picture
layout(location = 0) out vec4 o_water;
layout(location = 1) out float o_depth;

// Absorption per metre of summed sphere chords (about the water's depth: the presets' particle
// spheres hold the particle's volume), red most: a few centimetres tint, half a metre is deep blue.
const vec3 kAbsorption = vec3(11.0, 4.2, 2.4);
const vec3 kDeepWater = vec3(0.015, 0.09, 0.16);
const float kRefraction = 0.25;  // uv offset per metre of thickness and unit of normal
const float kMaxRefractThickness = 0.15;

vec3 viewPosition(vec2 uv, float depth) { return vec3((uv * 2.0 - 1.0) / u_proj_scale * depth, -depth); }

// Of the differences towards the two neighbours along one axis, the one smaller in depth; a
// neighbour without water (or on a surface behind) does not count.
vec3 difference(vec3 p, vec3 forward_p, vec3 backward_p, bool forward_ok, bool backward_ok) {
  vec3 forward = forward_p - p;
  vec3 backward = p - backward_p;
  if (!forward_ok) return backward_ok ? backward : vec3(0.0);
  if (!backward_ok) return forward;
  return abs(forward.z) < abs(backward.z) ? forward : backward;
}

// Picture uv -> uv of the guard-banded surface textures.
vec2 surfaceUv(vec2 uv) {
  vec2 size = vec2(textureSize(u_surface, 0));
  return (uv * (size - 2.0 * u_guard) + u_guard) / size;
}
float surfaceAt(vec2 uv) { return texture(u_surface, surfaceUv(uv)).r; }

// The neighbours are 1.5 texels away, sampled bilinearly: each averages two texels, and the
// difference spans 1.5, which together quiet the pixel-scale noise a finite difference of one
// texel makes of what the filter left of the particles' bumps.
vec3 normalAt(vec2 uv, vec2 texel, float depth, vec3 centre) {
  vec2 hx = vec2(1.5 * texel.x, 0.0);
  vec2 hy = vec2(0.0, 1.5 * texel.y);
  float right = surfaceAt(uv + hx);
  float left = surfaceAt(uv - hx);
  float up = surfaceAt(uv + hy);
  float down = surfaceAt(uv - hy);
  float limit = depth + u_step_m;  // a mix with "no water" reads far behind
  vec3 dx = difference(centre, viewPosition(uv + hx, right), viewPosition(uv - hx, left), right < limit, left < limit);
  vec3 dy = difference(centre, viewPosition(uv + hy, up), viewPosition(uv - hy, down), up < limit, down < limit);
  vec3 n = cross(dx, dy);
  return dot(n, n) > 0.0 ? normalize(n) : vec3(0.0, 0.0, 1.0);
}

void main() {
  vec2 texel = 1.0 / (vec2(textureSize(u_surface, 0)) - 2.0 * u_guard);  // of the picture, this pass's scale
  vec2 uv = gl_FragCoord.xy * texel;
  float depth = texelFetch(u_surface, ivec2(gl_FragCoord.xy + u_guard), 0).r;
  vec3 centre = viewPosition(uv, depth);
  vec3 n = normalAt(uv, texel, depth, centre);
  // Thickness blurred over about 4 x 4 texels: four bilinear samples around the centre. Summed
  // sphere chords vary from particle to particle, which absorption would show as blotches.
  vec2 tuv = surfaceUv(uv);
  vec2 tt = 1.0 / vec2(textureSize(u_thickness, 0));
  float thickness = 0.25 * (texture(u_thickness, tuv + vec2(1.5, 0.5) * tt).r +
                            texture(u_thickness, tuv + vec2(-0.5, 1.5) * tt).r +
                            texture(u_thickness, tuv + vec2(-1.5, -0.5) * tt).r +
                            texture(u_thickness, tuv + vec2(0.5, -1.5) * tt).r);

  vec3 v = -normalize(centre);
  float m = 1.0 - max(dot(n, v), 0.0);
  float fresnel = 0.02 + 0.98 * m * m * m * m * m;
  vec3 reflected = skyColour(u_view_to_world * reflect(-v, n));
  vec2 refracted_uv = uv + n.xy * kRefraction * min(thickness, kMaxRefractThickness);
  vec3 transmittance = exp(-kAbsorption * thickness);
  vec3 body = texture(u_backdrop, refracted_uv).rgb * transmittance + kDeepWater * (1.0 - transmittance);
  vec3 sun = transpose(u_view_to_world) * kSunDirection;
  float h = max(dot(n, normalize(sun + v)), 0.0);
  h *= h; h *= h; h *= h; h *= h; h *= h; h *= h; h *= h; h *= h;  // h^256: a small, sharp highlight
  vec3 colour = mix(body, reflected, fresnel) + vec3(1.5 * h);

  if (u_debug == 1) colour = n * 0.5 + 0.5;
  if (u_debug == 2) colour = encodeMetres(depth);
  if (u_debug == 3) colour = encodeMetres(thickness);
  float scene_depth = texture(u_backdrop_depth, uv).r;
  bool water = depth < kFar && depth < scene_depth;
  o_water = water ? vec4(colour, 1.0) : vec4(0.0);
  o_depth = min(depth, scene_depth);
}
)";

// Two programs from one source: DEBUG set, the shaded pixel itself (debug encodings are numbers,
// never a blend of neighbours), else the water blended over the backdrop.
const char* const kPresentShader = R"(
uniform sampler2D u_water;
uniform sampler2D u_depth;
uniform sampler2D u_backdrop;
uniform vec2 u_depth_proj;  // projection (2,2), (2,3): clip z = a z + b for view-space z
uniform int u_scale;
uniform vec4 u_marker;      // debug: the colour of "no water"
in vec2 v_uv;
out vec4 o_colour;

void main() {
#ifdef DEBUG
  vec4 water = texelFetch(u_water, ivec2(gl_FragCoord.xy) / u_scale, 0);
  o_colour = water.a > 0.5 ? vec4(water.rgb, 1.0) : u_marker;
#else
  vec4 water = texture(u_water, v_uv);
  o_colour = vec4(texture(u_backdrop, v_uv).rgb * (1.0 - water.a) + water.rgb, 1.0);
#endif
  gl_FragDepth = windowDepth(texture(u_depth, v_uv).r, u_depth_proj);
}
)";

}  // namespace

FluidComposite::FluidComposite()
    : shade_(glslSource({kGlslCommon, kFullscreenVertexShader}).c_str(),
             glslSource({kGlslCommon, kShadeShader}).c_str(), "fluid shade"),
      present_(glslSource({kGlslCommon, kFullscreenVertexShader}).c_str(),
               glslSource({kGlslCommon, kPresentShader}).c_str(), "fluid present"),
      present_debug_(glslSource({kGlslCommon, kFullscreenVertexShader}).c_str(),
                     glslSource({kGlslCommon, "#define DEBUG\n", kPresentShader}).c_str(), "fluid present debug") {}

void FluidComposite::shade(const ShadeInputs& in, const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection,
                           RenderDebug debug, const FullscreenTriangle& triangle) const {
  glUseProgram(shade_.id());
  bindTexture(shade_.uniform("u_surface"), 0, in.surface_depth);
  bindTexture(shade_.uniform("u_thickness"), 1, in.thickness);
  bindTexture(shade_.uniform("u_backdrop"), 2, in.backdrop);
  bindTexture(shade_.uniform("u_backdrop_depth"), 3, in.backdrop_depth);
  glUniform2f(shade_.uniform("u_proj_scale"), projection(0, 0), projection(1, 1));
  const Eigen::Matrix3f view_to_world = view.block<3, 3>(0, 0).transpose();
  glUniformMatrix3fv(shade_.uniform("u_view_to_world"), 1, GL_FALSE, view_to_world.data());
  glUniform1i(shade_.uniform("u_debug"), static_cast<int>(debug));
  glUniform1f(shade_.uniform("u_step_m"), in.step_m);
  glUniform1f(shade_.uniform("u_guard"), in.guard);
  triangle.draw();
  glActiveTexture(GL_TEXTURE0);
}

void FluidComposite::present(const PresentInputs& in, const Eigen::Matrix4f& projection, RenderDebug debug,
                             const FullscreenTriangle& triangle) const {
  const GlProgram& program = debug == RenderDebug::kNone ? present_ : present_debug_;
  glUseProgram(program.id());
  bindTexture(program.uniform("u_water"), 0, in.water);
  bindTexture(program.uniform("u_depth"), 1, in.depth);
  bindTexture(program.uniform("u_backdrop"), 2, in.backdrop);
  glUniform2f(program.uniform("u_depth_proj"), projection(2, 2), projection(2, 3));
  glUniform1i(program.uniform("u_scale"), in.scale);
  // render_settings.h: normals mark "no water" black, the depth encodings white.
  const float marker = debug == RenderDebug::kNormals ? 0.0f : 1.0f;
  glUniform4f(program.uniform("u_marker"), marker, marker, marker, 1.0f);
  triangle.draw();
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace viewer
