// A teaching video's captions drawn as subtitles: light text on a dark translucent box, centred
// just above the overlay's bottom panels (the Hall plot on the left, the results on the right),
// so it covers neither. Long text wraps to at most three lines; text that still does not fit is
// drawn smaller, down to the overlay's smallest text, and then cut with "…". Sizes are laid out
// for 640x360 and scale with the frame, as the rig overlay's (rig_overlay.hpp).
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "render/overlay.hpp"
#include "scene/captions_yaml.hpp"

namespace fl::render {

// The caption shown at simulated time t [s]: the one with at <= t < until, where a caption
// without `until` lasts until the next caption's `at`, the last until the run's end. Nothing
// before the first or between captions that end early. Frame times within 1 ns of a caption's
// start count as at it.
std::optional<std::string> caption_at(std::span<const Caption> captions, double t);

// `text` broken into lines no wider than `max_width` as `width_of` measures them: at spaces,
// and at each line end of the text; a word wider than `max_width` alone is broken between its
// characters. Runs of spaces and empty lines are dropped.
std::vector<std::string> wrap_text(std::string_view text, float max_width,
                                   const std::function<float(std::string_view)>& width_of);

// Text fitted to at most `most_lines` lines of `max_width`: the largest size, in steps of
// `scale` pixels from `largest` x scale down to `smallest` x scale, that keeps it to that many
// lines; at the smallest, the lines beyond cut and the last ended with "…". (Captions and the
// title card's title.)
struct FittedText {
  float pixel_size = 0.0f;
  std::vector<std::string> lines;
};
FittedText fit_text(Overlay& overlay, std::string_view text, float max_width, float largest,
                    float smallest, float scale, std::size_t most_lines);

// Where and how large a caption is drawn in a width x height frame.
struct CaptionLayout {
  float pixel_size = 0.0f;         // the text's
  std::vector<std::string> lines;  // at most kCaptionLines
  Rect box;                        // the dark box behind them
};
inline constexpr std::size_t kCaptionLines = 3;

// The caption's layout; no lines (and an empty box) in frames too small for the overlay.
CaptionLayout layout_caption(Overlay& overlay, int width, int height, std::string_view text);

// Draws the caption as a subtitle into a width x height frame.
void draw_caption(Overlay& overlay, int width, int height, std::string_view text);

}  // namespace fl::render
