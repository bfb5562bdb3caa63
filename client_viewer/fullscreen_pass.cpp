#include "fullscreen_pass.h"

namespace viewer {

const char* const kFullscreenVertexShader = R"(
out vec2 v_uv;
void main() {
  // Vertices 0, 1, 2 -> (0, 0), (2, 0), (0, 2): one triangle whose inside covers the 0..1 square.
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  v_uv = p;
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

void FullscreenTriangle::draw() const {
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace viewer
