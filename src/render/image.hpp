// Frames in memory: 8-bit RGBA, rows top-down. An ImageView borrows pixels (the GL back end's
// buffer, a sink's queue slot); an Image owns them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fl::render {

// Borrowed RGBA pixels, rows top-down; `stride` is the distance in bytes from one row to the
// next (negative for a buffer stored bottom-up).
struct ImageView {
  const std::uint8_t* pixels = nullptr;
  int width = 0;
  int height = 0;
  std::ptrdiff_t stride = 0;

  const std::uint8_t* row(int y) const { return pixels + stride * y; }
  // {r, g, b, a} of the pixel in column x, row y (0 = top).
  std::array<std::uint8_t, 4> at(int x, int y) const {
    const std::uint8_t* p = row(y) + 4 * x;
    return {p[0], p[1], p[2], p[3]};
  }
  bool empty() const { return pixels == nullptr || width <= 0 || height <= 0; }
};

// Owned RGBA pixels, rows top-down, tightly packed.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;

  Image() = default;
  Image(int w, int h);
  ImageView view() const;
  std::uint8_t* row(int y) { return rgba.data() + static_cast<std::ptrdiff_t>(y) * width * 4; }
  std::array<std::uint8_t, 4> at(int x, int y) const { return view().at(x, y); }
};

// A copy of a view's pixels.
Image copy_image(const ImageView& view);
// The same into an image kept from frame to frame: its buffer is reused when the size matches.
void copy_into(Image& into, const ImageView& view);

// Root mean square difference of the R, G and B channels (0 to 255); the sizes must match.
double rms_difference(const ImageView& a, const ImageView& b);

// |a - b| per channel scaled by `gain`, alpha 255: a picture of where two frames differ.
Image difference_image(const ImageView& a, const ImageView& b, int gain = 4);

// Pixels whose RGB differs from `rgb` by more than `tolerance` in any channel.
std::size_t count_pixels_unlike(const ImageView& view, std::array<std::uint8_t, 3> rgb,
                                int tolerance = 0);

}  // namespace fl::render
