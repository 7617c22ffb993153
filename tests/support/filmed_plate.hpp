// A synthetic plate (support/synthetic_plate_video.hpp) filmed into an MP4 through the lab's own
// H.264 writer (render/sinks/video.hpp), as a phone would record it: for the tracker's tests and
// its benchmark (needs a build with video).
#pragma once

#include <random>
#include <string>

#include "render/sinks/video.hpp"
#include "support/synthetic_plate_video.hpp"

namespace fl::test {

// `seconds` of the scene at `fps` frames a second into `path`; `preset` is x264's.
inline void film_plate(const PlateScene& scene, double seconds, int fps, const std::string& path,
                       const std::string& preset = "veryfast") {
  render::VideoOptions options;
  options.path = path;
  options.fps = fps;
  options.preset = preset;
  options.queue_frames = 0;
  auto sink = render::make_mp4_sink(options);
  std::mt19937 random(scene.seed);
  render::Image rgba(scene.width, scene.height);
  for (int k = 0; k < static_cast<int>(seconds * fps); ++k) {
    const GrayFrame f = scene.frame(static_cast<double>(k) / fps, random);
    for (std::size_t p = 0; p < f.levels.size(); ++p) {
      for (int c = 0; c < 3; ++c) rgba.rgba[4 * p + c] = f.levels[p];
      rgba.rgba[4 * p + 3] = 255;
    }
    sink->write(rgba.view());
  }
  sink->finish();
}

}  // namespace fl::test
