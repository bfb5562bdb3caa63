#include "fluid_particle_passes.h"

#include "fullscreen_pass.h"
#include "glsl_common.h"
#include "texture_target.h"

namespace viewer {

namespace {

constexpr float kFar = 1.0e4f;  // glsl_common.cpp

const char* const kVertexShader = R"(
uniform mat4 u_view;
uniform mat4 u_projection;
uniform float u_spray_max;     // neighbours <= this: spray
uniform int u_spray;           // 1: draw the spray particles, 0: the others
uniform float u_radius_scale;
out vec2 v_corner;
flat out float v_radius;
flat out float v_centre_z;

void main() {
  bool spray = a_attrs.z <= u_spray_max;
  if (spray != (u_spray == 1)) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: the quad is culled
    return;
  }
  float radius = levelRadius() * u_radius_scale;
  vec4 centre = u_view * vec4(a_centre, 1.0);
  v_corner = a_corner;
  v_radius = radius;
  v_centre_z = centre.z;
  // The quad at the sphere's front, scaled to keep its outline (as particle_renderer.cpp): the
  // droplets are depth-tested, and early depth tests need the quad's own depth to be right.
  float scale = (centre.z + radius) / centre.z;
  gl_Position = u_projection * vec4((centre.xy + a_corner * radius) * scale, centre.z + radius, 1.0);
}
)";

// The surface sees only the water in front of the backdrop (an obstacle hides what is behind it):
// the depth test against the backdrop's depth (fillSceneDepth) rejects the rest before shading.
const char* const kSurfaceFragment = R"(
in vec2 v_corner;
flat in float v_radius;
flat in float v_centre_z;
layout(location = 0) out float o_depth;
layout(location = 1) out float o_thickness;
void main() {
  float d2 = dot(v_corner, v_corner);
  if (d2 > 1.0) discard;
  float half_chord = v_radius * sqrt(1.0 - d2);
  o_depth = -v_centre_z - half_chord;
  o_thickness = 2.0 * half_chord;
}
)";

// The backdrop's depth (metres along the view axis) into the depth buffer of the surface target:
// u_scene_scale and u_scene_guard map this pass's pixels onto the backdrop's (in the guard band,
// onto the nearest pixel at the picture's edge).
const char* const kSceneDepthFragment = R"(
uniform sampler2D u_scene_depth;
uniform float u_scene_scale;
uniform float u_scene_guard;
uniform vec2 u_depth_proj;
void main() {
  ivec2 at = ivec2((gl_FragCoord.xy - u_scene_guard) * u_scene_scale);
  float scene = texelFetch(u_scene_depth, clamp(at, ivec2(0), textureSize(u_scene_depth, 0) - 1), 0).r;
  gl_FragDepth = windowDepth(scene, u_depth_proj);
}
)";

const char* const kDropletFragment = R"(
uniform mat3 u_view_to_world;
in vec2 v_corner;
out vec4 o_colour;
void main() {
  float d2 = dot(v_corner, v_corner);
  if (d2 > 1.0) discard;
  vec3 n = vec3(v_corner, sqrt(1.0 - d2));
  // Schlick's Fresnel term with water's F0 = 0.02; the view direction is taken as +z.
  float fresnel = 0.02 + 0.98 * pow(1.0 - n.z, 5.0);
  vec3 sky = skyColour(u_view_to_world * reflect(vec3(0.0, 0.0, -1.0), n));
  vec3 sun = transpose(u_view_to_world) * kSunDirection;
  float specular = pow(max(dot(n, normalize(sun + vec3(0.0, 0.0, 1.0))), 0.0), 80.0);
  vec3 body = vec3(0.70, 0.84, 0.92) * (0.55 + 0.45 * max(dot(n, sun), 0.0));
  o_colour = vec4(mix(body, sky, fresnel) + vec3(specular), 1.0);
}
)";

}  // namespace

