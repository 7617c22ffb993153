// Finds and opens the video module (video_module.hpp) the first time a run asks for frames.
// The module stays loaded for the rest of the process: OSMesa's LLVM and libav keep state
// (threads, atexit handlers) that must not outlive their code, and LeakSanitizer needs the
// module's symbols at exit to read its reports. So no dlclose.
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include "lab/video/video_module.hpp"

#ifndef FRICTIONLAB_VIDEO_MODULE_BUILT
#error "FRICTIONLAB_VIDEO_MODULE_BUILT is set by the fl_lab_recorder target"
#endif
#ifndef FRICTIONLAB_VIDEO_MODULE_FILE
#error "FRICTIONLAB_VIDEO_MODULE_FILE is set by the fl_lab_recorder target"
#endif

namespace fl {
namespace {

namespace fs = std::filesystem;

// What a build without rendering says, as the recorder always has.
constexpr const char* kWithoutRendering =
    "video, frames and stills need off-screen rendering (the drawing layer and a GL back end: "
    "OSMesa, libpng, stb_truetype), which this build of frictionlab does not have (configure "
    "with -DFRICTIONLAB_WITH_RENDER=ON -DFRICTIONLAB_WITH_OSMESA=ON after apt-get install "
    "libosmesa6-dev libpng-dev libstb-dev libgl-dev fonts-dejavu-core)";

// $FRICTIONLAB_VIDEO_MODULE, else the module beside the running executable. Empty with the
// reason in *error when neither can be had.
fs::path module_path(std::string* error) {
  const char* env = std::getenv(kVideoModuleVariable);
  // Absolute: dlopen would look up a bare file name in the library path, not here.
  std::error_code ec;
  if (env != nullptr && *env != '\0') {
    const fs::path absolute = fs::absolute(fs::path(env), ec);
    return ec ? fs::path(env) : absolute;
  }
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    *error = "video, frames and stills need the video module " +
             std::string(FRICTIONLAB_VIDEO_MODULE_FILE) +
             ", which is looked for beside the frictionlab executable, but /proc/self/exe cannot "
             "be read (" +
             ec.message() + "); set " + kVideoModuleVariable + " to the module's path";
    return {};
  }
  return exe.parent_path() / FRICTIONLAB_VIDEO_MODULE_FILE;
}

// Opens the module; on failure returns null with the reason in *error.
const VideoModule* open_module(std::string* error) {
  if (!FRICTIONLAB_VIDEO_MODULE_BUILT) {
    *error = kWithoutRendering;
    return nullptr;
  }
  const fs::path path = module_path(error);
  if (path.empty()) return nullptr;
  const bool from_env =
      std::getenv(kVideoModuleVariable) != nullptr && *std::getenv(kVideoModuleVariable) != '\0';
  const std::string where =
      path.string() + (from_env ? std::string(" (from ") + kVideoModuleVariable + ")" : "");
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    *error = "video, frames and stills need the video module " + where +
             ", which does not exist (the build puts " + FRICTIONLAB_VIDEO_MODULE_FILE +
             " beside the frictionlab executable; " + kVideoModuleVariable + " names another file)";
    return nullptr;
  }
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    *error = "the video module " + where + " cannot be loaded: " + (why ? why : "unknown error");
    return nullptr;
  }
  using Entry = const VideoModule* (*)();
  // POSIX guarantees that a function's address survives the round trip through void*.
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, kVideoModuleEntry));
  const VideoModule* module = entry != nullptr ? entry() : nullptr;
  if (module == nullptr) {
    *error = "the file " + where + " is not a frictionlab video module (it has no " +
             kVideoModuleEntry + ")";
    return nullptr;
  }
  if (!(module->abi == VideoModuleAbi{})) {
    *error = "the video module " + where +
             " was built from other frictionlab sources than this executable (rebuild both)";
    return nullptr;
  }
  return module;
}

}  // namespace

#if defined(__SANITIZE_ADDRESS__)
// Under LeakSanitizer (the asan preset): Mesa's OSMesa, which the module loads, keeps a
// framebuffer per format and size and 16 bytes per context for the process's life
// (tests/render/lsan.supp has the details), which would fail every video run at exit. Only
// allocations with libOSMesa on their stack are suppressed. The sanitizer runtime looks this
// function up in the executable: a module opened with dlopen later cannot provide it.
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\n";
}

// And LeakSanitizer keeps no record of dynamic TLS (intercept_tls_get_addr=0). The libraries the
// module brings in (LLVM through Mesa's swrast_dri.so, GnuTLS through libavformat) have
// thread-local storage that glibc mallocs when a thread first touches it. GCC 12's runtime guesses
// such a block's extent from the 16 bytes in front of it whenever the block starts 16 bytes into
// a page (its "glibc >= 2.19" rule); under AddressSanitizer those bytes are the allocator's chunk
// header, so it records a range that is not memory ({0x34ce, 0x1800001102} for LLVM's block) and
// the leak check at exit dies scanning it ("Tracer caught signal 11: addr=0x34d0", "LeakSanitizer
// has encountered a fatal error", status 134) whenever the heap puts the block there. Nothing is
// lost: the blocks are heap chunks the thread's DTV points to, which the check reaches from the
// thread's static TLS (docs/rendering.md, "LeakSanitizer"). LSAN_OPTIONS and ASAN_OPTIONS still
// override this.
extern "C" const char* __lsan_default_options();
extern "C" const char* __lsan_default_options() {
  return "intercept_tls_get_addr=0";
}
#endif

const VideoModule& load_video_module() {
  struct Loaded {
    const VideoModule* module = nullptr;
    std::string error;
  };
  // Once per process, thread-safe.
  static const Loaded loaded = [] {
    Loaded l;
    l.module = open_module(&l.error);
    return l;
  }();
  if (loaded.module == nullptr) throw VideoUnavailable(loaded.error);
  return *loaded.module;
}

}  // namespace fl
