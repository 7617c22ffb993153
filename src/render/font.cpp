#define STB_TRUETYPE_IMPLEMENTATION
#include <stb/stb_truetype.h>

#include "render/font.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <unordered_map>

#include "render/components.hpp"

namespace fl::render {
namespace {

// Single code points outside the contiguous ranges below.
constexpr int kSigns[] = {0x2013, 0x2014, 0x2022, 0x2026, 0x2032, 0x2033, 0x2190, 0x2192,
                          0x2212, 0x2248, 0x2260, 0x2264, 0x2265, 0x221A, 0x221E, 0x00D7};
struct CodeRange {
  int first;
  int count;
};
constexpr CodeRange kRanges[] = {
    {0x20, 0x5F}, {0xA0, 0x60}, {0x391, 0x39}, {0x2080, 0x0A}, {0x2090, 0x0D}};

}  // namespace

struct Font::Impl {
  std::vector<unsigned char> file;
  stbtt_fontinfo info{};
  float pixel_height = 0;
  float scale = 0;
  float ascent = 0;
  float descent = 0;
  float line_gap = 0;
  CoverageAtlas atlas;
  std::vector<stbtt_packedchar> chars;
  std::unordered_map<char32_t, std::size_t> index;  // code point -> entry of chars
};

Font::Font(const std::string& ttf_path, float pixel_height) : impl_(std::make_unique<Impl>()) {
  Impl& f = *impl_;
  if (!(pixel_height >= 4.0f && pixel_height <= 512.0f))
    throw RenderError("a font size must be 4 to 512 pixels, not " + std::to_string(pixel_height));
  std::ifstream in(ttf_path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : -1;
  if (size <= 0)
    throw RenderError("cannot read the font file " + ttf_path +
                      " (apt-get install fonts-dejavu-core, or set FRICTIONLAB_FONT)");
  f.file.resize(static_cast<std::size_t>(size));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(f.file.data()), size))
    throw RenderError("cannot read the font file " + ttf_path);
  const int offset = stbtt_GetFontOffsetForIndex(f.file.data(), 0);
  if (offset < 0 || !stbtt_InitFont(&f.info, f.file.data(), offset))
    throw RenderError("the font file " + ttf_path + " is not a TrueType font stb_truetype reads");
  f.pixel_height = pixel_height;
  f.scale = stbtt_ScaleForPixelHeight(&f.info, pixel_height);
  int ascent = 0;
  int descent = 0;
  int line_gap = 0;
  stbtt_GetFontVMetrics(&f.info, &ascent, &descent, &line_gap);
  f.ascent = static_cast<float>(ascent) * f.scale;
  f.descent = -static_cast<float>(descent) * f.scale;
  f.line_gap = static_cast<float>(line_gap) * f.scale;

  std::vector<int> codepoints;
  for (const CodeRange& r : kRanges) {
    for (int c = r.first; c < r.first + r.count; ++c) codepoints.push_back(c);
  }
  codepoints.insert(codepoints.end(), std::begin(kSigns), std::end(kSigns));
  f.chars.assign(codepoints.size(), stbtt_packedchar{});

  // Pack into the smallest square atlas that holds every glyph; 2x horizontal oversampling
  // keeps small text crisp at fractional positions.
  for (int side = 256; side <= 4096; side *= 2) {
    f.atlas.width = side;
    f.atlas.height = side;
    f.atlas.coverage.assign(static_cast<std::size_t>(side) * side, 0);
    stbtt_pack_context pack;
    if (!stbtt_PackBegin(&pack, f.atlas.coverage.data(), side, side, 0, 1, nullptr))
      throw RenderError("stb_truetype could not start packing " + ttf_path);
    stbtt_PackSetOversampling(&pack, 2, 1);
    stbtt_pack_range range{};
    range.font_size = pixel_height;
    range.array_of_unicode_codepoints = codepoints.data();
    range.num_chars = static_cast<int>(codepoints.size());
    range.chardata_for_range = f.chars.data();
    const int ok = stbtt_PackFontRanges(&pack, f.file.data(), 0, &range, 1);
    stbtt_PackEnd(&pack);
    if (ok) break;
    if (side == 4096)
      throw RenderError("the glyphs of " + ttf_path + " at " + std::to_string(pixel_height) +
                        " px do not fit a 4096x4096 atlas");
  }
  for (std::size_t i = 0; i < codepoints.size(); ++i) {
    // Glyphs the font lacks are packed as empty boxes; leave them out so they show as '?'.
    if (stbtt_FindGlyphIndex(&f.info, codepoints[i]) != 0 || codepoints[i] == 0x20)
      f.index.emplace(static_cast<char32_t>(codepoints[i]), i);
  }
}

Font::~Font() = default;

float Font::pixel_height() const {
  return impl_->pixel_height;
}
float Font::ascent() const {
  return impl_->ascent;
}
float Font::descent() const {
  return impl_->descent;
}
float Font::line_height() const {
  return impl_->ascent + impl_->descent + impl_->line_gap;
}
const CoverageAtlas& Font::atlas() const {
  return impl_->atlas;
}

float Font::layout(std::string_view utf8, float x, float baseline,
                   std::vector<GlyphQuad>* out) const {
  const Impl& f = *impl_;
  float pen = x;
  float y = baseline;
  char32_t previous = 0;
  for (char32_t c : decode_utf8(utf8)) {
    auto found = f.index.find(c);
    if (found == f.index.end()) {
      c = U'?';
      found = f.index.find(c);
      if (found == f.index.end()) continue;  // a font without '?': leave the character out
    }
    if (previous != 0)
      pen += f.scale * static_cast<float>(stbtt_GetCodepointKernAdvance(
                           &f.info, static_cast<int>(previous), static_cast<int>(c)));
    stbtt_aligned_quad q;
    stbtt_GetPackedQuad(&f.chars[found->second], f.atlas.width, f.atlas.height, 0, &pen, &y, &q, 0);
    if (out != nullptr && q.x1 > q.x0 && q.y1 > q.y0)
      out->push_back(GlyphQuad{q.x0, q.y0, q.x1, q.y1, q.s0, q.t0, q.s1, q.t1});
    previous = c;
  }
  return pen - x;
}

std::string default_font_path() {
  const char* env = std::getenv("FRICTIONLAB_FONT");
  if (env != nullptr && *env != '\0') return env;
  return FRICTIONLAB_DEFAULT_FONT;
}

}  // namespace fl::render