FluidParticlePasses::FluidParticlePasses()
    : surface_(glslSource({kGlslCommon, kGlslParticleAttributes, kVertexShader}).c_str(),
               glslSource({kGlslCommon, kSurfaceFragment}).c_str(), "fluid surface"),
      droplets_(glslSource({kGlslCommon, kGlslParticleAttributes, kVertexShader}).c_str(),
                glslSource({kGlslCommon, kDropletFragment}).c_str(), "fluid droplets"),
      scene_depth_(glslSource({kGlslCommon, kFullscreenVertexShader}).c_str(),
                   glslSource({kGlslCommon, kSceneDepthFragment}).c_str(), "fluid scene depth"),
      blend_per_attachment_(epoxy_gl_version() >= 40 || epoxy_has_gl_extension("GL_ARB_draw_buffers_blend")) {}

void FluidParticlePasses::draw(const GlProgram& program, const ParticleBuffers& particles, const Eigen::Matrix4f& view,
                               const Eigen::Matrix4f& projection, bool spray) const {
  if (particles.count() == 0) return;
  glUseProgram(program.id());
  glUniformMatrix4fv(program.uniform("u_view"), 1, GL_FALSE, view.data());
  glUniformMatrix4fv(program.uniform("u_projection"), 1, GL_FALSE, projection.data());
  particles.setRadii(program.uniform("u_radius"));
  glUniform1f(program.uniform("u_spray_max"), static_cast<float>(kSprayMaxNeighbours));
  glUniform1i(program.uniform("u_spray"), spray ? 1 : 0);
  glUniform1f(program.uniform("u_radius_scale"), spray ? kDropletRadiusScale : kSurfaceRadiusScale);
  particles.draw();
}

void FluidParticlePasses::fillSceneDepth(const SceneDepth& scene, const Eigen::Matrix4f& projection,
                                         const FullscreenTriangle& triangle) const {
  glUseProgram(scene_depth_.id());
  bindTexture(scene_depth_.uniform("u_scene_depth"), 0, scene.texture);
  glUniform1f(scene_depth_.uniform("u_scene_scale"), scene.scale);
  glUniform1f(scene_depth_.uniform("u_scene_guard"), scene.guard);
  glUniform2f(scene_depth_.uniform("u_depth_proj"), projection(2, 2), projection(2, 3));
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  triangle.draw();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
}

void FluidParticlePasses::drawSurface(const ParticleBuffers& particles, const Eigen::Matrix4f& view,
                                      const Eigen::Matrix4f& projection) const {
  const float far[4] = {kFar, kFar, kFar, kFar};
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, far);
  glClearBufferfv(GL_COLOR, 1, zero);
  // Tested against the backdrop's depth, never written: the quads lie at the spheres' fronts, so a
  // sphere whose front is behind an obstacle is rejected before its fragments are shaded.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  if (blend_per_attachment_) {
    glBlendEquationi(0, GL_MIN);
    glBlendEquationi(1, GL_FUNC_ADD);
    draw(surface_, particles, view, projection, false);
  } else {
    // Without per-attachment blending: the same program twice, each time writing one attachment.
    glBlendEquation(GL_MIN);
    glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    draw(surface_, particles, view, projection, false);
    glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glBlendEquation(GL_FUNC_ADD);
    draw(surface_, particles, view, projection, false);
    glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
}

void FluidParticlePasses::drawDroplets(const ParticleBuffers& particles, const Eigen::Matrix4f& view,
                                       const Eigen::Matrix4f& projection) const {
  if (!particles.hasNeighbourCounts()) return;  // then no particle is spray
  glUseProgram(droplets_.id());
  const Eigen::Matrix3f view_to_world = view.block<3, 3>(0, 0).transpose();
  glUniformMatrix3fv(droplets_.uniform("u_view_to_world"), 1, GL_FALSE, view_to_world.data());
  draw(droplets_, particles, view, projection, true);
}

}  // namespace viewer
