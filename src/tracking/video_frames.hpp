// A video file read as a stream of grey frames through libav: MP4 and MOV (H.264, H.265), WebM
// and Matroska (VP8, VP9, AV1 where libav has a decoder), AVI. One frame is decoded at a time and
// handed on, so memory does not grow with the video's length; each frame is scaled down (area
// averaging) to at most `most_width` pixels across, keeping its aspect ratio. libav itself is in
// the decoder module (tracking/video_decoder_module.hpp), opened the first time a video is read.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tracking/gray_frame.hpp"

namespace fl {

struct VideoStream {
  std::string container;  // libav's name of the container: "mov,mp4,m4a,3gp,3g2,mj2", "avi"
  std::string codec;      // "h264", "vp9"
  int width = 0;          // the video's own pixels
  int height = 0;
  double fps = 0.0;     // the stream's average frame rate (0 when it does not say)
  int frames_read = 0;  // frames decoded and handed on
  double scale = 1.0;   // the frames' pixels per video pixel (<= 1)
};

// Takes each frame; returns false to stop reading.
using FrameHandler = std::function<bool(const GrayFrame&, const VideoStream&)>;

// Decodes `path` and calls `frame` for each frame in order of presentation, with what is known of
// the stream so far; stops early when `frame` returns false. `threads`: the decoder's threads (0:
// libav decides). Throws InputError, located at the file (and at the frame where decoding failed),
// for a file that is not a video libav reads, one without a video stream, or one that ends before
// its container says (a truncated file); and for a build without libav, or a decoder module that
// is missing or not this build's, saying which and what to do.
VideoStream read_video_frames(const std::string& path, int most_width, const FrameHandler& frame,
                              int threads = 0);

// Writes an RGB image (rows top-down, 3 bytes a pixel, tightly packed) as a PNG through libav's
// encoder in the decoder module, atomically (a ".part" file renamed). Throws InputError without
// the module, std::runtime_error when it cannot write.
void write_rgb_png(const std::string& path, int width, int height,
                   const std::vector<unsigned char>& rgb);

}  // namespace fl
