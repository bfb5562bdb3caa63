#include "particle_renderer.h"

#include <array>

#include "glsl_common.h"
#include "level_colours.h"

namespace viewer {

namespace {

const char* kVertexShader = R"(
uniform mat4 u_view;
uniform mat4 u_projection;
uniform int u_colour_mode;   // 0 size level, 1 speed
uniform float u_max_speed;
out vec2 v_corner;
flat out vec3 v_colour;
flat out float v_radius;
flat out float v_centre_z;

vec3 speedColour(float t) {  // blue -> cyan -> yellow -> red
  t = clamp(t, 0.0, 1.0);
  if (t < 0.33) return mix(vec3(0.1, 0.3, 1.0), vec3(0.1, 0.9, 0.9), t / 0.33);
  if (t < 0.66) return mix(vec3(0.1, 0.9, 0.9), vec3(1.0, 0.9, 0.1), (t - 0.33) / 0.33);
  return mix(vec3(1.0, 0.9, 0.1), vec3(0.95, 0.15, 0.1), (t - 0.66) / 0.34);
}

// One colour per level of the frame (level_colours.h), set per frame.
uniform vec3 u_level_colour[16];
vec3 levelColour(int level) { return u_level_colour[level]; }

void main() {
  float radius = levelRadius();
  vec4 centre = u_view * vec4(a_centre, 1.0);
  v_corner = a_corner;
  v_radius = radius;
  v_centre_z = centre.z;
  if (u_colour_mode == 1) {
    v_colour = speedColour(a_attrs.y / u_max_speed);
  } else {
    v_colour = levelColour(asLevel());
  }
  // The quad sits at the sphere's front (z + r), scaled so its outline on screen is unchanged: the
  // depth buffer then orders spheres by their nearest points, without writing gl_FragDepth (which
  // would turn off early depth testing and halve the fill rate of software GL).
  float scale = (centre.z + radius) / centre.z;
  gl_Position = u_projection * vec4((centre.xy + a_corner * radius) * scale, centre.z + radius, 1.0);
}
)";

const char* kFragmentShader = R"(
in vec2 v_corner;
flat in vec3 v_colour;
flat in float v_radius;
flat in float v_centre_z;
uniform int u_debug;  // 0 shaded, 1 normals, 2 depth (render_settings.h)
out vec4 o_colour;
void main() {
  float d2 = dot(v_corner, v_corner);
  if (d2 > 1.0) discard;
  vec3 normal = vec3(v_corner, sqrt(1.0 - d2));
  if (u_debug == 1) {
    o_colour = vec4(normal * 0.5 + 0.5, 1.0);
    return;
  }
  if (u_debug == 2) {
    o_colour = vec4(encodeMetres(-v_centre_z - v_radius * normal.z), 1.0);
    return;
  }
  vec3 light = normalize(vec3(0.35, 0.6, 1.0));
  float diffuse = max(dot(normal, light), 0.0);
  float specular = pow(max(dot(normal, normalize(light + vec3(0.0, 0.0, 1.0))), 0.0), 40.0);
  o_colour = vec4(v_colour * (0.3 + 0.7 * diffuse) + vec3(0.12 * specular), 1.0);
}
)";

}  // namespace

ParticleRenderer::ParticleRenderer()
    : program_(glslSource({kGlslCommon, kGlslParticleAttributes, kVertexShader}).c_str(),
               glslSource({kGlslCommon, kFragmentShader}).c_str(), "particles") {}

void ParticleRenderer::draw(const ParticleBuffers& particles, const Eigen::Matrix4f& view,
                            const Eigen::Matrix4f& projection, ColourMode mode, RenderDebug debug) const {
  if (particles.count() == 0) return;
  glUseProgram(program_.id());
  glUniformMatrix4fv(program_.uniform("u_view"), 1, GL_FALSE, view.data());
  glUniformMatrix4fv(program_.uniform("u_projection"), 1, GL_FALSE, projection.data());
  particles.setRadii(program_.uniform("u_radius"));
  // Without velocities in the frame speed colouring has nothing to show: fall back to size levels.
  glUniform1i(program_.uniform("u_colour_mode"), mode == ColourMode::kSpeed && particles.hasSpeed() ? 1 : 0);
  glUniform1f(program_.uniform("u_max_speed"), particles.maxSpeed());
  std::array<float, 3 * kMaxSizeLevels> colours{};
  for (std::size_t level = 0; level < kMaxSizeLevels; ++level) {
    const LevelRgb c = levelColour(level, particles.levelCount());
    colours[3 * level] = c.r;
    colours[3 * level + 1] = c.g;
    colours[3 * level + 2] = c.b;
  }
  glUniform3fv(program_.uniform("u_level_colour"), static_cast<GLsizei>(kMaxSizeLevels), colours.data());
  glUniform1i(program_.uniform("u_debug"), static_cast<int>(debug));
  particles.draw();
}

}  // namespace viewer
