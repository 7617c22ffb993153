#include "render/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace fl::render {

Image::Image(int w, int h)
    : width(w), height(h), rgba(static_cast<std::size_t>(std::max(w, 0)) * std::max(h, 0) * 4) {}

ImageView Image::view() const {
  return ImageView{rgba.data(), width, height, static_cast<std::ptrdiff_t>(width) * 4};
}

Image copy_image(const ImageView& view) {
  Image out;
  copy_into(out, view);
  return out;
}

void copy_into(Image& into, const ImageView& view) {
  if (into.width != view.width || into.height != view.height) into = Image(view.width, view.height);
  const std::size_t bytes = static_cast<std::size_t>(view.width) * 4;
  for (int y = 0; y < view.height; ++y) std::memcpy(into.row(y), view.row(y), bytes);
}

namespace {
void require_same_size(const ImageView& a, const ImageView& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " against " + std::to_string(b.width) +
                                "x" + std::to_string(b.height));
}
}  // namespace

double rms_difference(const ImageView& a, const ImageView& b) {
  require_same_size(a, b);
  if (a.width == 0 || a.height == 0) return 0.0;
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y) {
    const std::uint8_t* pa = a.row(y);
    const std::uint8_t* pb = b.row(y);
    for (int x = 0; x < a.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const double d = static_cast<double>(pa[4 * x + c]) - static_cast<double>(pb[4 * x + c]);
        sum += d * d;
      }
    }
  }
  return std::sqrt(sum / (3.0 * a.width * a.height));
}

Image difference_image(const ImageView& a, const ImageView& b, int gain) {
  require_same_size(a, b);
  Image out(a.width, a.height);
  for (int y = 0; y < a.height; ++y) {
    std::uint8_t* o = out.row(y);
    for (int x = 0; x < a.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(a.row(y)[4 * x + c] - b.row(y)[4 * x + c]) * gain;
        o[4 * x + c] = static_cast<std::uint8_t>(std::min(d, 255));
      }
      o[4 * x + 3] = 255;
    }
  }
  return out;
}

std::size_t count_pixels_unlike(const ImageView& view, std::array<std::uint8_t, 3> rgb,
                                int tolerance) {
  std::size_t count = 0;
  for (int y = 0; y < view.height; ++y) {
    const std::uint8_t* p = view.row(y);
    for (int x = 0; x < view.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        if (std::abs(p[4 * x + c] - rgb[static_cast<std::size_t>(c)]) > tolerance) {
          ++count;
          break;
        }
      }
    }
  }
  return count;
}

}  // namespace fl::render
