#include "scene/video_format.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

namespace fl {
namespace {

constexpr std::array<std::pair<std::string_view, VideoFormat>, 3> kFormats = {{
    {"mp4", VideoFormat::kMp4},
    {"gif", VideoFormat::kGif},
    {"webm", VideoFormat::kWebm},
}};

// The extension after the last dot of the file's name (not of a folder), lower case.
std::string extension_of(std::string_view path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string_view name = slash == std::string_view::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.find_last_of('.');
  if (dot == std::string_view::npos || dot == 0) return {};
  std::string ext(name.substr(dot + 1));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

std::optional<VideoFormat> video_format_of(std::string_view path) {
  const std::string ext = extension_of(path);
  for (const auto& [name, format] : kFormats)
    if (ext == name) return format;
  return std::nullopt;
}

std::string_view video_format_name(VideoFormat format) {
  for (const auto& [name, f] : kFormats)
    if (f == format) return name;
  return "?";
}

std::string video_file_problem(std::string_view path) {
  if (video_format_of(path)) return {};
  const std::string ext = extension_of(path);
  const std::string found = ext.empty() ? "a name without an extension" : "\"." + ext + "\"";
  return "expected a video file ending in " + std::string(kVideoExtensions) +
         " (H.264, an animated GIF or VP9), found " + found + " in \"" + std::string(path) + "\"";
}

}  // namespace fl
