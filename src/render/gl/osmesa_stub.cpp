// Built instead of osmesa_context.cpp when FRICTIONLAB_WITH_OSMESA is OFF: asking for the OSMesa
// back end fails naming it and the back ends this build has.
#include "render/gl/gl_backends.hpp"

namespace fl::render {

std::unique_ptr<GlContext> make_osmesa_context(const GlContextOptions& /*options*/) {
  throw_without_osmesa("the GL back end 'osmesa'", "OSMesa");
}

}  // namespace fl::render
