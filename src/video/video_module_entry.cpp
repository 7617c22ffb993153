// The entry of the video module, frictionlab-video.so (video_module.hpp): the one symbol the
// module exports. Everything else in it, its own code and the static libraries linked in, is
// hidden (src/lab/CMakeLists.txt), so nothing in it can clash with the executable's copies.
#include "lab/video/video_module.hpp"

extern "C" __attribute__((visibility("default"))) const fl::VideoModule*
frictionlab_video_module() {
  static const fl::VideoModule module{fl::VideoModuleAbi{}, &fl::make_video_engine};
  return &module;
}
