// A linked GLSL program (vertex + fragment). Compile and link failures throw RenderError with
// the program's name, the stage and the driver's log.
#pragma once

#include <string>
#include <string_view>

#include "render/gl/gl_api.hpp"

namespace fl::render {

class ShaderProgram {
 public:
  // Needs a current context.
  ShaderProgram(const GlApi& gl, std::string name, std::string_view vertex_source,
                std::string_view fragment_source);
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;
  ~ShaderProgram();

  void use() const { gl_.UseProgram(program_); }
  GLuint id() const { return program_; }
  // The location of a uniform; -1 (GL ignores it) if the shader does not use it.
  GLint uniform(const char* name) const { return gl_.GetUniformLocation(program_, name); }

 private:
  const GlApi& gl_;
  std::string name_;
  GLuint program_ = 0;
};

}  // namespace fl::render
