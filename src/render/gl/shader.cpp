#include "render/gl/shader.hpp"

#include <vector>

#include "render/components.hpp"

namespace fl::render {
namespace {

std::string shader_log(const GlApi& gl, GLuint shader) {
  GLint length = 0;
  gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  gl.GetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log.data();
}

std::string program_log(const GlApi& gl, GLuint program) {
  GLint length = 0;
  gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  gl.GetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log.data();
}

GLuint compile(const GlApi& gl, GLenum stage, std::string_view source, const std::string& name) {
  const GLuint shader = gl.CreateShader(stage);
  const GLchar* text = source.data();
  const auto length = static_cast<GLint>(source.size());
  gl.ShaderSource(shader, 1, &text, &length);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = shader_log(gl, shader);
    gl.DeleteShader(shader);
    throw RenderError("the " + std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                      " shader of '" + name + "' does not compile:\n" + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const GlApi& gl, std::string name, std::string_view vertex_source,
                             std::string_view fragment_source)
    : gl_(gl), name_(std::move(name)) {
  const GLuint vertex = compile(gl, GL_VERTEX_SHADER, vertex_source, name_);
  GLuint fragment = 0;
  try {
    fragment = compile(gl, GL_FRAGMENT_SHADER, fragment_source, name_);
  } catch (...) {
    gl.DeleteShader(vertex);
    throw;
  }
  program_ = gl.CreateProgram();
  gl.AttachShader(program_, vertex);
  gl.AttachShader(program_, fragment);
  gl.LinkProgram(program_);
  gl.DeleteShader(vertex);
  gl.DeleteShader(fragment);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = program_log(gl, program_);
    gl.DeleteProgram(program_);
    throw RenderError("the shader program '" + name_ + "' does not link:\n" + log);
  }
}

ShaderProgram::~ShaderProgram() {
  gl_.DeleteProgram(program_);
}

}  // namespace fl::render
