// Built instead of mp4_sink.cpp when FRICTIONLAB_WITH_VIDEO is OFF.
#include "render/components.hpp"
#include "render/video.hpp"

namespace fl::render {

std::unique_ptr<FrameSink> make_mp4_sink(const VideoOptions& /*options*/) {
  throw_missing("MP4 video", "libav (libavcodec, libavformat, libswscale)",
                "configure with -DFRICTIONLAB_WITH_VIDEO=ON after apt-get install "
                "libavcodec-dev libavformat-dev libswscale-dev");
}

}  // namespace fl::render
