// Built instead of egl_context.cpp when FRICTIONLAB_WITH_EGL is OFF: asking for the EGL back end
// fails naming it and the back ends this build has.
#include "render/components.hpp"
#include "render/gl/gl_backends.hpp"

namespace fl::render {

std::unique_ptr<GlContext> make_egl_context(const GlContextOptions& /*options*/) {
  std::string how = "GL back ends in this build: " + compiled_gl_backends() + "; configure with ";
  if (!kHasRender) how += "-DFRICTIONLAB_WITH_RENDER=ON ";
  how += "-DFRICTIONLAB_WITH_EGL=ON after apt-get install libegl-dev";
  throw_missing("the GL back end 'egl'", "EGL", how);
}

}  // namespace fl::render
