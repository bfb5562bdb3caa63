#include "texture_target.h"

#include <stdexcept>

namespace viewer {

TextureTarget::~TextureTarget() { release(); }

void TextureTarget::release() {
  if (!textures_.empty()) glDeleteTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
  if (depth_ != 0) glDeleteRenderbuffers(1, &depth_);
  if (framebuffer_ != 0) glDeleteFramebuffers(1, &framebuffer_);
  textures_.clear();
  depth_ = framebuffer_ = 0;
  width_ = height_ = 0;
}

void TextureTarget::allocate(int width, int height) {
  release();
  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  textures_.resize(specs_.size());
  glGenTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
  std::vector<GLenum> draw_buffers;
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const bool rgba = specs_[i].internal_format == GL_RGBA8;
    glBindTexture(GL_TEXTURE_2D, textures_[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(specs_[i].internal_format), width, height, 0,
                 rgba ? GL_RGBA : GL_RED, rgba ? GL_UNSIGNED_BYTE : GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(specs_[i].filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(specs_[i].filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, textures_[i], 0);
    draw_buffers.push_back(attachment);
  }
  glDrawBuffers(static_cast<GLsizei>(draw_buffers.size()), draw_buffers.data());
  if (with_depth_) {
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("fluid framebuffer is incomplete (float colour targets unsupported?)");
  }
  width_ = width;
  height_ = height;
}

bool TextureTarget::bind(int width, int height) {
  const bool reallocate = width != width_ || height != height_ || framebuffer_ == 0;
  if (reallocate) allocate(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
  return reallocate;
}

void bindTexture(GLint location, int unit, GLuint texture) {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D, texture);
  glUniform1i(location, unit);
}

}  // namespace viewer
