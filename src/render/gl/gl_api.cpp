#include "render/gl/gl_api.hpp"

#include "render/components.hpp"

namespace fl::render {

void GlApi::load(ProcLoader loader, const std::string& backend) {
#define FL_GL_LOAD(type, name)                                 \
  name = reinterpret_cast<type>(loader("gl" #name));           \
  if (name == nullptr)                                         \
    throw RenderError("the " + backend +                       \
                      " GL back end does not provide gl" #name \
                      " (frictionlab needs OpenGL 3.3 core)");
  FL_GL_FUNCTIONS(FL_GL_LOAD)
#undef FL_GL_LOAD
}

void GlApi::check(const char* where) const {
  const GLenum first = GetError();
  if (first == GL_NO_ERROR) return;
  // Drain the queue so that one failure does not report again later.
  for (int i = 0; i < 16 && GetError() != GL_NO_ERROR; ++i) {
  }
  throw RenderError(std::string(where) + ": GL error " + gl_error_name(first));
}

const char* gl_error_name(GLenum error) {
  switch (error) {
    case GL_NO_ERROR:
      return "GL_NO_ERROR";
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default:
      return "(unknown GL error)";
  }
}

}  // namespace fl::render
