// Built instead of the font rasteriser (font.cpp) when FRICTIONLAB_WITH_RENDER is OFF: Font's
// constructor throws MissingComponent naming it; the other members exist so that code using them
// still links.
#include "render/components.hpp"
#include "render/font.hpp"

namespace fl::render {

struct Font::Impl {};
Font::Font(const std::string&, float) {
  missing_drawing_layer("text");
}
Font::~Font() = default;
float Font::pixel_height() const {
  missing_drawing_layer("text");
}
float Font::ascent() const {
  missing_drawing_layer("text");
}
float Font::descent() const {
  missing_drawing_layer("text");
}
float Font::line_height() const {
  missing_drawing_layer("text");
}
const CoverageAtlas& Font::atlas() const {
  missing_drawing_layer("text");
}
float Font::layout(std::string_view, float, float, std::vector<GlyphQuad>*) const {
  missing_drawing_layer("text");
}
std::string default_font_path() {
  return "";
}

}  // namespace fl::render
