// A run's video as a run asks for it and as it comes out: the frames' request (the run request's
// video, frames, still and their settings, lab/request/run_request.hpp), the scene's video settings
// with the request's overrides, the frame clock, and the report. Plain values: the executable
// checks a request with them before it loads anything, and the video module (video_module.hpp)
// takes them.
//
// The frame clock is the video's, not the physics': frame k of the run shows simulated time
// t_k = k / (fps x slow_motion), for k = 0 .. N-1 with N = ceil(duration x fps x slow_motion),
// each interpolated between the two physics steps around t_k. So the video lasts
// duration x slow_motion seconds; a title card adds round(2 s x fps) frames before frame 0. The
// still (--still) is drawn at the run's last step.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace fl {

// What the run asked for, read from its request; empty or absent values take the scene's `video`
// part, then the defaults.
struct VideoRequest {
  std::string video;   // .mp4 file
  std::string frames;  // folder for frame_000000.png, ... (earlier frames there are replaced)
  std::string still;   // .png file: the frame at the run's last step
  std::string gl;      // GL back end: osmesa, egl, auto; empty: $FRICTIONLAB_GL, then auto
  std::optional<std::array<int, 2>> size;  // pixels
  std::optional<int> fps;
  std::optional<double> slow_motion;
  std::optional<std::string> camera;  // a preset: front, top, sensor, phone
  std::optional<double> orbit;        // rad per second of video
  std::optional<std::string> title;   // the title card's title; given, it turns the card on
  std::optional<std::vector<Caption>> captions;  // replace the scene's (an empty list: none)
  std::string asset_dir;                         // LEGO meshes and the paper's table

  bool any() const { return !video.empty() || !frames.empty() || !still.empty(); }
};

// The recorder could not start: a component this build lacks (rendering, the video module, a GL
// back end, libav, assimp), a GL back end that is unknown or does not start, or a part the scene
// names that cannot be drawn.
class VideoUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The scene's video settings with the request's overrides. Throws InputError located at the
// request's field for a value out of range.
VideoDesc effective_video(const Scene& scene, const VideoRequest& request);

// Frames of the run itself (title card not included) for a run of `duration` seconds.
std::size_t run_frame_count(const VideoDesc& video, double duration);
// Frames of the title card (0 without one).
std::size_t title_frame_count(const VideoDesc& video);
// Frames of the end card (0 without one), and of the banner after a run a guard stopped.
std::size_t end_card_frame_count(const VideoDesc& video);
std::size_t guard_banner_frame_count(const VideoDesc& video);

// How the run ended, for the video's last frames.
struct VideoEnding {
  // Why a guard stopped the run (lab/run/run_summary.hpp RunSummary::failure), empty when it ran to
  // its end or was interrupted.
  std::string stopped_by;
  double stopped_at = 0.0;  // s, when
};

struct VideoReport {
  std::size_t frames = 0;         // written to the video and/or the folder, title included
  std::size_t title_frames = 0;   // of which the title card
  std::size_t ending_frames = 0;  // and the guard's banner and the end card
  int width = 0;
  int height = 0;
  int fps = 0;
  double slow_motion = 1.0;
  std::string camera;               // the preset, or "placed"
  std::string backend;              // GL_VERSION, GL_RENDERER
  std::size_t triangles = 0;        // in the camera pass of the last frame
  std::size_t frame_triangles = 0;  // the LEGO frame's, after hidden faces were left out
  std::size_t frame_triangles_full = 0;
  double setup_seconds = 0.0;   // context, meshes, shaders
  double render_seconds = 0.0;  // drawing frames, in the run's thread
  double finish_seconds = 0.0;  // waiting for the encoder and the PNG writer at the end
};

}  // namespace fl
