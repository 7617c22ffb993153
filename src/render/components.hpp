// Which optional rendering components this build has, and the errors the render layer throws.
// Rendering (OSMesa, fonts, PNG) and video (libav) are optional: a build without them compiles
// stubs whose functions throw MissingComponent naming what is missing. Tests skip on kHas*.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#ifndef FRICTIONLAB_HAS_RENDER
#error "FRICTIONLAB_HAS_RENDER is set by the fl_render target; link fl_render"
#endif
#ifndef FRICTIONLAB_HAS_VIDEO
#error "FRICTIONLAB_HAS_VIDEO is set by the fl_render target; link fl_render"
#endif

namespace fl::render {

// Off-screen rendering through OSMesa, text through stb_truetype, PNG through libpng.
inline constexpr bool kHasRender = FRICTIONLAB_HAS_RENDER != 0;
// MP4 through libavcodec/libavformat/libswscale (H.264 by libx264).
inline constexpr bool kHasVideo = FRICTIONLAB_HAS_VIDEO != 0;

// A failure of the render layer: a GL error, a shader that does not compile, an encoder error.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A component this build was configured without (or a back end not compiled in).
class MissingComponent : public RenderError {
 public:
  using RenderError::RenderError;
};

// Throws MissingComponent: "<what> needs <component>, which this build of frictionlab does not
// have (<how to get it>)".
[[noreturn]] void throw_missing(std::string_view what, std::string_view component,
                                std::string_view how);

}  // namespace fl::render
