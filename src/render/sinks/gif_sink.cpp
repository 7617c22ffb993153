// An animated GIF through libav: one palette of 256 colours for the whole clip, made by
// libavfilter's palettegen from every frame and applied by paletteuse with ordered (Bayer)
// dithering, and only the rectangle that changed since the previous frame. palettegen gives its
// palette at the end of the clip, so the filter graph holds the frames (RGBA) until finish():
// 0.9 MB a frame at 640x360, 110 MB for 12 s at 10 fps.
#include <cstring>

#include "render/components.hpp"
#include "render/sinks/av_output.hpp"
#include "render/sinks/video.hpp"

extern "C" {
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
}

namespace fl::render {
namespace {

class GifEncoder final : public FrameSink {
 public:
  explicit GifEncoder(VideoOptions options) : options_(std::move(options)) {
    if (options_.path.empty()) throw RenderError("a video needs a file name");
    if (options_.fps < 1 || options_.fps > 50)
      throw RenderError(
          "a GIF's frame rate must be 1 to 50 fps (its delays are whole 1/100 s), "
          "not " +
          std::to_string(options_.fps));
    quiet_av_log();
    encoder_ = avcodec_find_encoder_by_name("gif");
    if (encoder_ == nullptr)
      throw_missing("GIF video", "the gif encoder in libavcodec",
                    "Debian's libavcodec59 has it; a build of FFmpeg without it does not");
    if (avfilter_get_by_name("palettegen") == nullptr ||
        avfilter_get_by_name("paletteuse") == nullptr)
      throw_missing("GIF video", "libavfilter's palettegen and paletteuse",
                    "Debian's libavfilter8 has them");
  }

  ~GifEncoder() override { close(); }

  void write(const ImageView& frame) override {
    if (finished_) throw std::logic_error("a frame was written after the video was finished");
    if (graph_ == nullptr) open(frame.width, frame.height);
    if (frame.width != width_ || frame.height != height_)
      throw RenderError("a frame of " + std::to_string(frame.width) + "x" +
                        std::to_string(frame.height) + " does not fit a video of " +
                        std::to_string(width_) + "x" + std::to_string(height_));
    AVFrame* rgba = av_frame_alloc();
    if (rgba == nullptr) throw RenderError("out of memory for video frames");
    rgba->format = AV_PIX_FMT_RGBA;
    rgba->width = width_;
    rgba->height = height_;
    rgba->pts = static_cast<std::int64_t>(count_);
    int code = av_frame_get_buffer(rgba, 0);
    if (code >= 0) {
      const std::size_t row = static_cast<std::size_t>(width_) * 4;
      for (int y = 0; y < height_; ++y)
        std::memcpy(rgba->data[0] + static_cast<std::ptrdiff_t>(y) * rgba->linesize[0],
                    frame.pixels + static_cast<std::ptrdiff_t>(y) * frame.stride, row);
      // The graph takes the frame's reference.
      code = av_buffersrc_add_frame_flags(source_, rgba, 0);
    }
    av_frame_free(&rgba);
    av_check(code, "queueing a GIF frame");
    ++count_;
  }

  void finish() override {
    if (finished_) return;
    if (graph_ == nullptr) throw RenderError("a video needs at least one frame");
    av_check(av_buffersrc_add_frame_flags(source_, nullptr, 0), "ending the GIF's frames");
    AVFrame* paletted = av_frame_alloc();
    if (paletted == nullptr) throw RenderError("out of memory for video frames");
    try {
      for (;;) {
        const int got = av_buffersink_get_frame(sink_, paletted);
        if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) break;
        av_check(got, "making the GIF's palette");
        send(paletted);
        av_frame_unref(paletted);
      }
    } catch (...) {
      av_frame_free(&paletted);
      throw;
    }
    av_frame_free(&paletted);
    send(nullptr);
    output_->finish();
    close();
    finished_ = true;
  }

  std::size_t frame_count() const override { return count_; }

