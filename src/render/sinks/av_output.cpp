#include "render/sinks/av_output.hpp"

#include <filesystem>

#include "render/components.hpp"

extern "C" {
#include <libavutil/log.h>
}

namespace fl::render {

std::string av_error(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

void av_check(int code, const std::string& what) {
  if (code < 0) throw RenderError(what + ": " + av_error(code));
}

void quiet_av_log() {
  if (av_log_get_level() == AV_LOG_INFO) av_log_set_level(AV_LOG_WARNING);
}

AvOutput::AvOutput(const std::string& path, const char* muxer)
    : path_(path), part_path_(path + ".part") {
  const std::filesystem::path target(path_);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  // The muxer by name: the .part file's extension would not tell it.
  av_check(avformat_alloc_output_context2(&format_, nullptr, muxer, part_path_.c_str()),
           std::string("starting a ") + muxer + " container for " + path_);
}

AvOutput::~AvOutput() {
  close();
  // Not finished: no partial file under any name.
  if (!finished_) {
    std::error_code ignored;
    std::filesystem::remove(part_path_, ignored);
  }
}

void AvOutput::open(const AVCodecContext& encoder, AVDictionary** options) {
  stream_ = avformat_new_stream(format_, nullptr);
  if (stream_ == nullptr) throw RenderError("cannot add a video stream to " + path_);
  av_check(avcodec_parameters_from_context(stream_->codecpar, &encoder),
           "describing the video stream");
  stream_->time_base = encoder.time_base;
  stream_->avg_frame_rate = encoder.framerate;
  av_check(avio_open(&format_->pb, part_path_.c_str(), AVIO_FLAG_WRITE),
           "cannot write " + part_path_);
  av_check(avformat_write_header(format_, options), "writing the header of " + path_);
}

void AvOutput::drain(AVCodecContext& encoder, AVPacket& packet) {
  for (;;) {
    const int got = avcodec_receive_packet(&encoder, &packet);
    if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
    av_check(got, "encoding a video frame");
    // Each frame lasts one tick of 1/fps; without it the container's duration comes out one
    // frame short (4.967 s for 150 frames at 30 fps).
    if (packet.duration == 0) packet.duration = 1;
    av_packet_rescale_ts(&packet, encoder.time_base, stream_->time_base);
    packet.stream_index = stream_->index;
    av_check(av_interleaved_write_frame(format_, &packet), "writing " + path_);
  }
}

void AvOutput::finish() {
  if (finished_) return;
  av_check(av_write_trailer(format_), "finishing " + path_);
  close();
  std::error_code ec;
  std::filesystem::rename(part_path_, path_, ec);
  if (ec)
    throw RenderError("cannot move the finished video into place at " + path_ + ": " +
                      ec.message());
  finished_ = true;
}

void AvOutput::close() {
  if (format_ == nullptr) return;
  if (format_->pb != nullptr) avio_closep(&format_->pb);
  avformat_free_context(format_);
  format_ = nullptr;
}

}  // namespace fl::render
