// The decoder module, frictionlab-decoder.so (tracking/video_decoder_module.hpp): a video read
// through libav as a stream of grey frames, one decoded at a time (memory does not grow with the
// video's length), each scaled down by area averaging; and libav's PNG encoder for the tracker's
// picture. Its one exported symbol is the entry at the end; everything else is hidden.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "tracking/video_decoder_module.hpp"
#include "tracking/video_frames.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libswscale/swscale.h>
}

namespace fl {
namespace {

// Why a video cannot be read, said without its file's name (the executable locates it).
class DecodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::string av_text(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

struct FormatCloser {
  void operator()(AVFormatContext* f) const { avformat_close_input(&f); }
};
struct CodecCloser {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct FrameCloser {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct PacketCloser {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct ScaleCloser {
  void operator()(SwsContext* s) const { sws_freeContext(s); }
};

// One video stream being decoded into grey frames.
class GreyDecoder {
 public:
  GreyDecoder(const std::string& path, int most_width, int threads) : path_(path) {
    AVFormatContext* format = nullptr;
    if (const int code = avformat_open_input(&format, path.c_str(), nullptr, nullptr); code < 0)
      throw DecodeError("libav cannot read it as a video (" + av_text(code) +
                        "); a video cut short before its end cannot be "
                        "read: copy it from the phone again");
    format_.reset(format);
    if (const int code = avformat_find_stream_info(format, nullptr); code < 0)
      throw DecodeError("libav finds no stream in it (" + av_text(code) + ")");
    const AVCodec* codec = nullptr;
    stream_index_ = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
    if (stream_index_ < 0 || codec == nullptr)
      throw DecodeError(stream_index_ == AVERROR_DECODER_NOT_FOUND
                            ? "this build's libav has no decoder for its video; convert it to "
                              "H.264 (MP4) first"
                            : "expected a video stream, found none (a sound recording?)");
    stream_ = format->streams[stream_index_];
    decoder_.reset(avcodec_alloc_context3(codec));
    avcodec_parameters_to_context(decoder_.get(), stream_->codecpar);
    decoder_->thread_count = threads;
    decoder_->thread_type = FF_THREAD_FRAME | FF_THREAD_SLICE;
    if (const int code = avcodec_open2(decoder_.get(), codec, nullptr); code < 0)
      throw DecodeError("libav cannot open its decoder (" + av_text(code) + ")");
    info_.container = format->iformat->name;
    info_.codec = codec->name;
    info_.width = stream_->codecpar->width;
    info_.height = stream_->codecpar->height;
    if (info_.width <= 0 || info_.height <= 0)
      throw DecodeError("its video stream says no frame size");
    if (stream_->avg_frame_rate.num > 0 && stream_->avg_frame_rate.den > 0)
      info_.fps = av_q2d(stream_->avg_frame_rate);
    const int width = std::min(info_.width, most_width);
    out_width_ = width;
    out_height_ = std::max(
        1, static_cast<int>(std::lround(static_cast<double>(info_.height) * width / info_.width)));
    info_.scale = static_cast<double>(width) / info_.width;
    packet_.reset(av_packet_alloc());
    frame_.reset(av_frame_alloc());
    grey_.width = out_width_;
    grey_.height = out_height_;
    grey_.levels.assign(static_cast<std::size_t>(out_width_) * out_height_, 0);
  }

  VideoStream run(const FrameHandler& hand_on) {
    bool more = true;
    int read_code = 0;
    while (more && (read_code = av_read_frame(format_.get(), packet_.get())) >= 0) {
      if (packet_->stream_index == stream_index_) more = decode(packet_.get(), hand_on);
      av_packet_unref(packet_.get());
    }
    if (!more) return info_;
    if (read_code != AVERROR_EOF)
      throw DecodeError(where() + "libav cannot read on (" + av_text(read_code) +
                        "): the file is damaged");
    if (decode(nullptr, hand_on) && stream_->nb_frames > 0 &&
        info_.frames_read + 1 < stream_->nb_frames)
      throw DecodeError("the video ends at frame " + std::to_string(info_.frames_read) +
                        " of the " + std::to_string(stream_->nb_frames) +
                        " its container lists: the file is cut short; copy it again");
    return info_;
  }

 private:
  std::string where() const {
    char at[64];
    std::snprintf(at, sizeof at, "frame %d (t = %.3f s): ", info_.frames_read, last_t_s_);
    return at;
  }

  bool decode(const AVPacket* packet, const FrameHandler& hand_on) {
    if (const int code = avcodec_send_packet(decoder_.get(), packet);
        code < 0 && code != AVERROR_EOF)
      throw DecodeError(where() + "libav cannot decode the next frame (" + av_text(code) +
                        "): the file is damaged or cut short");
    for (;;) {
      const int code = avcodec_receive_frame(decoder_.get(), frame_.get());
      if (code == AVERROR(EAGAIN) || code == AVERROR_EOF) return true;
      if (code < 0)
        throw DecodeError(where() + "libav cannot decode it (" + av_text(code) +
                          "): the file is damaged");
      const bool go_on = hand_on_frame(hand_on);
      av_frame_unref(frame_.get());
      if (!go_on) return false;
    }
  }

  bool hand_on_frame(const FrameHandler& hand_on) {
    SwsContext* scale = sws_getCachedContext(
        scale_.release(), frame_->width, frame_->height, static_cast<AVPixelFormat>(frame_->format),
        out_width_, out_height_, AV_PIX_FMT_GRAY8, SWS_AREA, nullptr, nullptr, nullptr);
    scale_.reset(scale);
    if (scale == nullptr) throw DecodeError(where() + "libav cannot convert its pixels to grey");
    std::uint8_t* planes[4] = {grey_.levels.data(), nullptr, nullptr, nullptr};
    int strides[4] = {out_width_, 0, 0, 0};
    sws_scale(scale, frame_->data, frame_->linesize, 0, frame_->height, planes, strides);
    const std::int64_t stamp = frame_->best_effort_timestamp;
    double t = stamp == AV_NOPTS_VALUE
                   ? (info_.fps > 0 ? info_.frames_read / info_.fps : info_.frames_read)
                   : static_cast<double>(stamp) * av_q2d(stream_->time_base);
    if (info_.frames_read == 0) first_t_s_ = t;
    t -= first_t_s_;
    last_t_s_ = t;
    grey_.t_s = t;
    ++info_.frames_read;
    return hand_on(grey_, info_);
  }

  std::string path_;
  std::unique_ptr<AVFormatContext, FormatCloser> format_;
  std::unique_ptr<AVCodecContext, CodecCloser> decoder_;
  std::unique_ptr<AVPacket, PacketCloser> packet_;
  std::unique_ptr<AVFrame, FrameCloser> frame_;
  std::unique_ptr<SwsContext, ScaleCloser> scale_;
  AVStream* stream_ = nullptr;
  int stream_index_ = -1;
  int out_width_ = 0;
  int out_height_ = 0;
  double first_t_s_ = 0.0;
  double last_t_s_ = 0.0;
  GrayFrame grey_;
  VideoStream info_;
};

void write_rgb_png_here(const std::string& path, int width, int height, const unsigned char* rgb) {
  const AVCodec* codec = avcodec_find_encoder(AV_CODEC_ID_PNG);
  if (codec == nullptr) throw std::runtime_error(path + ": this build's libav has no PNG encoder");
  std::unique_ptr<AVCodecContext, CodecCloser> encoder(avcodec_alloc_context3(codec));
  encoder->width = width;
  encoder->height = height;
  encoder->pix_fmt = AV_PIX_FMT_RGB24;
  encoder->time_base = {1, 1};
  if (const int code = avcodec_open2(encoder.get(), codec, nullptr); code < 0)
    throw std::runtime_error(path + ": cannot start libav's PNG encoder (" + av_text(code) + ")");
  std::unique_ptr<AVFrame, FrameCloser> frame(av_frame_alloc());
  frame->width = width;
  frame->height = height;
  frame->format = AV_PIX_FMT_RGB24;
  av_image_fill_arrays(frame->data, frame->linesize, rgb, AV_PIX_FMT_RGB24, width, height, 1);
  std::unique_ptr<AVPacket, PacketCloser> packet(av_packet_alloc());
  if (avcodec_send_frame(encoder.get(), frame.get()) < 0 ||
      avcodec_send_frame(encoder.get(), nullptr) < 0 ||
      avcodec_receive_packet(encoder.get(), packet.get()) < 0)
    throw std::runtime_error(path + ": libav's PNG encoder failed");
  const std::string part = path + ".part";
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(packet->data), packet->size);
    if (!out) throw std::runtime_error(part + ": cannot write");
  }
  std::filesystem::rename(part, path);
}

}  // namespace
}  // namespace fl

namespace {

void say(const std::string& text, char* error, std::size_t size) {
  if (size == 0) return;
  const std::size_t n = std::min(text.size(), size - 1);
  std::memcpy(error, text.data(), n);
  error[n] = '\0';
}

void copy_name(const std::string& name, char* to, std::size_t size) {
  say(name, to, size);
}

int read_video(const char* path, int most_width, int threads, fl::DecodedFrameHandler handler,
               void* user, fl::DecodedVideoInfo* info, char* error, std::size_t error_size) {
  try {
    // Every failure is said in the message, located by the caller; libav's own lines would
    // repeat it.
    if (av_log_get_level() == AV_LOG_INFO) av_log_set_level(AV_LOG_QUIET);
    fl::GreyDecoder decoder(path, std::max(1, most_width), threads);
    const auto fill = [&](const fl::VideoStream& s) {
      copy_name(s.container, info->container, sizeof info->container);
      copy_name(s.codec, info->codec, sizeof info->codec);
      info->width = s.width;
      info->height = s.height;
      info->fps = s.fps;
      info->frames_read = s.frames_read;
      info->scale = s.scale;
    };
    const fl::VideoStream done = decoder.run([&](const fl::GrayFrame& f, const fl::VideoStream& s) {
      fill(s);
      const fl::DecodedGreyFrame frame{f.levels.data(), f.width, f.height, f.t_s};
      return handler(user, &frame, info) != 0;
    });
    fill(done);
    return 0;
  } catch (const std::exception& e) {
    say(e.what(), error, error_size);
    return 1;
  }
}

int write_png(const char* path, int width, int height, const unsigned char* rgb, char* error,
              std::size_t error_size) {
  try {
    fl::write_rgb_png_here(path, width, height, rgb);
    return 0;
  } catch (const std::exception& e) {
    say(e.what(), error, error_size);
    return 1;
  }
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const fl::VideoDecoderModule*
frictionlab_video_decoder() {
  static const fl::VideoDecoderModule module{fl::kVideoDecoderAbi, &read_video, &write_png};
  return &module;
}
