// The video's settings and frame clock (fl_lab_video): linked into the executable, which
// checks a request with them before it loads the video module, even in a build without
// rendering, and into the module.
#include <algorithm>
#include <cmath>

#include "io/input_error.hpp"
#include "lab/video/video_settings.hpp"
#include "scene/video_format.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

constexpr std::size_t kMostTitleCharacters = 200;

// Characters, not bytes: UTF-8 continuation bytes are not counted.
std::size_t characters(const std::string& text) {
  std::size_t n = 0;
  for (const char c : text) n += (static_cast<unsigned char>(c) & 0xC0) == 0x80 ? 0 : 1;
  return n;
}

// A problem with a request's field (lab/request/run_request.hpp).
void check(const std::string& field, const std::string& problem) {
  if (!problem.empty()) throw InputError(SourceLocation::of_field(field), problem);
}

}  // namespace

VideoDesc effective_video(const Scene& scene, const VideoRequest& request) {
  VideoDesc v = scene.video.value_or(VideoDesc{});
  if (request.size) {
    v.width = (*request.size)[0];
    v.height = (*request.size)[1];
    check("size", video_size_problem(v.width, v.height));
  }
  if (request.fps) {
    v.fps = *request.fps;
    check("fps", video_fps_problem(v.fps));
  }
  if (request.slow_motion) {
    v.slow_motion = *request.slow_motion;
    check("slow_motion", video_slow_motion_problem(v.slow_motion));
  }
  if (request.camera) {
    check("camera", video_camera_problem(*request.camera));
    v.camera = *request.camera;
    v.placed.reset();
  }
  if (request.orbit) {
    v.orbit = *request.orbit;
    check("orbit", video_orbit_problem(v.orbit));
  }
  if (request.title) {
    if (trim(*request.title).empty())
      check("title", "expected the title card's title, found an empty text");
    // The card wraps a title to three lines and shrinks it to fit; beyond 200 characters no
    // frame shows it legibly.
    else if (characters(*request.title) > kMostTitleCharacters)
      check("title", "expected a title of at most " + std::to_string(kMostTitleCharacters) +
                         " characters (the card wraps it to three lines), found " +
                         std::to_string(characters(*request.title)) + "; shorten it");
    v.title = true;
    v.title_text = *request.title;
  }
  if (request.captions) v.captions = *request.captions;
  if (v.camera == "phone" && !v.placed) {
    // A phone records the picture alone.
    v.overlay = false;
    v.title = false;
    v.end_card = false;
    v.phase_portrait = false;
    v.captions.clear();
  }
  if (!request.video.empty()) {
    check("video", video_file_problem(request.video));
    // A GIF is drawn small unless the command line asks otherwise: its size is what keeps it
    // to a few MB, and text drawn at the GIF's own size stays sharp (scaling text down blurs it).
    if (video_format_of(request.video) == VideoFormat::kGif) {
      if (!request.size) {
        const double scale = std::min({1.0, static_cast<double>(kGifMaxWidth) / v.width,
                                       static_cast<double>(kGifMaxHeight) / v.height});
        v.width = 2 * static_cast<int>(std::lround(0.5 * v.width * scale));
        v.height = 2 * static_cast<int>(std::lround(0.5 * v.height * scale));
      }
      if (!request.fps) v.fps = std::min(v.fps, kGifMaxFps);
    }
  }
  return v;
}

std::size_t run_frame_count(const VideoDesc& video, double duration) {
  const double frames = duration * video.fps * video.slow_motion;
  // Frames at t_k = k / (fps s) < duration; a product that should be whole is taken as whole.
  return static_cast<std::size_t>(std::max(0.0, std::ceil(frames - 1e-6)));
}

std::size_t title_frame_count(const VideoDesc& video) {
  return video.title ? static_cast<std::size_t>(std::lround(kTitleSeconds * video.fps)) : 0;
}

std::size_t end_card_frame_count(const VideoDesc& video) {
  return video.end_card ? static_cast<std::size_t>(std::lround(kEndCardSeconds * video.fps)) : 0;
}

std::size_t guard_banner_frame_count(const VideoDesc& video) {
  return static_cast<std::size_t>(std::lround(kGuardBannerSeconds * video.fps));
}

}  // namespace fl
