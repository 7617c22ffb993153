// MP4 video through libavcodec/libavformat/libswscale: H.264 (libx264) in yuv420p, BT.709
// colour set and tagged, constant frame rate. Frames stream to the encoder one at a time, by
// default on an encoder thread behind a bounded queue so that rendering and encoding overlap.
#pragma once

#include <memory>
#include <string>

#include "render/frame_sink.hpp"

namespace fl::render {

struct VideoOptions {
  std::string path;                 // the .mp4 file; written as path + ".part", renamed at finish
  int fps = 30;                     // frames per second of video (constant)
  int crf = 20;                     // x264 constant quality: 0 lossless .. 51; 18-23 look clean
  std::string preset = "veryfast";  // x264 speed preset
  int encoder_threads = 0;          // x264 threads; 0: x264 decides
  int queue_frames = 8;  // frames queued for the encoder thread; 0: encode on the caller's thread
};

// Opens the encoder at the first frame (its size sets the video's; width and height must be
// even). Throws RenderError for an encoder failure, MissingComponent in a build without video.
std::unique_ptr<FrameSink> make_mp4_sink(const VideoOptions& options);

}  // namespace fl::render
