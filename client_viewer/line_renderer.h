// Coloured GL_LINES from a LineList (outline_geometry.h), transformed by one matrix: projection * view
// for world outlines, identity for screen overlays already in NDC.
#pragma once

#include <Eigen/Core>

#include "gl_program.h"
#include "outline_geometry.h"

namespace viewer {

class LineRenderer {
 public:
  LineRenderer();
  ~LineRenderer();
  LineRenderer(const LineRenderer&) = delete;
  LineRenderer& operator=(const LineRenderer&) = delete;

  void draw(const LineList& lines, const Eigen::Matrix4f& transform);

 private:
  GlProgram program_;
  GLuint vao_ = 0;
  GLuint buffer_ = 0;
};

}  // namespace viewer
