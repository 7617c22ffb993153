#include "tracking/given_video.hpp"

#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <stdexcept>

namespace fl {
namespace {

std::mutex g_mutex;
std::map<std::string, GivenVideo> g_videos;

void say(char* error, std::size_t size, const std::string& text) {
  std::snprintf(error, size, "%s", text.c_str());
}

void copy_name(char* to, std::size_t size, const std::string& from) {
  std::snprintf(to, size, "%s", from.c_str());
}

int read_given(const char* path, int most_width, int, DecodedFrameHandler handler, void* user,
               DecodedVideoInfo* info, char* error, std::size_t error_size) {
  const std::string name = std::filesystem::path(path).filename().string();
  const std::lock_guard lock(g_mutex);
  const auto it = g_videos.find(name);
  if (it == g_videos.end()) {
    say(error, error_size,
        "this video reached the lab without its frames: the page decodes a video with the "
        "browser's own decoder before the lab reads it; choose the file on the page again");
    return 1;
  }
  const GivenVideo& video = it->second;
  if (!video.failure.empty()) {
    say(error, error_size, video.failure);
    return 1;
  }
  *info = DecodedVideoInfo{};
  copy_name(info->container, sizeof info->container, video.container);
  copy_name(info->codec, sizeof info->codec, video.codec);
  info->width = video.width;
  info->height = video.height;
  info->fps = video.fps;
  info->scale = video.scale;
  for (const GrayFrame& frame : video.frames) {
    if (frame.width > most_width) {
      say(error, error_size,
          "the page gave frames " + std::to_string(frame.width) + " pixels across, more than the " +
              std::to_string(most_width) + " the lab reads");
      return 1;
    }
    const DecodedGreyFrame grey{frame.levels.data(), frame.width, frame.height, frame.t_s};
    ++info->frames_read;
    if (handler(user, &grey, info) == 0) break;
  }
  return 0;
}

int write_no_png(const char*, int, int, const unsigned char*, char* error, std::size_t size) {
  say(error, size, "the lab in the browser writes no picture of the tracked video");
  return 1;
}

const VideoDecoderModule kGiven{kVideoDecoderAbi, &read_given, &write_no_png};

}  // namespace

void give_video(const std::string& name, GivenVideo video) {
  for (std::size_t i = 0; i < video.frames.size(); ++i) {
    const GrayFrame& f = video.frames[i];
    if (f.width != video.frames.front().width || f.height != video.frames.front().height ||
        f.levels.size() != static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height))
      throw std::invalid_argument("frame " + std::to_string(i + 1) +
                                  " is not the size of the first, or its levels do not fill it");
    if (i > 0 && !(f.t_s > video.frames[i - 1].t_s))
      throw std::invalid_argument("frame " + std::to_string(i + 1) +
                                  "'s time does not follow the frame before's");
  }
  const std::lock_guard lock(g_mutex);
  g_videos[name] = std::move(video);
}

void forget_given_videos() {
  const std::lock_guard lock(g_mutex);
  g_videos.clear();
}

const VideoDecoderModule* given_video_decoder() {
  return &kGiven;
}

}  // namespace fl
