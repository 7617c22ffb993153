// A TrueType font rasterised at one pixel size into a coverage atlas (stb_truetype), and the
// layout of UTF-8 text into textured quads. The atlas holds ASCII, Latin-1 (± µ ° ²), Greek
// (μ Δ ω) and a few signs (− ≈ ≤ ≥ …, subscripts ₀..₉ ₖ); other characters show as '?'.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace fl::render {

// One glyph's quad: screen pixels (y down) and atlas coordinates (0..1).
struct GlyphQuad {
  float x0, y0, x1, y1;
  float s0, t0, s1, t1;
};

// 8-bit coverage, rows top-down.
struct CoverageAtlas {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> coverage;
};

class Font {
 public:
  // Reads and rasterises the font; throws RenderError naming the file if it cannot.
  Font(const std::string& ttf_path, float pixel_height);
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;
  ~Font();

  float pixel_height() const;
  float ascent() const;       // pixels above the baseline
  float descent() const;      // pixels below the baseline (positive)
  float line_height() const;  // baseline to baseline, pixels
  const CoverageAtlas& atlas() const;

  // Lays out `utf8` from x with its baseline at `baseline` (pixels, y down), appending one quad
  // per visible glyph to `out` (if not null). Returns the advance width in pixels.
  float layout(std::string_view utf8, float x, float baseline, std::vector<GlyphQuad>* out) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// $FRICTIONLAB_FONT if set, else DejaVu Sans from fonts-dejavu-core.
std::string default_font_path();

// The code points of a UTF-8 text; a malformed byte gives U+FFFD.
std::vector<char32_t> decode_utf8(std::string_view text);

}  // namespace fl::render
