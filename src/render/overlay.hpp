// The 2D layer drawn over the 3D scene: filled rectangles, lines, polylines, dots and text, in
// pixel coordinates from the frame's top-left corner (x right, y down). It records triangles on
// the CPU; the Renderer draws them, in the order given, after the scene.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "render/font.hpp"
#include "render/mesh_data.hpp"

namespace fl::render {

struct Rect {
  float x = 0;  // left, pixels
  float y = 0;  // top, pixels
  float width = 0;
  float height = 0;
};

enum class TextAlign { kLeft, kCenter, kRight };

struct OverlayVertex {
  float x, y;  // pixels
  float u, v;  // atlas coordinates (text only)
  Color color;
};

// A run of vertices sharing one font atlas (nullptr: plain shapes).
struct OverlayBatch {
  const Font* font = nullptr;
  std::size_t first = 0;
  std::size_t count = 0;
};

class Overlay {
 public:
  explicit Overlay(std::string font_path = default_font_path());

  // Forgets what was drawn (the Renderer does this at each begin_frame). Fonts stay.
  void clear();

  void rect(const Rect& r, const Color& color);
  void rect_outline(const Rect& r, float width, const Color& color);
  // A straight line `width` pixels wide, square ends.
  void line(const Eigen::Vector2f& a, const Eigen::Vector2f& b, float width, const Color& color);
  // Joined segments through the points (a plot trace).
  void polyline(std::span<const Eigen::Vector2f> points, float width, const Color& color);
  // The polyline dashed: `on` points drawn, `off` left out, again (a last dash of two or more
  // points is drawn). Points a few pixels apart make even dashes.
  void dashed_polyline(std::span<const Eigen::Vector2f> points, float width, const Color& color,
                       std::size_t on = 4, std::size_t off = 2);
  // An arrow from `from` to `to`: a shaft `width` pixels wide and a head `head` pixels long whose
  // point is exactly `to`. Nothing for an arrow shorter than a pixel.
  void arrow(const Eigen::Vector2f& from, const Eigen::Vector2f& to, float width, float head,
             const Color& color);
  // A filled disc (a marker).
  void dot(const Eigen::Vector2f& centre, float radius, const Color& color);

  // Draws UTF-8 text of `pixel_size` (the font's ascent + descent). `at` is the top of the text
  // box and, by `align`, its left end, centre or right end. Returns the box.
  Rect text(std::string_view utf8, const Eigen::Vector2f& at, float pixel_size, const Color& color,
            TextAlign align = TextAlign::kLeft);
  // The box text() would fill at (0, 0), without drawing.
  Rect measure_text(std::string_view utf8, float pixel_size);

  // The font at a size (rasterised once per size, on first use). Throws RenderError if the
  // font file cannot be read, MissingComponent in a build without rendering.
  const Font& font(float pixel_size);

  const std::vector<OverlayVertex>& vertices() const { return vertices_; }
  const std::vector<OverlayBatch>& batches() const { return batches_; }
  std::size_t font_count() const { return fonts_.size(); }

 private:
  void triangle(const Eigen::Vector2f& a, const Eigen::Vector2f& b, const Eigen::Vector2f& c,
                const Color& color);
  void begin_batch(const Font* font);

  std::string font_path_;
  std::map<int, std::unique_ptr<Font>> fonts_;  // by size in 1/4 pixels
  std::vector<OverlayVertex> vertices_;
  std::vector<OverlayBatch> batches_;
  std::vector<GlyphQuad> glyphs_;
};

}  // namespace fl::render
