// A video decoded outside the lab: the browser's build (tools/site) has no libav, so its page
// decodes a phone's video with the browser's own decoder (WebCodecs) into grey frames, scaled to
// the width the tracker reads, and gives them here before the lab reads the file. The lab then
// reads them through the decoder module's seam (video_decoder_module.hpp), as it reads libav's:
// the same tracker, the same estimate.
#pragma once

#include <string>
#include <vector>

#include "tracking/gray_frame.hpp"
#include "tracking/video_decoder_module.hpp"

namespace fl {

struct GivenVideo {
  std::string container;  // what the container is ("mp4")
  std::string codec;      // the decoder's name of the codec ("avc1.64001e")
  int width = 0;          // the video's own pixels
  int height = 0;
  double fps = 0.0;     // the frames' average rate (0 when unknown)
  double scale = 1.0;   // the frames' pixels per video pixel (<= 1)
  std::string failure;  // why the page could not decode it ("" : it did)
  std::vector<GrayFrame> frames;
};

// The video of the file named `name` (its last part; a later one of the same name takes its
// place). Throws std::invalid_argument for frames of another size than the first, or times that
// do not increase.
void give_video(const std::string& name, GivenVideo video);
// Forgets every video given (after the file was read).
void forget_given_videos();

// The decoder module that serves the videos given: read() finds the file's by its name, and
// refuses a video none was given for, one the page could not decode (its `failure`), and frames
// wider than the width asked; write_png() writes nothing.
const VideoDecoderModule* given_video_decoder();

}  // namespace fl
