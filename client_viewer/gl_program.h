// Shader program helpers for the OpenGL 3.3 core renderers (functions loaded by libepoxy).
#pragma once

#include <epoxy/gl.h>

#include <string>

namespace viewer {

// Compiles and links; throws std::runtime_error with the driver's log on failure.
GLuint buildProgram(const char* vertex_source, const char* fragment_source, const std::string& name);

// Owns a GL object name and deletes it with the matching call.
class GlProgram {
 public:
  GlProgram() = default;
  GlProgram(const char* vertex_source, const char* fragment_source, const std::string& name)
      : id_(buildProgram(vertex_source, fragment_source, name)) {}
  ~GlProgram() {
    if (id_ != 0) glDeleteProgram(id_);
  }
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;
  GLuint id() const { return id_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

}  // namespace viewer
