#include "particle_renderer.h"

#include <algorithm>

namespace viewer {

namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 a_corner;   // quad corner, -1..1
layout(location = 1) in vec3 a_centre;   // particle centre, world
layout(location = 2) in vec2 a_attrs;    // size class (0 SMALL, 1 LARGE), speed
uniform mat4 u_view;
uniform mat4 u_projection;
uniform float u_radius[2];
uniform int u_colour_mode;   // 0 class, 1 speed
uniform float u_max_speed;
out vec2 v_corner;
flat out vec3 v_colour;

vec3 speedColour(float t) {  // blue -> cyan -> yellow -> red
  t = clamp(t, 0.0, 1.0);
  if (t < 0.33) return mix(vec3(0.1, 0.3, 1.0), vec3(0.1, 0.9, 0.9), t / 0.33);
  if (t < 0.66) return mix(vec3(0.1, 0.9, 0.9), vec3(1.0, 0.9, 0.1), (t - 0.33) / 0.33);
  return mix(vec3(1.0, 0.9, 0.1), vec3(0.95, 0.15, 0.1), (t - 0.66) / 0.34);
}

void main() {
  int size_class = a_attrs.x > 0.5 ? 1 : 0;
  float radius = u_radius[size_class];
  vec4 centre = u_view * vec4(a_centre, 1.0);
  v_corner = a_corner;
  if (u_colour_mode == 1) {
    v_colour = speedColour(a_attrs.y / u_max_speed);
  } else {
    v_colour = size_class == 1 ? vec3(0.92, 0.18, 0.12) : vec3(0.15, 0.38, 1.0);
  }
  // The quad sits at the sphere's front (z + r), scaled so its outline on screen is unchanged: the
  // depth buffer then orders spheres by their nearest points, without writing gl_FragDepth (which
  // would turn off early depth testing and halve the fill rate of software GL).
  float scale = (centre.z + radius) / centre.z;
  gl_Position = u_projection * vec4((centre.xy + a_corner * radius) * scale, centre.z + radius, 1.0);
}
)";

const char* kFragmentShader = R"(#version 330 core
in vec2 v_corner;
flat in vec3 v_colour;
out vec4 o_colour;
void main() {
  float d2 = dot(v_corner, v_corner);
  if (d2 > 1.0) discard;
  vec3 normal = vec3(v_corner, sqrt(1.0 - d2));
  vec3 light = normalize(vec3(0.35, 0.6, 1.0));
  float diffuse = max(dot(normal, light), 0.0);
  float specular = pow(max(dot(normal, normalize(light + vec3(0.0, 0.0, 1.0))), 0.0), 40.0);
  o_colour = vec4(v_colour * (0.3 + 0.7 * diffuse) + vec3(0.12 * specular), 1.0);
}
)";

constexpr float kQuad[8] = {-1, -1, 1, -1, -1, 1, 1, 1};

}  // namespace

ParticleRenderer::ParticleRenderer() : program_(kVertexShader, kFragmentShader, "particles") {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &quad_buffer_);
  glGenBuffers(1, &centre_buffer_);
  glGenBuffers(1, &attribute_buffer_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, quad_buffer_);
  glBufferData(GL_ARRAY_BUFFER, sizeof(kQuad), kQuad, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, centre_buffer_);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glVertexAttribDivisor(1, 1);
  glBindBuffer(GL_ARRAY_BUFFER, attribute_buffer_);
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glVertexAttribDivisor(2, 1);
  glBindVertexArray(0);
}

ParticleRenderer::~ParticleRenderer() {
  glDeleteBuffers(1, &attribute_buffer_);
  glDeleteBuffers(1, &centre_buffer_);
  glDeleteBuffers(1, &quad_buffer_);
  glDeleteVertexArrays(1, &vao_);
}

void ParticleRenderer::upload(const DecodedFrame& frame) {
  const std::size_t n = frame.particleCount();
  count_ = static_cast<GLsizei>(n);
  radius_[0] = frame.radius_small;
  radius_[1] = frame.radius_large;
  has_speed_ = !frame.speeds.empty();
  max_speed_ = 1e-3f;
  staging_.resize(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    staging_[2 * i] = static_cast<float>(frame.classes[i]);
    staging_[2 * i + 1] = has_speed_ ? frame.speeds[i] : 0.0f;
    if (has_speed_) max_speed_ = std::max(max_speed_, frame.speeds[i]);
  }
  // Orphan and refill: the driver may still be drawing from the previous contents.
  glBindBuffer(GL_ARRAY_BUFFER, centre_buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(n * sizeof(Vec3f)), frame.positions.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, attribute_buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(staging_.size() * sizeof(float)), staging_.data(),
               GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void ParticleRenderer::draw(const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection, ColourMode mode) const {
  if (count_ == 0) return;
  glUseProgram(program_.id());
  glUniformMatrix4fv(program_.uniform("u_view"), 1, GL_FALSE, view.data());
  glUniformMatrix4fv(program_.uniform("u_projection"), 1, GL_FALSE, projection.data());
  glUniform1fv(program_.uniform("u_radius"), 2, radius_);
  // Without velocities in the frame speed colouring has nothing to show: fall back to classes.
  glUniform1i(program_.uniform("u_colour_mode"), mode == ColourMode::kSpeed && has_speed_ ? 1 : 0);
  glUniform1f(program_.uniform("u_max_speed"), max_speed_);
  glBindVertexArray(vao_);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count_);
  glBindVertexArray(0);
}

}  // namespace viewer
