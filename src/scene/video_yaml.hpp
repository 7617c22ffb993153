// The scene's `video` part: how `frictionlab run --video/--frames/--still` draws the rig (frame
// size, frame rate, slow motion, camera, orbit, title card, captions). Plain structs with their
// defaults, and the strict reader of the YAML key. The command line's --size, --fps,
// --slow-motion, --camera, --orbit, --title and --captions override these values and go through
// the same checks.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/captions_yaml.hpp"

namespace fl {

class YamlNode;

// A camera placed by hand (instead of a preset).
struct VideoCameraPlacement {
  std::array<double, 3> position{0.0, -0.4, 0.15};  // m, world
  std::array<double, 3> target{0.0, 0.0, 0.0};      // m, world: the point at the frame's centre
  double fov = 0.6108652381980153;                  // rad, vertical field of view (35 deg)
};

struct VideoDesc {
  int width = 1280;              // pixels (even: H.264 in yuv420p)
  int height = 720;              // pixels (even)
  int fps = 30;                  // frames per second of video
  double slow_motion = 1.0;      // factor s: the video shows 1/s simulated seconds per second,
                                 // rendering fps x s frames per simulated second
  std::string camera = "front";  // preset: front, top, sensor, phone (see kCameraPresets)
  std::optional<VideoCameraPlacement> placed;  // a placed camera instead of the preset
  double orbit = 0.0;                          // rad per second of video, about the vertical
                                               // through the camera's target
  bool title = false;             // a title card (kTitleSeconds of video) before the run
  std::string title_text;         // the card's title (run --title); empty: the default title
  bool end_card = false;          // an end card (kEndCardSeconds) with the run's T, mu_k and regime
  bool phase_portrait = false;    // v against x with the theory's ellipse and the slip limit
  std::vector<Caption> captions;  // subtitles at simulated times (captions_yaml.hpp)
  // The teaching overlay (panels, force arrows, captions, cards); off for a phone's recording,
  // which is the picture alone (lab/video/video_settings.hpp effective_video).
  bool overlay = true;
};

// Seconds of video the title card lasts (frames rendered before the run's first frame).
inline constexpr double kTitleSeconds = 2.0;
// Seconds of video the end card lasts, and the banner over the last frame of a run a guard
// stopped (both after the run's last frame).
inline constexpr double kEndCardSeconds = 3.0;
inline constexpr double kGuardBannerSeconds = 2.0;

// The camera presets: the whole rig from the front (from -y, a little above and to the right),
// from above, a close-up on the Hall sensor and the magnet that passes under it, and a phone on a
// support beside the rig, level with the plate and square on to its motion: the picture alone,
// as a phone records it (no overlay, captions, title or end card: what `frictionlab track` and
// `estimate` read as a student's video).
inline constexpr std::array<std::string_view, 4> kCameraPresets = {"front", "top", "sensor",
                                                                   "phone"};

// Reads `video:`; every error is located at its key. Keys: size ("1280x720" or [1280, 720]),
// fps, slow_motion, camera (a preset name, or {position, target, fov}), orbit, title, end_card,
// phase_portrait, captions.
VideoDesc read_video(const YamlNode& node);

// "1280x720" -> {1280, 720}; nothing for anything else.
std::optional<std::array<int, 2>> parse_video_size(std::string_view text);

// The reason a value is out of range, or empty when it is fine (shared with the command line).
std::string video_size_problem(int width, int height);
std::string video_fps_problem(int fps);
std::string video_slow_motion_problem(double factor);
std::string video_camera_problem(std::string_view preset);
std::string video_orbit_problem(double rad_per_second);

}  // namespace fl
