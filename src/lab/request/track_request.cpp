#include "lab/request/track_request.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "hall_log/oscillation_log.hpp"
#include "hall_log/periodic_motion.hpp"
#include "hall_log/video_log.hpp"
#include "io/atomic_file.hpp"
#include "io/json_value.hpp"
#include "lab/logs/log_estimate.hpp"
#include "lab/request/output_paths.hpp"
#include "lab/request/video_fields.hpp"
#include "text/text.hpp"

namespace fl {
namespace {

constexpr const char* kTrackCsv = "track.csv";
constexpr const char* kTrackStill = "track.png";

TrackOptions checked_options(const TrackRequest& request, FieldChecks& checks) {
  if (request.video.empty()) checks.problem("video", "expected a video file, found none");
  if (request.out.empty()) checks.problem("out", "expected a folder for the track, found none");
  return checked_track_options(request.roi, request.scale, request.plate_length, checks);
}

// The track as a position table `estimate` reads: comments, then "t (s)" and "x (<unit>)".
std::string track_table(const TrackResult& result, const std::string& video) {
  const PlateTrack& t = result.tracked.track;
  std::string out = fmt::format(
      "# frictionlab track: {}\n# the plate followed without clicks: {} pixels in {} patch(es), "
      "along a line at {:.1f} deg (0 across the picture, 90 up)\n# x: its position along that "
      "line from its mean, in {}{}\nt (s),x ({})\n",
      video, t.pixels_followed, t.edges, t.direction_deg, t.unit,
      t.mm_per_px ? fmt::format(" ({:.6g} mm per pixel, from the {})", *t.mm_per_px, t.scale_from)
                  : std::string(" of the video (no scale given)"),
      t.unit);
  for (std::size_t k = 0; k < t.t_s.size(); ++k)
    out += fmt::format("{:.6f},{:.4f}\n", t.t_s[k], t.x[k]);
  return out;
}

// The first frame in grey with the followed pixels in orange and the region searched outlined.
void write_still(const PlateTrack& t, const std::string& path) {
  const GrayFrame& f = t.first;
  std::vector<unsigned char> rgb(static_cast<std::size_t>(f.width) * f.height * 3);
  for (std::size_t p = 0; p < f.levels.size(); ++p) {
    const unsigned char g = f.levels[p];
    const bool followed = t.followed[p] != 0;
    rgb[3 * p] = followed ? 255 : g;
    rgb[3 * p + 1] = followed ? static_cast<unsigned char>(90 + g / 3) : g;
    rgb[3 * p + 2] = followed ? 0 : g;
  }
  const auto box = [&](double v) { return static_cast<int>(std::lround(v * t.scale)); };
  const int x0 = std::clamp(box(t.region[0]), 0, f.width - 1);
  const int y0 = std::clamp(box(t.region[1]), 0, f.height - 1);
  const int x1 = std::clamp(box(t.region[0] + t.region[2]) - 1, 0, f.width - 1);
  const int y1 = std::clamp(box(t.region[1] + t.region[3]) - 1, 0, f.height - 1);
  const auto paint = [&](int x, int y) {
    const std::size_t p = static_cast<std::size_t>(y) * f.width + x;
    rgb[3 * p] = 0;
    rgb[3 * p + 1] = 200;
    rgb[3 * p + 2] = 255;
  };
  for (int x = x0; x <= x1; ++x) paint(x, y0), paint(x, y1);
  for (int y = y0; y <= y1; ++y) paint(x0, y), paint(x1, y);
  write_rgb_png(path, f.width, f.height, rgb);
}

}  // namespace

TrackResult track_video(const TrackRequest& request) {
  FieldChecks checks;
  const TrackOptions options = checked_options(request, checks);
  checks.throw_if_any();
  prepare_output_folder(request.out, "out");
  refuse_overwriting_inputs(request.out, {kTrackCsv, kTrackStill}, "out",
                            {{request.video, "the video"}});

  TrackResult result;
  result.tracked = track_plate_in_video(request.video, options);
  const PlateTrack& t = result.tracked.track;
  // As estimate reads a video (hall_log/video_log.hpp), without its refusal of no periodic
  // motion: a track without a period is still written, and said to have none.
  const Series positions = positions_of(t);
  const HallLog log =
      log_of_oscillation(positions, request.video, t.unit, periodicity_of(positions));
  result.amplitude = log.half_swing.value_or(0.0);
  result.stats = estimate_log(log, LogSetUp{}, false).stats;

  const std::filesystem::path folder(request.out);
  result.csv = (folder / kTrackCsv).string();
  result.still = (folder / kTrackStill).string();
  write_file_atomic(result.csv, track_table(result, request.video));
  write_still(t, result.still);
  return result;
}

nlohmann::json TrackResult::json() const {
  const VideoStream& v = tracked.video;
  const PlateTrack& t = tracked.track;
  const fl_estimator::Stats& s = stats;
  return {
      {"video",
       {{"container", v.container},
        {"codec", v.codec},
        {"width", v.width},
        {"height", v.height},
        {"fps", v.fps > 0 ? nlohmann::json(v.fps) : nlohmann::json(nullptr)},
        {"frames", v.frames_read}}},
      {"tracked",
       {{"pixels_followed", t.pixels_followed},
        {"patches", t.edges},
        {"direction_deg", t.direction_deg},
        {"noise_grey", t.noise_grey},
        {"frames_learned", t.frames_learned},
        {"region", t.region},
        {"plate_length_px", json_or_null(t.plate_length_px)}}},
      {"unit", t.unit},
      {"mm_per_px", json_or_null(t.mm_per_px)},
      {"scale_from", t.scale_from.empty() ? nlohmann::json(nullptr) : nlohmann::json(t.scale_from)},
      {"amplitude", amplitude},
      {"periods_used", s.periods_used},
      {"period_s", s.periods_used > 0 ? json_or_null(static_cast<double>(s.period_s))
                                      : nlohmann::json(nullptr)},
      {"period_std_s", s.periods_used > 1 ? json_or_null(static_cast<double>(s.period_std_s))
                                          : nlohmann::json(nullptr)},
      {"csv", csv},
      {"still", still},
  };
}

}  // namespace fl
