// The container side of a video written through libav (internal to the render library): one
// video stream muxed into `path + ".part"`, renamed to `path` when finished; a file abandoned
// unfinished leaves nothing under either name. Each packet lasts one frame, so the container's
// duration is frames / fps exactly. Shared by the H.264/VP9 sink and the GIF sink.
#pragma once

#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

namespace fl::render {

// libav's text for an error code.
std::string av_error(int code);
// Throws RenderError "<what>: <libav's text>" for a negative code.
void av_check(int code, const std::string& what);
// libav reports encoders' settings at AV_LOG_INFO, its default level: keep warnings and errors
// only, unless the program chose a level itself.
void quiet_av_log();

class AvOutput {
 public:
  // `muxer`: "mp4", "webm", "gif". Creates the file's folder and the muxer; the stream comes in
  // open().
  AvOutput(const std::string& path, const char* muxer);
  AvOutput(const AvOutput&) = delete;
  AvOutput& operator=(const AvOutput&) = delete;
  ~AvOutput();

  const AVOutputFormat& format() const { return *format_->oformat; }
  // Adds the stream of an opened encoder and writes the header. `options`: the muxer's.
  void open(const AVCodecContext& encoder, AVDictionary** options);
  // Writes every packet the encoder has ready (after a frame or the end was sent to it).
  void drain(AVCodecContext& encoder, AVPacket& packet);
  // Writes the trailer, closes the file and moves it into place.
  void finish();
  const std::string& path() const { return path_; }

 private:
  void close();

  std::string path_;
  std::string part_path_;
  AVFormatContext* format_ = nullptr;
  AVStream* stream_ = nullptr;
  bool finished_ = false;
};

}  // namespace fl::render
