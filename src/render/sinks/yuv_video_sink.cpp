// MP4 (H.264 by libx264) and WebM (VP9 by libvpx-vp9): both yuv420p with BT.709 colour set in
// swscale and tagged in the stream, a constant frame rate and a key frame every 2 s.
#include <cstdio>

#include "render/components.hpp"
#include "render/sinks/av_output.hpp"
#include "render/sinks/video.hpp"

extern "C" {
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace fl::render {
namespace {

// What differs between the two: the encoder, the muxer and the encoder's settings.
struct Codec {
  VideoFormat format;
  const char* encoder;
  const char* muxer;
  const char* what;  // for messages
};

Codec codec_of(VideoFormat format) {
  if (format == VideoFormat::kWebm) return {format, "libvpx-vp9", "webm", "WebM (VP9)"};
  return {VideoFormat::kMp4, "libx264", "mp4", "MP4 (H.264)"};
}

class YuvVideoEncoder final : public FrameSink {
 public:
  YuvVideoEncoder(VideoOptions options, Codec codec) : options_(std::move(options)), codec_(codec) {
    if (options_.path.empty()) throw RenderError("a video needs a file name");
    if (options_.fps < 1 || options_.fps > 240)
      throw RenderError("a video's frame rate must be 1 to 240 fps, not " +
                        std::to_string(options_.fps));
    if (options_.crf < 0 || options_.crf > 51)
      throw RenderError("x264's crf must be 0 to 51, not " + std::to_string(options_.crf));
    if (options_.vp9_crf < 0 || options_.vp9_crf > 63)
      throw RenderError("VP9's crf must be 0 to 63, not " + std::to_string(options_.vp9_crf));
    quiet_av_log();
    encoder_ = avcodec_find_encoder_by_name(codec_.encoder);
    if (encoder_ == nullptr)
      throw_missing(std::string(codec_.what) + " video",
                    std::string("the ") + codec_.encoder + " encoder in libavcodec",
                    "Debian's libavcodec59 has it; a build of FFmpeg without it does not");
  }

  ~YuvVideoEncoder() override { close(); }

  void write(const ImageView& frame) override {
    if (finished_) throw std::logic_error("a frame was written after the video was finished");
    if (context_ == nullptr) open(frame.width, frame.height);
    if (frame.width != context_->width || frame.height != context_->height)
      throw RenderError("a frame of " + std::to_string(frame.width) + "x" +
                        std::to_string(frame.height) + " does not fit a video of " +
                        std::to_string(context_->width) + "x" + std::to_string(context_->height));
    av_check(av_frame_make_writable(yuv_), "preparing a video frame");
    const std::uint8_t* source[1] = {frame.pixels};
    const int stride[1] = {static_cast<int>(frame.stride)};
    sws_scale(scaler_, source, stride, 0, frame.height, yuv_->data, yuv_->linesize);
    yuv_->pts = static_cast<std::int64_t>(count_);
    send(yuv_);
    ++count_;
  }

  void finish() override {
    if (finished_) return;
    if (context_ == nullptr) throw RenderError("a video needs at least one frame");
    send(nullptr);
    output_->finish();
    close();
    finished_ = true;
  }

  std::size_t frame_count() const override { return count_; }

 private:
  void set(const char* key, const std::string& value) {
    av_check(av_opt_set(context_->priv_data, key, value.c_str(), 0),
             std::string(codec_.encoder) + " takes no " + key + " '" + value + "'");
  }

  void open(int width, int height) {
    if (width % 2 != 0 || height % 2 != 0)
      throw RenderError(std::string(codec_.what) +
                        " in yuv420p needs an even width and height, not " + std::to_string(width) +
                        "x" + std::to_string(height));
    output_ = std::make_unique<AvOutput>(options_.path, codec_.muxer);
    context_ = avcodec_alloc_context3(encoder_);
    if (context_ == nullptr) throw RenderError(std::string("cannot allocate ") + codec_.encoder);
    AVCodecContext& c = *context_;
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
    if (output_->format().flags & AVFMT_GLOBALHEADER) c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    if (codec_.format == VideoFormat::kMp4) {
      set("preset", options_.preset);
      set("crf", std::to_string(options_.crf));
    } else {
      // Constant quality (crf with no bit-rate target); "realtime" with cpu-used 8 and rows in
      // parallel keeps VP9 about as fast as drawing the frames (docs/rendering.md).
      c.bit_rate = 0;
      set("crf", std::to_string(options_.vp9_crf));
      set("deadline", "realtime");
      set("cpu-used", "8");
      set("row-mt", "1");
    }
    av_check(avcodec_open2(context_, encoder_, nullptr),
             std::string("opening the ") + codec_.encoder + " encoder");
    // The muxer's options, freed however open() ends.
    AVDictionary* muxer_options = nullptr;
    const std::unique_ptr<AVDictionary*, void (*)(AVDictionary**)> free_options(&muxer_options,
                                                                                &av_dict_free);
    if (codec_.format == VideoFormat::kMp4) {
      // The movie's time scale (1000 by default) must count whole frames too, or the
      // container's duration is rounded to the millisecond (1 frame at 30 fps: 0.034 s).
      av_dict_set_int(&muxer_options, "movie_timescale", 1000L * options_.fps, 0);
    }
    output_->open(c, &muxer_options);

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
    av_check(av_frame_get_buffer(yuv_, 0), "allocating a video frame");
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
    av_check(avcodec_send_frame(context_, frame), "encoding a video frame");
    output_->drain(*context_, *packet_);
  }

  void close() {
    if (scaler_ != nullptr) sws_freeContext(scaler_);
    scaler_ = nullptr;
    av_frame_free(&yuv_);
    av_packet_free(&packet_);
    avcodec_free_context(&context_);
    output_.reset();  // removes the .part file of a video not finished
  }

  VideoOptions options_;
  Codec codec_;
  const AVCodec* encoder_ = nullptr;
  std::unique_ptr<AvOutput> output_;
  AVCodecContext* context_ = nullptr;
  AVFrame* yuv_ = nullptr;
  AVPacket* packet_ = nullptr;
  SwsContext* scaler_ = nullptr;
  std::size_t count_ = 0;
  bool finished_ = false;
};

std::unique_ptr<FrameSink> behind_queue(std::unique_ptr<FrameSink> sink, int queue_frames) {
  if (queue_frames <= 0) return sink;
  return std::make_unique<ThreadedSink>(std::move(sink), static_cast<std::size_t>(queue_frames));
}

}  // namespace

std::unique_ptr<FrameSink> make_mp4_sink(const VideoOptions& options) {
  return behind_queue(std::make_unique<YuvVideoEncoder>(options, codec_of(VideoFormat::kMp4)),
                      options.queue_frames);
}

std::unique_ptr<FrameSink> make_video_sink(const VideoOptions& options) {
  const std::optional<VideoFormat> format = video_format_of(options.path);
  if (!format) throw RenderError(video_file_problem(options.path));
  if (*format == VideoFormat::kGif)
    return behind_queue(make_gif_sink(options), options.queue_frames);
  return behind_queue(std::make_unique<YuvVideoEncoder>(options, codec_of(*format)),
                      options.queue_frames);
}

}  // namespace fl::render
