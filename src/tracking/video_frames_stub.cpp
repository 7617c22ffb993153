// A build without libav (FRICTIONLAB_WITH_VIDEO=OFF) reads no video.
#include <stdexcept>

#include "io/input_error.hpp"
#include "tracking/video_frames.hpp"

namespace fl {

VideoStream read_video_frames(const std::string& path, int, const FrameHandler&, int) {
  throw InputError(
      SourceLocation(path),
      "this build of frictionlab reads no video (it was built without libav: "
      "apt-get install libavcodec-dev libavformat-dev libswscale-dev and build again)");
}

void write_rgb_png(const std::string& path, int, int, const std::vector<unsigned char>&) {
  throw std::runtime_error(path + ": this build writes no PNG without libav");
}

bool reads_videos() {
  return false;
}

}  // namespace fl
