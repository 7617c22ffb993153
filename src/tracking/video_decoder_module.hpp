// The seam between the frictionlab executable and the video decoder module,
// frictionlab-decoder.so: the shared object that holds libav (and through it a hundred codec
// libraries), opened with dlopen only when a video is read (tracking/video_frames.cpp). Every
// other command, the sweeps, MPI ranks and the Python module start without it.
//
// Only C types cross: the module exports one C function, kVideoDecoderEntry, returning its
// VideoDecoderModule; the executable refuses one whose abi differs from its own. Errors come back
// as a return value and a message (no exception crosses).
//
// Where the executable looks: $FRICTIONLAB_DECODER_MODULE if set, else frictionlab-decoder.so in
// the folder of the running executable (/proc/self/exe), where the build puts it.
#pragma once

#include <cstddef>
#include <cstdint>

namespace fl {

inline constexpr const char* kVideoDecoderEntry = "frictionlab_video_decoder";
inline constexpr const char* kVideoDecoderVariable = "FRICTIONLAB_DECODER_MODULE";
inline constexpr const char* kVideoDecoderFile = "frictionlab-decoder.so";
inline constexpr int kVideoDecoderAbi = 2;

extern "C" {

// One decoded frame, grey, rows top-down and tightly packed (valid during the call only).
struct DecodedGreyFrame {
  const std::uint8_t* levels;
  int width;
  int height;
  double t_s;
};

// What is known of the stream (filled as it is opened; frames_read counts as they come).
struct DecodedVideoInfo {
  char container[64];
  char codec[32];
  int width;
  int height;
  double fps;  // 0 when the stream does not say
  int frames_read;
  double scale;  // the frames' pixels per video pixel
};

// Takes a frame; returns 0 to stop reading.
using DecodedFrameHandler = int (*)(void* user, const DecodedGreyFrame* frame,
                                    const DecodedVideoInfo* info);

struct VideoDecoderModule {
  int abi;
  // Decodes `path`, frames scaled down to at most `most_width` across; 0 when read to its end (or
  // stopped by the handler), else 1 with the reason in `error` (a message without the file's
  // name: the caller locates it).
  int (*read)(const char* path, int most_width, int threads, DecodedFrameHandler handler,
              void* user, DecodedVideoInfo* info, char* error, std::size_t error_size);
  // Writes an RGB image as a PNG (`path` + ".part", renamed); 0 when written, else 1 and `error`.
  int (*write_png)(const char* path, int width, int height, const unsigned char* rgb, char* error,
                   std::size_t error_size);
};

}  // extern "C"

}  // namespace fl
