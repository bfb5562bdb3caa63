// A framebuffer whose colour attachments are textures that later passes sample: the fluid mode's
// intermediate pictures (backdrop, depth, thickness). Reallocated when the size changes.
#pragma once

#include <epoxy/gl.h>

#include <utility>
#include <vector>

namespace viewer {

struct TextureSpec {
  GLenum internal_format;  // GL_RGBA8, GL_R32F, GL_R16F
  GLenum filter;           // GL_NEAREST for depths (no blending across silhouettes), GL_LINEAR else
};

class TextureTarget {
 public:
  explicit TextureTarget(std::vector<TextureSpec> attachments) : specs_(std::move(attachments)) {}
  ~TextureTarget();
  TextureTarget(const TextureTarget&) = delete;
  TextureTarget& operator=(const TextureTarget&) = delete;

  // (Re)allocates when the size changed; binds the framebuffer, every attachment drawn to, and sets
  // the viewport.
  void bind(int width, int height);
  GLuint texture(std::size_t attachment) const { return textures_[attachment]; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void allocate(int width, int height);
  void release();
  std::vector<TextureSpec> specs_;
  std::vector<GLuint> textures_;
  GLuint framebuffer_ = 0;
  int width_ = 0;
  int height_ = 0;
};

// Binds `texture` to texture unit `unit` and points the sampler uniform `location` at it.
void bindTexture(GLint location, int unit, GLuint texture);

}  // namespace viewer
