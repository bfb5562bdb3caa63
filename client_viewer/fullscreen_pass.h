// Screen-space passes: one triangle that covers the viewport, its corners made from gl_VertexID, so
// a pass needs no vertex buffer (core profile still wants a vertex array object bound).
#pragma once

#include <epoxy/gl.h>

namespace viewer {

// The vertex shader of every screen-space pass: `out vec2 v_uv`, 0..1 across the viewport. It has
// no #version line: put kGlslCommon (glsl_common.h) before it.
extern const char* const kFullscreenVertexShader;

class FullscreenTriangle {
 public:
  FullscreenTriangle() { glGenVertexArrays(1, &vao_); }
  ~FullscreenTriangle() { glDeleteVertexArrays(1, &vao_); }
  FullscreenTriangle(const FullscreenTriangle&) = delete;
  FullscreenTriangle& operator=(const FullscreenTriangle&) = delete;
  void draw() const;

 private:
  GLuint vao_ = 0;
};

}  // namespace viewer
