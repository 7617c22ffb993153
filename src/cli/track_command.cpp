// frictionlab track: a phone's video of the rig, its plate followed without clicks.
#include <memory>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "lab/request/track_request.hpp"

namespace fl::cli {
namespace {

struct TrackOptions {
  std::string video;
  std::string out = "out/track";
  std::string roi;
  std::optional<double> scale;
  std::string plate_length;
  bool json = false;
};

int run_track(const TrackOptions& o) {
  TrackRequest request;
  request.video = o.video;
  request.out = o.out;
  request.roi = o.roi;
  request.scale = o.scale;
  if (!o.plate_length.empty()) request.plate_length = o.plate_length;
  const TrackResult result = track_video(request);
  if (o.json) {
    fmt::print("{}\n", result.json().dump(2));
    return 0;
  }
  const VideoStream& v = result.tracked.video;
  const PlateTrack& t = result.tracked.track;
  fmt::print("frictionlab track: {}\n", o.video);
  fmt::print("  {:<20} {} ({}), {}x{}, {} frames{}\n", "video", v.codec, v.container, v.width,
             v.height, v.frames_read, v.fps > 0 ? fmt::format(" at {:.3g} fps", v.fps) : "");
  fmt::print(
      "  {:<20} {} pixels in {} patch(es) (of {}x{} read), along a line at {:.1f} deg "
      "(0 across, 90 up); learned from the first {} frames; noise {:.1f} grey levels\n",
      "followed", t.pixels_followed, t.edges, t.first.width, t.first.height, t.direction_deg,
      t.frames_learned, t.noise_grey);
  fmt::print("  {:<20} {} {}\n", "scale",
             t.mm_per_px ? fmt::format("{:.5g} mm per pixel", *t.mm_per_px)
                         : "none: positions in the video's pixels",
             t.mm_per_px ? "(from the " + t.scale_from + ")"
                         : "(give --scale or --plate-length for millimetres)");
  if (t.plate_length_px)
    fmt::print("  {:<20} {:.1f} pixels between the two ends followed\n", "plate length",
               *t.plate_length_px);
  fmt::print("  {:<20} {:.3f} {}\n", "amplitude", result.amplitude, t.unit);
  if (result.stats.periods_used > 0)
    fmt::print(
        "  {:<20} {:.6f} +- {:.6f} s (N = {}); mu_k: frictionlab estimate {} "
        "--spacing L\n",
        "period T", static_cast<double>(result.stats.period_s),
        static_cast<double>(result.stats.period_std_s), result.stats.periods_used, result.csv);
  else
    fmt::print("  {:<20} none: the rig's estimator finds no period in the track\n", "period T");
  fmt::print("  {:<20} {} (x against t), {} (what was followed, in orange)\n", "files", result.csv,
             result.still);
  return result.stats.periods_used > 0 ? 0 : 3;
}

}  // namespace

Command add_track_command(CLI::App& app, const GlobalOptions&) {
  auto options = std::make_shared<TrackOptions>();
  CLI::App* sub = app.add_subcommand(
      "track", "Follow the plate in a phone's video of the rig: x(t) as a CSV and a picture");
  sub->add_option("video", options->video, "The video (MP4, MOV, WebM, MKV, AVI)")->required();
  sub->add_option("--out", options->out, "Folder for track.csv and track.png")
      ->capture_default_str();
  sub->add_option("--roi", options->roi,
                  "The region to search, X,Y,W,H in the video's pixels (default: the whole "
                  "picture)");
  sub->add_option("--scale", options->scale, "Millimetres per pixel of the video");
  sub->add_option("--plate-length", options->plate_length,
                  "Or the plate's length (both ends in view), e.g. \"200 mm\"");
  sub->add_flag("--json", options->json, "Print one JSON object instead of the text");
  return Command{sub, [options] { return run_track(*options); }};
}

}  // namespace fl::cli