 private:
  void open(int width, int height) {
    width_ = width;
    height_ = height;
    output_ = std::make_unique<AvOutput>(options_.path, "gif");
    context_ = avcodec_alloc_context3(encoder_);
    packet_ = av_packet_alloc();
    graph_ = avfilter_graph_alloc();
    if (context_ == nullptr || packet_ == nullptr || graph_ == nullptr)
      throw RenderError("out of memory for the GIF encoder");
    AVCodecContext& c = *context_;
    c.width = width;
    c.height = height;
    c.pix_fmt = AV_PIX_FMT_PAL8;
    c.time_base = AVRational{1, options_.fps};
    c.framerate = AVRational{options_.fps, 1};
    av_check(avcodec_open2(context_, encoder_, nullptr), "opening the GIF encoder");
    // loop 0: the GIF plays on and on, as a teaching clip on a slide should.
    AVDictionary* muxer_options = nullptr;
    const std::unique_ptr<AVDictionary*, void (*)(AVDictionary**)> free_options(&muxer_options,
                                                                                &av_dict_free);
    av_dict_set(&muxer_options, "loop", "0", 0);
    output_->open(c, &muxer_options);
    make_graph();
  }

  // rgba frames -> split -> palettegen (the clip's palette) -> paletteuse -> pal8 frames.
  void make_graph() {
    const std::string source_args =
        "video_size=" + std::to_string(width_) + "x" + std::to_string(height_) +
        ":pix_fmt=" + std::to_string(static_cast<int>(AV_PIX_FMT_RGBA)) + ":time_base=1/" +
        std::to_string(options_.fps) + ":pixel_aspect=1/1";
    av_check(avfilter_graph_create_filter(&source_, avfilter_get_by_name("buffer"), "in",
                                          source_args.c_str(), nullptr, graph_),
             "making the GIF's filter graph (its source)");
    av_check(avfilter_graph_create_filter(&sink_, avfilter_get_by_name("buffersink"), "out",
                                          nullptr, nullptr, graph_),
             "making the GIF's filter graph (its sink)");
    const enum AVPixelFormat pal8[] = {AV_PIX_FMT_PAL8, AV_PIX_FMT_NONE};
    av_check(av_opt_set_int_list(sink_, "pix_fmts", pal8, AV_PIX_FMT_NONE, AV_OPT_SEARCH_CHILDREN),
             "asking the GIF's filter graph for paletted frames");
    // stats_mode=full: the colours of every frame count alike (the still rig dominates);
    // bayer_scale 3: a fine pattern that LZW still compresses; diff_mode=rectangle: pixels
    // outside the changed rectangle keep the previous frame's indices, so they cost nothing.
    const char* graph =
        "split[a][b];[a]palettegen=stats_mode=full[p];"
        "[b][p]paletteuse=dither=bayer:bayer_scale=3:diff_mode=rectangle";
    AVFilterInOut* outputs = avfilter_inout_alloc();
    AVFilterInOut* inputs = avfilter_inout_alloc();
    if (outputs == nullptr || inputs == nullptr) {
      avfilter_inout_free(&outputs);
      avfilter_inout_free(&inputs);
      throw RenderError("out of memory for the GIF's filter graph");
    }
    outputs->name = av_strdup("in");
    outputs->filter_ctx = source_;
    outputs->pad_idx = 0;
    outputs->next = nullptr;
    inputs->name = av_strdup("out");
    inputs->filter_ctx = sink_;
    inputs->pad_idx = 0;
    inputs->next = nullptr;
    int code = avfilter_graph_parse_ptr(graph_, graph, &inputs, &outputs, nullptr);
    avfilter_inout_free(&outputs);
    avfilter_inout_free(&inputs);
    av_check(code, "making the GIF's filter graph");
    av_check(avfilter_graph_config(graph_, nullptr), "configuring the GIF's filter graph");
  }

  void send(AVFrame* frame) {
    if (frame != nullptr) frame->pict_type = AV_PICTURE_TYPE_NONE;
    av_check(avcodec_send_frame(context_, frame), "encoding a GIF frame");
    output_->drain(*context_, *packet_);
  }

  void close() {
    avfilter_graph_free(&graph_);  // frees the source and the sink with it
    source_ = nullptr;
    sink_ = nullptr;
    av_packet_free(&packet_);
    avcodec_free_context(&context_);
    output_.reset();  // removes the .part file of a GIF not finished
  }

  VideoOptions options_;
  const AVCodec* encoder_ = nullptr;
  std::unique_ptr<AvOutput> output_;
  AVCodecContext* context_ = nullptr;
  AVPacket* packet_ = nullptr;
  AVFilterGraph* graph_ = nullptr;
  AVFilterContext* source_ = nullptr;
  AVFilterContext* sink_ = nullptr;
  int width_ = 0;
  int height_ = 0;
  std::size_t count_ = 0;
  bool finished_ = false;
};

}  // namespace

std::unique_ptr<FrameSink> make_gif_sink(const VideoOptions& options) {
  return std::make_unique<GifEncoder>(options);
}

}  // namespace fl::render
