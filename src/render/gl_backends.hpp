// The back ends' factories (internal to the render library). Each is defined in its own file,
// or in a stub that throws MissingComponent when the back end is not compiled in.
#pragma once

#include <memory>

#include "render/gl_context.hpp"

namespace fl::render {

std::unique_ptr<GlContext> make_osmesa_context(const GlContextOptions& options);
std::unique_ptr<GlContext> make_egl_context(const GlContextOptions& options);

}  // namespace fl::render
