// The back ends' factories (internal to the render library). Each is defined in its own file,
// or in a stub that throws MissingComponent when the back end is not compiled in.
#pragma once

#include <memory>
#include <string_view>

#include "render/gl/gl_context.hpp"

namespace fl::render {

std::unique_ptr<GlContext> make_osmesa_context(const GlContextOptions& options);
std::unique_ptr<GlContext> make_egl_context(const GlContextOptions& options);

// Throws MissingComponent: "<what> needs <component>, which this build of frictionlab does not
// have (GL back ends in this build: ...; configure with ... -DFRICTIONLAB_WITH_OSMESA=ON ...)".
[[noreturn]] void throw_without_osmesa(std::string_view what, std::string_view component);

}  // namespace fl::render
