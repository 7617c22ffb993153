// The EGL back end (a GPU, no display) is not written yet: this machine has no GPU to test it
// on. It will be a GlContext made with eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA or a
// device), an OpenGL core context, GlApi::load(eglGetProcAddress), a multisampled framebuffer
// resolved into a single-sampled one, and glReadPixels with the rows flipped.
#include "render/components.hpp"
#include "render/gl_backends.hpp"

namespace fl::render {

std::unique_ptr<GlContext> make_egl_context(const GlContextOptions& /*options*/) {
  throw_missing("the GL back end 'egl'", "an EGL back end",
                kHasOsmesa ? "it is not implemented yet; use FRICTIONLAB_GL=osmesa"
                           : "it is not implemented yet, and FRICTIONLAB_GL=osmesa needs a build "
                             "with -DFRICTIONLAB_WITH_OSMESA=ON; GL back ends in this build: " +
                                 compiled_gl_backends());
}

}  // namespace fl::render
