#include "particle_buffers.h"

#include <algorithm>

namespace viewer {

// The array length is kMaxSizeLevels; levels past the frame's have radius 0 and draw nothing.
const char* const kGlslParticleAttributes = R"(
layout(location = 0) in vec2 a_corner;
layout(location = 1) in vec3 a_centre;
layout(location = 2) in vec3 a_attrs;
uniform float u_radius[16];
int asLevel() { return clamp(int(a_attrs.x + 0.5), 0, 15); }
float levelRadius() { return u_radius[asLevel()]; }
)";
static_assert(kMaxSizeLevels == 16, "kGlslParticleAttributes sizes u_radius by kMaxSizeLevels");

namespace {
constexpr float kQuad[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
constexpr int kAttributes = 3;  // size level, speed, neighbours
}  // namespace

ParticleBuffers::ParticleBuffers() {
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
  glVertexAttribPointer(2, kAttributes, GL_FLOAT, GL_FALSE, 0, nullptr);
  glVertexAttribDivisor(2, 1);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

ParticleBuffers::~ParticleBuffers() {
  glDeleteBuffers(1, &attribute_buffer_);
  glDeleteBuffers(1, &centre_buffer_);
  glDeleteBuffers(1, &quad_buffer_);
  glDeleteVertexArrays(1, &vao_);
}

void ParticleBuffers::upload(const DecodedFrame& frame) {
  const std::size_t n = frame.particleCount();
  count_ = static_cast<GLsizei>(n);
  radius_.fill(0.0f);
  has_level_.fill(false);
  for (std::size_t level = 0; level < std::min(frame.level_radii.size(), kMaxSizeLevels); ++level) {
    radius_[level] = frame.level_radii[level];
    has_level_[level] = level < frame.level_counts.size() && frame.level_counts[level] > 0;
  }
  level_count_ = std::min(frame.colourLevelCount(), kMaxSizeLevels);
  has_speed_ = !frame.speeds.empty();
  has_counts_ = !frame.neighbor_counts.empty();
  max_speed_ = 1e-3f;
  staging_.resize(kAttributes * n);
  for (std::size_t i = 0; i < n; ++i) {
    float* a = staging_.data() + kAttributes * i;
    a[0] = static_cast<float>(frame.classes[i]);
    a[1] = has_speed_ ? frame.speeds[i] : 0.0f;
    a[2] = has_counts_ ? static_cast<float>(frame.neighbor_counts[i]) : kUnknownNeighbours;
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

float ParticleBuffers::largestRadius() const {
  float r = 0.0f;
  for (std::size_t level = 0; level < kMaxSizeLevels; ++level) {
    if (has_level_[level]) r = std::max(r, radius_[level]);
  }
  return r;
}

void ParticleBuffers::setRadii(GLint location) const {
  glUniform1fv(location, static_cast<GLsizei>(radius_.size()), radius_.data());
}

void ParticleBuffers::draw() const {
  if (count_ == 0) return;
  glBindVertexArray(vao_);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count_);
  glBindVertexArray(0);
}

}  // namespace viewer
