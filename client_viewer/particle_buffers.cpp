#include "particle_buffers.h"

#include <algorithm>

namespace viewer {

const char* const kGlslParticleFetch = R"(
uniform samplerBuffer u_particles;   // x, y, z (world), size class (0 SMALL, 1 LARGE)
uniform samplerBuffer u_attributes;  // speed, neighbours
int particleIndex() { return gl_VertexID / 6; }
// Two triangles, (0, 1, 2) and (2, 1, 3), of the corners (-1, -1), (1, -1), (-1, 1), (1, 1).
vec2 quadCorner() {
  int k = gl_VertexID % 6;
  return vec2(k == 1 || k == 4 || k == 5 ? 1.0 : -1.0, k == 2 || k == 3 || k == 5 ? 1.0 : -1.0);
}
)";

namespace {
constexpr int kParticleUnit = 6;
constexpr int kAttributeUnit = 7;
constexpr GLsizei kVerticesPerParticle = 6;
}  // namespace

ParticleBuffers::ParticleBuffers() {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(2, buffers_);
  glGenTextures(2, textures_);
}

ParticleBuffers::~ParticleBuffers() {
  glDeleteTextures(2, textures_);
  glDeleteBuffers(2, buffers_);
  glDeleteVertexArrays(1, &vao_);
}

void ParticleBuffers::upload(const DecodedFrame& frame) {
  const std::size_t n = frame.particleCount();
  count_ = static_cast<GLsizei>(n);
  radius_[0] = frame.radius_small;
  radius_[1] = frame.radius_large;
  has_class_[0] = frame.small_count > 0;
  has_class_[1] = frame.large_count > 0;
  has_speed_ = !frame.speeds.empty();
  has_counts_ = !frame.neighbor_counts.empty();
  max_speed_ = 1e-3f;
  particles_.resize(4 * n);
  attributes_.resize(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3f& p = frame.positions[i];
    float* out = particles_.data() + 4 * i;
    out[0] = p.x;
    out[1] = p.y;
    out[2] = p.z;
    out[3] = static_cast<float>(frame.classes[i]);
    attributes_[2 * i] = has_speed_ ? frame.speeds[i] : 0.0f;
    attributes_[2 * i + 1] = has_counts_ ? static_cast<float>(frame.neighbor_counts[i]) : kUnknownNeighbours;
    if (has_speed_) max_speed_ = std::max(max_speed_, frame.speeds[i]);
  }
  const std::vector<float>* data[2] = {&particles_, &attributes_};
  const GLenum formats[2] = {GL_RGBA32F, GL_RG32F};
  for (int b = 0; b < 2; ++b) {
    // Orphan and refill: the driver may still be drawing from the previous contents.
    glBindBuffer(GL_TEXTURE_BUFFER, buffers_[b]);
    glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(data[b]->size() * sizeof(float)), data[b]->data(),
                 GL_STREAM_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, textures_[b]);
    glTexBuffer(GL_TEXTURE_BUFFER, formats[b], buffers_[b]);
  }
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

float ParticleBuffers::largestRadius() const {
  float r = 0.0f;
  for (int c = 0; c < 2; ++c) {
    if (has_class_[c]) r = std::max(r, radius_[c]);
  }
  return r;
}

void ParticleBuffers::draw(GLuint program) const {
  if (count_ == 0) return;
  glActiveTexture(GL_TEXTURE0 + kParticleUnit);
  glBindTexture(GL_TEXTURE_BUFFER, textures_[0]);
  glActiveTexture(GL_TEXTURE0 + kAttributeUnit);
  glBindTexture(GL_TEXTURE_BUFFER, textures_[1]);
  glActiveTexture(GL_TEXTURE0);
  glUniform1i(glGetUniformLocation(program, "u_particles"), kParticleUnit);
  glUniform1i(glGetUniformLocation(program, "u_attributes"), kAttributeUnit);
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, kVerticesPerParticle * count_);
  glBindVertexArray(0);
}

}  // namespace viewer
