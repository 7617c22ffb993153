#include <cstdio>
#include <filesystem>

#include "render/components.hpp"
#include "render/video.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace fl::render {
namespace {

std::string av_error(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

class Mp4Encoder final : public FrameSink {
 public:
  explicit Mp4Encoder(VideoOptions options)
      : options_(std::move(options)), part_path_(options_.path + ".part") {
    if (options_.path.empty()) throw RenderError("a video needs a file name");
    if (options_.fps < 1 || options_.fps > 240)
      throw RenderError("a video's frame rate must be 1 to 240 fps, not " +
                        std::to_string(options_.fps));
    if (options_.crf < 0 || options_.crf > 51)
      throw RenderError("x264's crf must be 0 to 51, not " + std::to_string(options_.crf));
    // x264 reports its settings and statistics at AV_LOG_INFO, libav's default level: keep
    // warnings and errors only, unless the program chose a level itself.
    if (av_log_get_level() == AV_LOG_INFO) av_log_set_level(AV_LOG_WARNING);
    codec_ = avcodec_find_encoder_by_name("libx264");
    if (codec_ == nullptr)
      throw_missing("MP4 video", "the libx264 encoder in libavcodec",
                    "Debian's libavcodec59 has it; a build of FFmpeg without x264 does not");
  }

  ~Mp4Encoder() override {
    close();
    // Not finished: no partial file under any name.
    if (!finished_) {
      std::error_code ignored;
      std::filesystem::remove(part_path_, ignored);
    }
  }

  void write(const ImageView& frame) override {
    if (finished_) throw std::logic_error("a frame was written after the video was finished");
    if (codec_context_ == nullptr) open(frame.width, frame.height);
    if (frame.width != codec_context_->width || frame.height != codec_context_->height)
      throw RenderError("a frame of " + std::to_string(frame.width) + "x" +
                        std::to_string(frame.height) + " does not fit a video of " +
                        std::to_string(codec_context_->width) + "x" +
                        std::to_string(codec_context_->height));
    check(av_frame_make_writable(yuv_), "preparing a video frame");
    const std::uint8_t* source[1] = {frame.pixels};
    const int stride[1] = {static_cast<int>(frame.stride)};
    sws_scale(scaler_, source, stride, 0, frame.height, yuv_->data, yuv_->linesize);
    yuv_->pts = static_cast<std::int64_t>(count_);
    send(yuv_);
    ++count_;
  }

  void finish() override {
    if (finished_) return;
    if (codec_context_ == nullptr) throw RenderError("a video needs at least one frame");
    send(nullptr);
    check(av_write_trailer(format_), "finishing " + options_.path);
    close();
    std::error_code ec;
    std::filesystem::rename(part_path_, options_.path, ec);
    if (ec)
      throw RenderError("cannot move the finished video into place at " + options_.path + ": " +
                        ec.message());
    finished_ = true;
  }

  std::size_t frame_count() const override { return count_; }

 private:
  void check(int code, const std::string& what) const {
    if (code < 0) throw RenderError(what + ": " + av_error(code));
  }

  void open(int width, int height) {
    if (width % 2 != 0 || height % 2 != 0)
      throw RenderError("H.264 in yuv420p needs an even width and height, not " +
                        std::to_string(width) + "x" + std::to_string(height));
    const std::filesystem::path target(options_.path);
    if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
    check(avformat_alloc_output_context2(&format_, nullptr, "mp4", part_path_.c_str()),
          "starting an MP4 container for " + options_.path);
    stream_ = avformat_new_stream(format_, nullptr);
    if (stream_ == nullptr) throw RenderError("cannot add a video stream to " + options_.path);
    codec_context_ = avcodec_alloc_context3(codec_);
    if (codec_context_ == nullptr) throw RenderError("cannot allocate the H.264 encoder");
    AVCodecContext& c = *codec_context_;
    c.width = width;
    c.height = height;
    c.pix_fmt = AV_PIX_FMT_YUV420P;
    c.time_base = AVRational{1, options_.fps};
    c.framerate = AVRational{options_.fps, 1};
    c.gop_size = 2 * options_.fps;  // a key frame every 2 s: a class can seek
    c.thread_count = options_.encoder_threads;
    // BT.709, limited range: what players assume for HD, set and written in the stream.
    c.color_primaries = AVCOL_PRI_BT709;
    c.color_trc = AVCOL_TRC_BT709;
    c.colorspace = AVCOL_SPC_BT709;
    c.color_range = AVCOL_RANGE_MPEG;
    if (format_->oformat->flags & AVFMT_GLOBALHEADER) c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    check(av_opt_set(c.priv_data, "preset", options_.preset.c_str(), 0),
          "x264 has no preset '" + options_.preset + "'");
    check(av_opt_set(c.priv_data, "crf", std::to_string(options_.crf).c_str(), 0),
          "setting x264's crf");
    check(avcodec_open2(codec_context_, codec_, nullptr), "opening the H.264 encoder");
    check(avcodec_parameters_from_context(stream_->codecpar, codec_context_),
          "describing the video stream");
    stream_->time_base = c.time_base;
    stream_->avg_frame_rate = c.framerate;
    check(avio_open(&format_->pb, part_path_.c_str(), AVIO_FLAG_WRITE),
          "cannot write " + part_path_);
    // The movie's time scale (1000 by default) must count whole frames too, or the container's
    // duration is rounded to the millisecond (1 frame at 30 fps: 0.034 s).
    AVDictionary* muxer_options = nullptr;
    av_dict_set_int(&muxer_options, "movie_timescale", 1000L * options_.fps, 0);
    const int header = avformat_write_header(format_, &muxer_options);
    av_dict_free(&muxer_options);
    check(header, "writing the MP4 header of " + options_.path);

    yuv_ = av_frame_alloc();
    packet_ = av_packet_alloc();
    if (yuv_ == nullptr || packet_ == nullptr) throw RenderError("out of memory for video frames");
    yuv_->format = c.pix_fmt;
    yuv_->width = width;
    yuv_->height = height;
    yuv_->color_primaries = c.color_primaries;
    yuv_->color_trc = c.color_trc;
    yuv_->colorspace = c.colorspace;
    yuv_->color_range = c.color_range;
    check(av_frame_get_buffer(yuv_, 0), "allocating a video frame");
    scaler_ = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P,
                             SWS_BILINEAR, nullptr, nullptr, nullptr);
    if (scaler_ == nullptr) throw RenderError("swscale cannot convert RGBA to yuv420p");
    // swscale converts with BT.601 unless told: BT.709 coefficients, full-range RGB in,
    // limited-range YUV out.
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(scaler_, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  }

  // Sends a frame (null: the end) and writes every packet the encoder has ready.
  void send(AVFrame* frame) {
    check(avcodec_send_frame(codec_context_, frame), "encoding a video frame");
    for (;;) {
      const int got = avcodec_receive_packet(codec_context_, packet_);
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      check(got, "encoding a video frame");
      // Each frame lasts one tick of 1/fps; without it the container's duration comes out one
      // frame short (4.967 s for 150 frames at 30 fps).
      if (packet_->duration == 0) packet_->duration = 1;
      av_packet_rescale_ts(packet_, codec_context_->time_base, stream_->time_base);
      packet_->stream_index = stream_->index;
      check(av_interleaved_write_frame(format_, packet_), "writing " + options_.path);
    }
  }

  void close() {
    if (scaler_ != nullptr) sws_freeContext(scaler_);
    scaler_ = nullptr;
    av_frame_free(&yuv_);
    av_packet_free(&packet_);
    avcodec_free_context(&codec_context_);
    if (format_ != nullptr) {
      if (format_->pb != nullptr) avio_closep(&format_->pb);
      avformat_free_context(format_);
      format_ = nullptr;
    }
  }

  VideoOptions options_;
  std::string part_path_;
  const AVCodec* codec_ = nullptr;
  AVFormatContext* format_ = nullptr;
  AVStream* stream_ = nullptr;
  AVCodecContext* codec_context_ = nullptr;
  AVFrame* yuv_ = nullptr;
  AVPacket* packet_ = nullptr;
  SwsContext* scaler_ = nullptr;
  std::size_t count_ = 0;
  bool finished_ = false;
};

}  // namespace

std::unique_ptr<FrameSink> make_mp4_sink(const VideoOptions& options) {
  auto encoder = std::make_unique<Mp4Encoder>(options);
  if (options.queue_frames <= 0) return encoder;
  return std::make_unique<ThreadedSink>(std::move(encoder),
                                        static_cast<std::size_t>(options.queue_frames));
}

}  // namespace fl::render
