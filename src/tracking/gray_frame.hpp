// One frame of a video as the tracker reads it: its grey levels (0 black .. 255 white), rows
// top-down and tightly packed, at the time the video shows it.
#pragma once

#include <cstdint>
#include <vector>

namespace fl {

struct GrayFrame {
  int width = 0;
  int height = 0;
  double t_s = 0.0;  // the frame's time in the video [s], from its presentation time stamp
  std::vector<std::uint8_t> levels;

  std::uint8_t at(int x, int y) const {
    return levels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)];
  }
};

}  // namespace fl
