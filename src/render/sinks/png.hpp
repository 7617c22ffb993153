// PNG files: one frame (RGB, 8 bits, zlib level 1 by default: fast, about 20 ms at 720p) or a
// folder of numbered frames. Files are written atomically (temporary file, then rename).
#pragma once

#include <memory>
#include <string>

#include "render/image.hpp"
#include "render/sinks/frame_sink.hpp"

namespace fl::render {

// The PNG file of a frame, as bytes. compression: zlib level 0..9.
std::string encode_png(const ImageView& frame, int compression = 1);
// Writes the frame to `path` atomically. Throws std::runtime_error naming the path.
void write_png(const std::string& path, const ImageView& frame, int compression = 1);
// Reads any PNG as RGBA, rows top-down. Throws RenderError naming the path.
Image read_png(const std::string& path);

struct PngSinkOptions {
  std::string directory;          // made if missing
  std::string prefix = "frame_";  // file names: prefix + zero-padded number + ".png"
  int digits = 6;                 // frame_000000.png
  int first_index = 0;            // number of the first frame
  int compression = 1;            // zlib level 0..9
  bool replace_existing = false;  // frames of an earlier run in the folder: remove them
                                  // (true) or refuse to start (false)
};

// "frame_000042.png" for index 42.
std::string png_frame_name(const PngSinkOptions& options, int index);

// Writes each frame to its own numbered file, on the caller's thread (wrap it in a
// ThreadedSink to overlap). Throws RenderError if the folder holds frames of an earlier run
// and replace_existing is false.
std::unique_ptr<FrameSink> make_png_sink(const PngSinkOptions& options);

// The same on a pool of `threads` encoder threads (0: one per core), each frame to its own file,
// so frames are encoded side by side (render/sinks/png_pool_sink.cpp). write() copies the frame
// into one of 2 x threads slots, waiting while all are taken; an encoder's error is rethrown by the
// next write() or by finish(), which waits for every frame taken. Destroyed without finish(), the
// frames not yet begun are not written (each file is whole or absent).
std::unique_ptr<FrameSink> make_png_pool_sink(const PngSinkOptions& options, unsigned threads = 0);

}  // namespace fl::render
