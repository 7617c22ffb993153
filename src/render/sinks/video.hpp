// Videos through libav, the format chosen by the file's extension (scene/video_format.hpp):
//  - .mp4: H.264 (libx264) in yuv420p, BT.709 colour set and tagged;
//  - .webm: VP9 (libvpx-vp9) in yuv420p, BT.709 likewise;
//  - .gif: an animated GIF with one palette of 256 colours made for the whole clip (libavfilter's
//    palettegen and paletteuse), ordered dithering, only the changed rectangle of each frame.
// All at a constant frame rate, each frame lasting exactly 1/fps. Frames stream to the encoder
// one at a time, by default on an encoder thread behind a bounded queue so that rendering and
// encoding overlap; a GIF holds its frames (RGBA) until the end, when its palette is known.
#pragma once

#include <memory>
#include <string>

#include "render/sinks/frame_sink.hpp"
#include "scene/video_format.hpp"

namespace fl::render {

struct VideoOptions {
  std::string path;  // .mp4, .webm or .gif; written as path + ".part", renamed at finish
  int fps = 30;      // frames per second of video (constant)
  int crf = 20;      // x264 constant quality: 0 lossless .. 51; 18-23 look clean
  std::string preset = "veryfast";  // x264 speed preset
  int vp9_crf = 32;                 // libvpx-vp9 constant quality: 0 .. 63; 31-36 look clean
  int encoder_threads = 0;          // encoder threads; 0: the encoder decides
  int queue_frames = 8;  // frames queued for the encoder thread; 0: encode on the caller's thread
};

// The video of options.path's format (RenderError for an extension it does not know). Opens the
// encoder at the first frame (its size sets the video's; MP4 and WebM need an even width and
// height). Throws RenderError for an encoder failure, MissingComponent in a build without video.
std::unique_ptr<FrameSink> make_video_sink(const VideoOptions& options);
// H.264 in an MP4 container whatever the file's name.
std::unique_ptr<FrameSink> make_mp4_sink(const VideoOptions& options);
// An animated GIF whatever the file's name, on the caller's thread (make_video_sink queues it).
std::unique_ptr<FrameSink> make_gif_sink(const VideoOptions& options);

}  // namespace fl::render
