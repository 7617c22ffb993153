#include "tracking/video_frames.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>

#include "io/input_error.hpp"
#include "tracking/given_video.hpp"
#include "tracking/video_decoder_module.hpp"

namespace fl {
namespace {

namespace fs = std::filesystem;

#ifdef FRICTIONLAB_DECODER_BUILT
constexpr bool kDecoderBuilt = true;
#else
constexpr bool kDecoderBuilt = false;
#endif

constexpr const char* kWithoutLibav =
    "this build of frictionlab reads no video (it was built without libav: apt-get install "
    "libavcodec-dev libavformat-dev libswscale-dev and build again)";

// $FRICTIONLAB_DECODER_MODULE, else the module beside the running executable.
fs::path module_path() {
  std::error_code ec;
  if (const char* env = std::getenv(kVideoDecoderVariable); env != nullptr && *env != '\0') {
    const fs::path absolute = fs::absolute(fs::path(env), ec);
    return ec ? fs::path(env) : absolute;
  }
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path(kVideoDecoderFile) : exe.parent_path() / kVideoDecoderFile;
}

// The module, opened the first time a video is read and kept for the process (libav keeps
// threads and state that must not outlive its code: no dlclose); or why it cannot be.
struct Opened {
  const VideoDecoderModule* module = nullptr;
  std::string error;
};

Opened open_module() {
  Opened out;
#ifdef __EMSCRIPTEN__
  // The browser's build: the page decodes, with the browser's own decoder.
  out.module = given_video_decoder();
  return out;
#endif
  if (!kDecoderBuilt) {
    out.error = kWithoutLibav;
    return out;
  }
  const fs::path path = module_path();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    out.error = "reading a video needs the decoder module " + path.string() +
                ", which does not exist (the build puts " + kVideoDecoderFile +
                " beside the frictionlab executable; " + kVideoDecoderVariable +
                " names another file)";
    return out;
  }
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    out.error = "the decoder module " + path.string() +
                " cannot be loaded: " + (why != nullptr ? why : "unknown error");
    return out;
  }
  using Entry = const VideoDecoderModule* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, kVideoDecoderEntry));
  const VideoDecoderModule* module = entry != nullptr ? entry() : nullptr;
  if (module == nullptr || module->abi != kVideoDecoderAbi) {
    out.error = "the file " + path.string() +
                " is not this frictionlab's decoder module (built from other sources?)";
    return out;
  }
  out.module = module;
  return out;
}

const VideoDecoderModule& decoder(const std::string& path) {
  static std::once_flag once;
  static Opened opened;
  std::call_once(once, [] { opened = open_module(); });
  if (opened.module == nullptr) throw InputError(SourceLocation(path), opened.error);
  return *opened.module;
}

VideoStream stream_of(const DecodedVideoInfo& info) {
  VideoStream s;
  s.container = info.container;
  s.codec = info.codec;
  s.width = info.width;
  s.height = info.height;
  s.fps = info.fps;
  s.frames_read = info.frames_read;
  s.scale = info.scale;
  return s;
}

// What the module's frame handler carries: the caller's handler, and an exception it threw (kept
// here: none crosses the module).
struct Handing {
  const FrameHandler* frame;
  GrayFrame grey;
  std::exception_ptr thrown;
};

int hand_on(void* user, const DecodedGreyFrame* frame, const DecodedVideoInfo* info) {
  auto* h = static_cast<Handing*>(user);
  try {
    h->grey.width = frame->width;
    h->grey.height = frame->height;
    h->grey.t_s = frame->t_s;
    h->grey.levels.assign(frame->levels,
                          frame->levels + static_cast<std::size_t>(frame->width) *
                                              static_cast<std::size_t>(frame->height));
    return (*h->frame)(h->grey, stream_of(*info)) ? 1 : 0;
  } catch (...) {
    h->thrown = std::current_exception();
    return 0;
  }
}

}  // namespace

VideoStream read_video_frames(const std::string& path, int most_width, const FrameHandler& frame,
                              int threads) {
  if (most_width < 1) throw std::invalid_argument("read_video_frames: most_width must be positive");
  const VideoDecoderModule& module = decoder(path);
  Handing handing{&frame, {}, nullptr};
  DecodedVideoInfo info{};
  char error[1024] = {};
  const int status = module.read(path.c_str(), most_width, threads, &hand_on, &handing, &info,
                                 error, sizeof error);
  if (handing.thrown) std::rethrow_exception(handing.thrown);
  if (status != 0) throw InputError(SourceLocation(path), error);
  return stream_of(info);
}

void write_rgb_png(const std::string& path, int width, int height,
                   const std::vector<unsigned char>& rgb) {
  const VideoDecoderModule& module = decoder(path);
  char error[1024] = {};
  if (module.write_png(path.c_str(), width, height, rgb.data(), error, sizeof error) != 0)
    throw std::runtime_error(path + ": " + error);
}

}  // namespace fl
