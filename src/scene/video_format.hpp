// The teaching video's file format, chosen by the file's extension: .mp4 (H.264), .gif (an
// animated GIF with a palette made for the clip) or .webm (VP9). A plain value that the command
// line checks before any work and the video module's sinks follow.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace fl {

enum class VideoFormat { kMp4, kGif, kWebm };

// The accepted extensions, for messages: ".mp4, .gif or .webm".
inline constexpr std::string_view kVideoExtensions = ".mp4, .gif or .webm";

// The format a file name asks for by its extension (case-insensitive); nothing for any other.
std::optional<VideoFormat> video_format_of(std::string_view path);

// "mp4", "gif", "webm".
std::string_view video_format_name(VideoFormat format);

// Why a file name cannot be a video (no or an unknown extension), or empty when it can.
std::string video_file_problem(std::string_view path);

// A GIF stays small when it is drawn at most this size and rate, unless the command line asks
// for others: the scene's size scaled down (its aspect kept) and its rate capped. 640x360 is the
// overlay's own layout (its smallest text 12 px); 10 fps is a whole number of the GIF's 1/100 s
// ticks. The paper's rig's 10 s (and its 2 s title) came to 0.89 MB (20 fps: 1.6 MB).
inline constexpr int kGifMaxWidth = 640;
inline constexpr int kGifMaxHeight = 360;
inline constexpr int kGifMaxFps = 10;

}  // namespace fl
