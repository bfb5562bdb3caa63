// The offscreen framebuffer every picture is drawn into (RGBA8 + depth). The window shows it by a
// blit; a snapshot reads it back. Drawing offscreen makes snapshots independent of whether the
// window is visible, mapped or covered.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

namespace viewer {

class RenderTarget {
 public:
  RenderTarget() = default;
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // (Re)allocates when the size changed; binds it for drawing.
  void bind(int width, int height);
  // Copies the picture to the window's default framebuffer.
  void blitToWindow() const;
  // RGBA rows, top row first.
  std::vector<std::uint8_t> readPixels() const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void release();
  GLuint framebuffer_ = 0;
  GLuint colour_ = 0;
  GLuint depth_ = 0;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace viewer
