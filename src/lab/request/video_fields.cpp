#include "lab/request/video_fields.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "text/text.hpp"

namespace fl {
namespace {

// "X,Y,W,H" -> the four numbers, or a problem.
std::optional<std::array<int, 4>> region_of(const std::string& text, FieldChecks& checks) {
  std::vector<std::string_view> parts;
  std::string_view rest = text;
  for (std::size_t comma; (comma = rest.find(',')) != std::string_view::npos;
       rest = rest.substr(comma + 1))
    parts.push_back(trim(rest.substr(0, comma)));
  parts.push_back(trim(rest));
  std::array<int, 4> region{};
  bool ok = parts.size() == 4;
  for (std::size_t i = 0; ok && i < 4; ++i) {
    const char* end = parts[i].data() + parts[i].size();
    const auto [at, error] = std::from_chars(parts[i].data(), end, region[i]);
    ok = error == std::errc() && at == end && region[i] >= 0 && !parts[i].empty();
  }
  if (ok && (region[2] < 2 || region[3] < 2)) ok = false;
  if (!ok) {
    checks.problem("roi", text,
                   "expected the region as X,Y,W,H in the video's pixels (whole numbers: the "
                   "top-left corner from the picture's top-left, then a width and a height of 2 "
                   "or more, such as 100,200,640,240), found \"" +
                       text + "\"");
    return std::nullopt;
  }
  return region;
}

}  // namespace

TrackOptions checked_track_options(const std::string& roi, const std::optional<double>& scale,
                                   const std::optional<QuantityInput>& plate_length,
                                   FieldChecks& checks) {
  TrackOptions options;
  if (!roi.empty()) options.roi = region_of(roi, checks);
  if (scale) {
    if (!std::isfinite(*scale) || *scale <= 0.0)
      checks.problem("scale", fmt::format("{}", *scale),
                     fmt::format("expected millimetres per pixel of the video, a finite positive "
                                 "number, found {}",
                                 *scale));
    else
      options.mm_per_px = *scale;
  }
  if (plate_length) {
    const double length =
        checks.positive(*plate_length, Dimension::kLength, "plate_length", "the plate's length");
    if (std::isfinite(length) && length > 0) options.plate_length_mm = length * 1e3;
  }
  if (scale && plate_length)
    checks.problem("plate_length",
                   "expected the scale or the plate's length, found both: give one of them");
  return options;
}

}  // namespace fl
