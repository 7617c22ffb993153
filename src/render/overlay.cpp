#include "render/overlay.hpp"
#include "core/units.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::render {

Overlay::Overlay(std::string font_path) : font_path_(std::move(font_path)) {}

void Overlay::clear() {
  vertices_.clear();
  batches_.clear();
}

void Overlay::begin_batch(const Font* font) {
  if (batches_.empty() || batches_.back().font != font)
    batches_.push_back(OverlayBatch{font, vertices_.size(), 0});
}

void Overlay::triangle(const Eigen::Vector2f& a, const Eigen::Vector2f& b, const Eigen::Vector2f& c,
                       const Color& color) {
  begin_batch(nullptr);
  for (const auto* p : {&a, &b, &c})
    vertices_.push_back(OverlayVertex{p->x(), p->y(), 0, 0, color});
  batches_.back().count += 3;
}

void Overlay::rect(const Rect& r, const Color& color) {
  const Eigen::Vector2f a(r.x, r.y);
  const Eigen::Vector2f b(r.x + r.width, r.y);
  const Eigen::Vector2f c(r.x + r.width, r.y + r.height);
  const Eigen::Vector2f d(r.x, r.y + r.height);
  triangle(a, b, c, color);
  triangle(a, c, d, color);
}

void Overlay::rect_outline(const Rect& r, float width, const Color& color) {
  rect(Rect{r.x, r.y, r.width, width}, color);
  rect(Rect{r.x, r.y + r.height - width, r.width, width}, color);
  rect(Rect{r.x, r.y + width, width, r.height - 2 * width}, color);
  rect(Rect{r.x + r.width - width, r.y + width, width, r.height - 2 * width}, color);
}

void Overlay::line(const Eigen::Vector2f& a, const Eigen::Vector2f& b, float width,
                   const Color& color) {
  const Eigen::Vector2f d = b - a;
  const float length = d.norm();
  if (length <= 0.0f) return;
  const Eigen::Vector2f along = d / length * (width / 2.0f);
  const Eigen::Vector2f across(-along.y(), along.x());
  const Eigen::Vector2f p0 = a - along + across;
  const Eigen::Vector2f p1 = b + along + across;
  const Eigen::Vector2f p2 = b + along - across;
  const Eigen::Vector2f p3 = a - along - across;
  triangle(p0, p1, p2, color);
  triangle(p0, p2, p3, color);
}

void Overlay::arrow(const Eigen::Vector2f& from, const Eigen::Vector2f& to, float width, float head,
                    const Color& color) {
  const Eigen::Vector2f d = to - from;
  const float length = d.norm();
  if (length < 1.0f) return;
  const Eigen::Vector2f along = d / length;
  const Eigen::Vector2f across(-along.y(), along.x());
  // A short arrow is all head.
  const float head_length = std::min(head, length);
  const Eigen::Vector2f base = to - along * head_length;
  if (length > head_length) line(from, base, width, color);
  const float half = std::max(0.5f * head_length, 0.75f * width);
  triangle(to, base + across * half, base - across * half, color);
}

void Overlay::polyline(std::span<const Eigen::Vector2f> points, float width, const Color& color) {
  for (std::size_t i = 1; i < points.size(); ++i) line(points[i - 1], points[i], width, color);
}

void Overlay::dashed_polyline(std::span<const Eigen::Vector2f> points, float width,
                              const Color& color, std::size_t on, std::size_t off) {
  for (std::size_t first = 0; first + 1 < points.size(); first += on + off)
    polyline(points.subspan(first, std::min(on, points.size() - first)), width, color);
}

void Overlay::dot(const Eigen::Vector2f& centre, float radius, const Color& color) {
  constexpr int kSides = 16;
  for (int i = 0; i < kSides; ++i) {
    const float a0 = 2.0f * static_cast<float>(kPi) * static_cast<float>(i) / kSides;
    const float a1 = 2.0f * static_cast<float>(kPi) * static_cast<float>(i + 1) / kSides;
    triangle(centre, centre + radius * Eigen::Vector2f(std::cos(a0), std::sin(a0)),
             centre + radius * Eigen::Vector2f(std::cos(a1), std::sin(a1)), color);
  }
}

const Font& Overlay::font(float pixel_size) {
  const int key = static_cast<int>(std::lround(pixel_size * 4.0f));
  auto found = fonts_.find(key);
  if (found == fonts_.end()) {
    found = fonts_.emplace(key, std::make_unique<Font>(font_path_, static_cast<float>(key) / 4.0f))
                .first;
  }
  return *found->second;
}

Rect Overlay::measure_text(std::string_view utf8, float pixel_size) {
  const Font& f = font(pixel_size);
  return Rect{0, 0, f.layout(utf8, 0, 0, nullptr), f.ascent() + f.descent()};
}

Rect Overlay::text(std::string_view utf8, const Eigen::Vector2f& at, float pixel_size,
                   const Color& color, TextAlign align) {
  const Font& f = font(pixel_size);
  const float width = f.layout(utf8, 0, 0, nullptr);
  float left = at.x();
  if (align == TextAlign::kCenter) left -= width / 2.0f;
  if (align == TextAlign::kRight) left -= width;
  // Whole-pixel baselines keep small text sharp.
  left = std::round(left);
  const float baseline = std::round(at.y() + f.ascent());
  glyphs_.clear();
  f.layout(utf8, left, baseline, &glyphs_);
  begin_batch(&f);
  for (const GlyphQuad& q : glyphs_) {
    const OverlayVertex a{q.x0, q.y0, q.s0, q.t0, color};
    const OverlayVertex b{q.x1, q.y0, q.s1, q.t0, color};
    const OverlayVertex c{q.x1, q.y1, q.s1, q.t1, color};
    const OverlayVertex d{q.x0, q.y1, q.s0, q.t1, color};
    vertices_.insert(vertices_.end(), {a, b, c, a, c, d});
    batches_.back().count += 6;
  }
  return Rect{left, baseline - f.ascent(), width, f.ascent() + f.descent()};
}

}  // namespace fl::render
