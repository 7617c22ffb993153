// A plate swinging in front of a camera, drawn with known truth for the tracker's tests: a slab of
// one grey over a textured background, its ends drawn to a fraction of a pixel (each pixel's grey
// is the part of it the plate covers), moving as d(t) = amplitude sin(2 pi t / period + phase)
// along a line at `direction_deg` (0 across the picture, 90 up), a roller under it turning its
// mark at another pace, and the camera's noise.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "tracking/gray_frame.hpp"

namespace fl::test {

struct PlateScene {
  int width = 240;
  int height = 135;
  double period_s = 0.7766;
  double amplitude_px = 20.0;
  double phase = 0.3;
  double plate_length_px = 120.0;
  double plate_height_px = 16.0;
  double centre_x = 120.0;  // the plate's centre at rest
  double centre_y = 66.0;
  double direction_deg = 0.0;
  double roller_hz = 0.42;  // the roller's mark: 25 rpm, not the plate's pace
  double noise_grey = 2.0;
  double shake_px = 0.0;  // the camera's shake: each frame moved by up to this much
  int samples = 1;        // per pixel along each axis (for a plate that is not level)
  unsigned seed = 7;

  double displacement(double t) const {
    return amplitude_px * std::sin(2.0 * std::numbers::pi * t / period_s + phase);
  }

  GrayFrame frame(double t, std::mt19937& random) const {
    GrayFrame f;
    f.width = width;
    f.height = height;
    f.t_s = t;
    f.levels.resize(static_cast<std::size_t>(width) * height);
    std::normal_distribution<double> noise(0.0, noise_grey);
    std::uniform_real_distribution<double> shake(-shake_px, shake_px);
    const double sx = shake_px > 0 ? shake(random) : 0.0;
    const double sy = shake_px > 0 ? shake(random) : 0.0;
    const double angle = direction_deg * std::numbers::pi / 180.0;
    const double ux = std::cos(angle), uy = -std::sin(angle);  // picture rows grow downwards
    const double d = displacement(t);
    const double cx = centre_x + d * ux + sx, cy = centre_y + d * uy + sy;
    const double mark = 2.0 * std::numbers::pi * roller_hz * t;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const double bx = x + sx, by = y + sy;
        double grey = 90.0 + 30.0 * std::sin(bx * 0.13) * std::cos(by * 0.17);
        // The roller under the plate, its bright mark turning.
        const double rx = bx - centre_x, ry = by - (centre_y + plate_height_px);
        if (rx * rx + ry * ry < 100.0) {
          const double a = std::remainder(std::atan2(ry, rx) - mark, 2.0 * std::numbers::pi);
          grey = std::abs(a) < 0.5 ? 230.0 : 40.0;
        }
        double covered = 0.0;
        if (direction_deg == 0.0) {
          // Exact: the part of the pixel's width inside the plate, rows wholly in or out.
          if (y + 0.5 >= cy - plate_height_px / 2 && y + 0.5 < cy + plate_height_px / 2)
            covered = std::clamp(std::min(x + 1.0, cx + plate_length_px / 2) -
                                     std::max(static_cast<double>(x), cx - plate_length_px / 2),
                                 0.0, 1.0);
        } else {
          for (int i = 0; i < samples; ++i)
            for (int j = 0; j < samples; ++j) {
              const double px = x + (i + 0.5) / samples - cx, py = y + (j + 0.5) / samples - cy;
              const double along = px * ux + py * uy, across = -px * uy + py * ux;
              if (std::abs(along) < plate_length_px / 2 && std::abs(across) < plate_height_px / 2)
                covered += 1.0 / (samples * samples);
            }
        }
        grey = grey * (1.0 - covered) + 200.0 * covered + noise(random);
        f.levels[static_cast<std::size_t>(y) * width + x] =
            static_cast<std::uint8_t>(std::clamp(std::lround(grey), 0L, 255L));
      }
    return f;
  }
};

}  // namespace fl::test
