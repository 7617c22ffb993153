// Built instead of the drawing layer (the renderer, the font rasteriser and the PNG code) when
// FRICTIONLAB_WITH_RENDER is OFF: every entry point throws MissingComponent naming it. Only
// Font's constructor, the renderer's and the PNG functions can be reached first; the other
// members exist so that code using them still links.
#include "render/components.hpp"
#include "render/font.hpp"
#include "render/png.hpp"
#include "render/renderer.hpp"

namespace fl::render {
namespace {

[[noreturn]] void missing(std::string_view what) {
  throw_missing(what, "the drawing layer (libpng, stb_truetype, DejaVu Sans)",
                "configure with -DFRICTIONLAB_WITH_RENDER=ON after apt-get install "
                "libpng-dev libstb-dev libgl-dev fonts-dejavu-core");
}

}  // namespace

struct Renderer::Impl {};
Renderer::Renderer(GlContext&, RendererOptions) {
  missing("the renderer");
}
Renderer::~Renderer() = default;
MeshId Renderer::upload(const MeshData&) {
  missing("the renderer");
}
void Renderer::begin_frame(const Camera&, const DirectionalLight&) {
  missing("the renderer");
}
void Renderer::draw(MeshId, const Eigen::Affine3f&, bool) {
  missing("the renderer");
}
void Renderer::set_shadow_bounds(std::optional<ShadowBounds>) {
  missing("the renderer");
}
Overlay& Renderer::overlay() {
  missing("the renderer");
}
ImageView Renderer::end_frame() {
  missing("the renderer");
}
const FrameStats& Renderer::last_frame_stats() const {
  missing("the renderer");
}
GlContext& Renderer::context() {
  missing("the renderer");
}

struct Font::Impl {};
Font::Font(const std::string&, float) {
  missing("text");
}
Font::~Font() = default;
float Font::pixel_height() const {
  missing("text");
}
float Font::ascent() const {
  missing("text");
}
float Font::descent() const {
  missing("text");
}
float Font::line_height() const {
  missing("text");
}
const CoverageAtlas& Font::atlas() const {
  missing("text");
}
float Font::layout(std::string_view, float, float, std::vector<GlyphQuad>*) const {
  missing("text");
}
std::string default_font_path() {
  return "";
}

std::string encode_png(const ImageView&, int) {
  missing("PNG output");
}
void write_png(const std::string&, const ImageView&, int) {
  missing("PNG output");
}
Image read_png(const std::string&) {
  missing("PNG input");
}
std::unique_ptr<FrameSink> make_png_sink(const PngSinkOptions&) {
  missing("PNG frames");
}

std::unique_ptr<FrameSink> make_png_pool_sink(const PngSinkOptions&, unsigned) {
  missing("PNG frames");
}

}  // namespace fl::render
