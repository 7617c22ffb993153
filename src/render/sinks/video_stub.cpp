// Built instead of the libav sinks when FRICTIONLAB_WITH_VIDEO is OFF.
#include "render/components.hpp"
#include "render/sinks/video.hpp"

namespace fl::render {
namespace {

[[noreturn]] void throw_without_libav(const VideoOptions& options) {
  const std::optional<VideoFormat> format = video_format_of(options.path);
  const std::string what = format == VideoFormat::kGif    ? "GIF video"
                           : format == VideoFormat::kWebm ? "WebM video"
                                                          : "MP4 video";
  throw_missing(what, "libav (libavcodec, libavformat, libavfilter, libswscale)",
                "configure with -DFRICTIONLAB_WITH_VIDEO=ON after apt-get install "
                "libavcodec-dev libavformat-dev libavfilter-dev libswscale-dev");
}

}  // namespace

std::unique_ptr<FrameSink> make_video_sink(const VideoOptions& options) {
  throw_without_libav(options);
}

std::unique_ptr<FrameSink> make_mp4_sink(const VideoOptions& options) {
  throw_without_libav(options);
}

std::unique_ptr<FrameSink> make_gif_sink(const VideoOptions& options) {
  throw_without_libav(options);
}

}  // namespace fl::render
