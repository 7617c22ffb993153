// Built instead of the PNG code (png.cpp, png_pool_sink.cpp) when FRICTIONLAB_WITH_RENDER is OFF:
// every entry point throws MissingComponent naming it.
#include "render/components.hpp"
#include "render/sinks/png.hpp"

namespace fl::render {

std::string encode_png(const ImageView&, int) {
  missing_drawing_layer("PNG output");
}
void write_png(const std::string&, const ImageView&, int) {
  missing_drawing_layer("PNG output");
}
Image read_png(const std::string&) {
  missing_drawing_layer("PNG input");
}
std::unique_ptr<FrameSink> make_png_sink(const PngSinkOptions&) {
  missing_drawing_layer("PNG frames");
}

std::unique_ptr<FrameSink> make_png_pool_sink(const PngSinkOptions&, unsigned) {
  missing_drawing_layer("PNG frames");
}

}  // namespace fl::render
