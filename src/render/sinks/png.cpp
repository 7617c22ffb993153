#include "render/sinks/png.hpp"

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <filesystem>
#include <vector>

#include "io/atomic_file.hpp"
#include "render/components.hpp"

namespace fl::render {
namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

void no_flush(png_structp) {}

// libpng reports errors by longjmp; nothing with a destructor lives in this frame.
bool encode_rows(png_structp png, png_infop info, png_bytepp rows, int width, int height,
                 int compression, std::string* out) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, &append_bytes, &no_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, compression);
  png_write_info(png, info);
  // Our rows are RGBA: libpng drops the fourth byte.
  png_set_filler(png, 0, PNG_FILLER_AFTER);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

std::string encode_png(const ImageView& frame, int compression) {
  if (frame.empty()) throw RenderError("cannot encode an empty frame as PNG");
  if (compression < 0 || compression > 9)
    throw RenderError("PNG compression is a zlib level 0..9, not " + std::to_string(compression));
  std::vector<png_bytep> rows(static_cast<std::size_t>(frame.height));
  for (int y = 0; y < frame.height; ++y)
    rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(frame.row(y));
  std::string out;
  out.reserve(static_cast<std::size_t>(frame.width) * frame.height);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) throw RenderError("libpng could not start a PNG");
  png_infop info = png_create_info_struct(png);
  const bool ok = info != nullptr &&
                  encode_rows(png, info, rows.data(), frame.width, frame.height, compression, &out);
  png_destroy_write_struct(&png, &info);
  if (!ok) throw RenderError("libpng failed to encode a PNG");
  return out;
}

void write_png(const std::string& path, const ImageView& frame, int compression) {
  write_file_atomic(path, encode_png(frame, compression));
}

Image read_png(const std::string& path) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str()))
    throw RenderError("cannot read the PNG " + path + ": " + image.message);
  image.format = PNG_FORMAT_RGBA;
  Image out(static_cast<int>(image.width), static_cast<int>(image.height));
  if (!png_image_finish_read(&image, nullptr, out.rgba.data(), 0, nullptr)) {
    const std::string why = image.message;
    png_image_free(&image);
    throw RenderError("cannot read the PNG " + path + ": " + why);
  }
  return out;
}

namespace {

class PngSink final : public FrameSink {
 public:
  explicit PngSink(PngSinkOptions options) : options_(std::move(options)) {
    namespace fs = std::filesystem;
    if (options_.directory.empty()) throw RenderError("PNG frames need a folder");
    if (options_.digits < 1 || options_.digits > 12)
      throw RenderError("PNG frame numbers take 1 to 12 digits");
    fs::create_directories(options_.directory);
    // Frames of an earlier run would make the folder a mix of two runs.
    std::vector<fs::path> old;
    for (const auto& entry : fs::directory_iterator(options_.directory)) {
      if (entry.is_regular_file() && is_frame_name(entry.path().filename().string()))
        old.push_back(entry.path());
    }
    if (!old.empty() && !options_.replace_existing)
      throw RenderError("the folder " + options_.directory + " already holds " +
                        std::to_string(old.size()) + " frame(s) named " + options_.prefix +
                        "*.png from an earlier run; remove them or choose another folder");
    for (const auto& path : old) fs::remove(path);
  }

  // prefix, one or more digits, ".png".
  bool is_frame_name(const std::string& name) const {
    const std::string& prefix = options_.prefix;
    if (name.size() <= prefix.size() + 4 || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - 4, 4, ".png") != 0)
      return false;
    for (std::size_t i = prefix.size(); i < name.size() - 4; ++i) {
      if (name[i] < '0' || name[i] > '9') return false;
    }
    return true;
  }

  void write(const ImageView& frame) override {
    if (finished_) throw std::logic_error("a frame was written after the sink was finished");
    const std::string name =
        png_frame_name(options_, options_.first_index + static_cast<int>(count_));
    write_png((std::filesystem::path(options_.directory) / name).string(), frame,
              options_.compression);
    ++count_;
  }
  void finish() override { finished_ = true; }
  std::size_t frame_count() const override { return count_; }

 private:
  PngSinkOptions options_;
  std::size_t count_ = 0;
  bool finished_ = false;
};

}  // namespace

std::unique_ptr<FrameSink> make_png_sink(const PngSinkOptions& options) {
  return std::make_unique<PngSink>(options);
}

}  // namespace fl::render
