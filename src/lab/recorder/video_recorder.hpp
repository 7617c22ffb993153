// Teaching videos of a run: the rig drawn from the scene and posed from the simulation, with the
// live Hall trace and the estimator's values over it, written as an MP4 (H.264), numbered PNG
// frames and/or one still. The recorder is the run's step observer (RunOptions::observer); the
// request, the settings, the frame clock and the report are in video_settings.hpp.
//
// The drawing is not in the executable: the recorder opens the video module
// (frictionlab-video.so, video_module.hpp) when it is made, so a run that asks for no frames
// never makes a recorder and never loads the renderer, OSMesa, libav or assimp, let alone
// creates a GL context, loads a mesh or opens an encoder. In a build without rendering
// (FRICTIONLAB_WITH_RENDER=OFF), or when the module cannot be found or opened, the recorder's
// constructor throws VideoUnavailable saying what is missing.
#pragma once

#include <memory>

#include "lab/run/experiment.hpp"
#include "lab/video/video_settings.hpp"
#include "scene/compiled_rig.hpp"

namespace fl {

class VideoRecorder {
 public:
  // Opens the video module, which creates the GL context, builds and uploads the rig, and opens
  // the sinks, so that anything missing fails before the physics runs. `video` is the scene's
  // video settings with the request's (effective_video). Throws VideoUnavailable, InputError.
  VideoRecorder(std::shared_ptr<const CompiledRig> rig, const VideoDesc& video,
                const VideoRequest& request);
  VideoRecorder(const VideoRecorder&) = delete;
  VideoRecorder& operator=(const VideoRecorder&) = delete;
  ~VideoRecorder();

  // The run's observer: takes each step and draws every frame whose time it has passed.
  void observe(const StepView& view);
  // Writes the still, flushes and closes the video and the frames. Call once, after the run.
  VideoReport finish(const VideoEnding& ending);
  // A line worth telling before the run, or empty: e.g. that the GL back end "auto" chose OSMesa
  // because EGL did not start, and why.
  std::string note() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fl
