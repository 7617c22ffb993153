// Built instead of video_recorder.cpp when FRICTIONLAB_WITH_RENDER is OFF: a run that asks for a
// video, frames or a still fails before it starts, naming what is missing.
#include "lab/video_recorder.hpp"

namespace fl {

struct VideoRecorder::Impl {};

VideoRecorder::VideoRecorder(const Scene& scene, const VideoRequest& request) {
  effective_video(scene, request);  // bad options are still bad input
  throw VideoUnavailable(
      "video, frames and stills need off-screen rendering (OSMesa, libpng, stb_truetype), which "
      "this build of frictionlab does not have (configure with -DFRICTIONLAB_WITH_RENDER=ON "
      "after apt-get install libosmesa6-dev libpng-dev libstb-dev fonts-dejavu-core)");
}

VideoRecorder::~VideoRecorder() = default;

void VideoRecorder::observe(const StepView&) {}

VideoReport VideoRecorder::finish() {
  return {};
}

}  // namespace fl
