// Which optional rendering components this build has, and the errors the render layer throws.
// The drawing layer (renderer, text, PNG: FRICTIONLAB_WITH_RENDER), the GL back ends
// (FRICTIONLAB_WITH_OSMESA, FRICTIONLAB_WITH_EGL) and video (libav: FRICTIONLAB_WITH_VIDEO) are
// optional: a build
// without one compiles stubs whose functions throw MissingComponent naming what is missing.
// Tests skip on kHas*.
#pragma once

#include <stdexcept>
#include <string_view>

#include "io/missing_component.hpp"

#ifndef FRICTIONLAB_HAS_RENDER
#error "FRICTIONLAB_HAS_RENDER is set by the fl_render target; link fl_render"
#endif
#ifndef FRICTIONLAB_HAS_OSMESA
#error "FRICTIONLAB_HAS_OSMESA is set by the fl_render target; link fl_render"
#endif
#ifndef FRICTIONLAB_HAS_EGL
#error "FRICTIONLAB_HAS_EGL is set by the fl_render target; link fl_render"
#endif
#ifndef FRICTIONLAB_HAS_VIDEO
#error "FRICTIONLAB_HAS_VIDEO is set by the fl_render target; link fl_render"
#endif

namespace fl::render {

// The drawing layer: the renderer, text through stb_truetype, PNG through libpng, the rig view.
inline constexpr bool kHasRender = FRICTIONLAB_HAS_RENDER != 0;
// The OSMesa GL back end (software rendering on llvmpipe). Drawing frames needs kHasRender and a
// back end (OSMesa or EGL).
inline constexpr bool kHasOsmesa = FRICTIONLAB_HAS_OSMESA != 0;
// The EGL GL back end (no display: Mesa's surfaceless platform or an EGL device).
inline constexpr bool kHasEgl = FRICTIONLAB_HAS_EGL != 0;
// Videos through libav: MP4 (H.264), WebM (VP9), GIF (libavfilter's palette).
inline constexpr bool kHasVideo = FRICTIONLAB_HAS_VIDEO != 0;

// A failure of the render layer: a GL error, a shader that does not compile, an encoder error.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A component this build was configured without (or a back end not compiled in): the one error
// type of every layer (io/missing_component.hpp, with throw_missing). Not a RenderError: catch
// both where both can come.
using MissingComponent = fl::MissingComponent;

// What a build without the drawing layer (FRICTIONLAB_WITH_RENDER=OFF) throws from its stubs
// (font_stub.cpp, gl/renderer_stub.cpp, sinks/png_stub.cpp): `what` names the part asked for.
[[noreturn]] inline void missing_drawing_layer(std::string_view what) {
  throw_missing(what, "the drawing layer (libpng, stb_truetype, DejaVu Sans)",
                "configure with -DFRICTIONLAB_WITH_RENDER=ON after apt-get install "
                "libpng-dev libstb-dev libgl-dev fonts-dejavu-core");
}

}  // namespace fl::render
