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
  // `depth`: also a depth buffer (not a texture), which passes may test against.
  explicit TextureTarget(std::vector<TextureSpec> attachments, bool depth = false)
      : specs_(std::move(attachments)), with_depth_(depth) {}
  ~TextureTarget();
  TextureTarget(const TextureTarget&) = delete;
  TextureTarget& operator=(const TextureTarget&) = delete;

  // (Re)allocates when the size changed; binds the framebuffer, every attachment drawn to, and sets
  // the viewport. True when it (re)allocated: the contents are undefined then.
  bool bind(int width, int height);
  GLuint texture(std::size_t attachment) const { return textures_[attachment]; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void allocate(int width, int height);
  void release();
  std::vector<TextureSpec> specs_;
  std::vector<GLuint> textures_;
  bool with_depth_;
  GLuint depth_ = 0;
  GLuint framebuffer_ = 0;
  int width_ = 0;
  int height_ = 0;
};

// Binds `texture` to texture unit `unit` and points the sampler uniform `location` at it.
void bindTexture(GLint location, int unit, GLuint texture);

}  // namespace viewer
