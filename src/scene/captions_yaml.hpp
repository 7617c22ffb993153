// A teaching video's captions: subtitles shown while the run's simulated time t lies in
// [at, until). A caption without `until` stays until the next caption's `at`, the last one until
// the run ends. Captions follow simulated time, so slow motion stretches them. The strict reader
// of the YAML list (the scene's `video.captions`, or a file given to `run --captions`).
#pragma once

#include <array>
#include <string_view>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace fl {

class YamlNode;

struct Caption {
  double at = 0.0;              // s of simulated time it appears
  std::optional<double> until;  // s it goes; none: at the next caption's `at`, or the run's end
  std::string text;             // UTF-8; a line end starts a new line
};

// What a caption may name of the run, filled in before the frames are drawn
// (lab/video/caption_values.hpp); any other {name} is refused.
inline constexpr std::array<std::string_view, 5> kCaptionPlaceholders = {
    "{mu_k}", "{material}", "{T}", "{temperature}", "{spacing}"};

// The most characters (code points) a caption may hold: three lines of subtitle at 16:9.
inline constexpr std::size_t kCaptionMaxCharacters = 200;

// Reads a list of {at, until, text}; every error is located at its key. Times are >= 0, each
// caption's `at` after the one before, `until` after its `at` and not past the next `at`; the
// text is UTF-8, not empty, at most kCaptionMaxCharacters.
std::vector<Caption> read_captions(const YamlNode& list);

// A captions file: a map whose one key `captions` holds that list (an empty list: no captions).
// Errors are located at file:line:column.
std::vector<Caption> load_captions_file(const std::string& file);

}  // namespace fl
