// The EGL back end: an OpenGL 3.3+ core context with no window, no display server and no
// surface. The display is Mesa's surfaceless platform (EGL_MESA_platform_surfaceless: llvmpipe
// here, a GPU's driver where there is one), else the first EGL device that starts
// (EGL_EXT_platform_device). With no default framebuffer, the frame is drawn into our own: the
// 4x multisampled target the OSMesa back end uses too, resolved into a single-sampled colour
// buffer and read with glReadPixels into a ring of pixel buffer objects: the copy of a frame runs
// while GL draws the next ones, and the mapped buffer is handed on as it is, its rows bottom-up
// (a negative stride, no flip).
#include "render/gl/gl_api.hpp"

// No X11 here: some eglplatform.h versions bring Xlib.h and its macros (None, Bool) unless told.
#define EGL_NO_X11
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>

#include "render/components.hpp"
#include "render/gl/frame_target.hpp"
#include "render/gl/gl_backends.hpp"

namespace fl::render {
namespace {

std::string egl_error_text() {
  const EGLint code = eglGetError();
  switch (code) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default:
      return "EGL error 0x" + [&] {
        char text[16];
        std::snprintf(text, sizeof text, "%x", static_cast<unsigned>(code));
        return std::string(text);
      }();
  }
}

bool has_extension(const char* list, std::string_view name) {
  if (list == nullptr) return false;
  const std::string_view all(list);
  for (std::size_t at = 0; (at = all.find(name, at)) != std::string_view::npos; at += name.size()) {
    const bool starts = at == 0 || all[at - 1] == ' ';
    const bool ends = at + name.size() == all.size() || all[at + name.size()] == ' ';
    if (starts && ends) return true;
  }
  return false;
}

// EGL displays are one per platform and device in a process, shared by every context on them:
// eglTerminate would end a display under the other contexts, and unload Mesa's driver. So each
// display is initialised once and stays for the process's life (eglInitialize on an initialised
// display only counts it again).
bool start_display(EGLDisplay display) {
  if (display == EGL_NO_DISPLAY) return false;
  static std::mutex mutex;
  const std::lock_guard lock(mutex);
  EGLint major = 0, minor = 0;
  return eglInitialize(display, &major, &minor) == EGL_TRUE;
}

// The surfaceless display, else the first device's that starts. Throws RenderError saying what
// was tried.
EGLDisplay open_display(std::string& platform) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (client == nullptr)
    throw RenderError(
        "EGL offers no client extensions (libEGL without EGL 1.5 or "
        "EGL_EXT_client_extensions)");
  const auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_display == nullptr || !has_extension(client, "EGL_EXT_platform_base"))
    throw RenderError("EGL has no eglGetPlatformDisplayEXT (EGL_EXT_platform_base)");
  std::string tried;
  if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
    const EGLDisplay d = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (start_display(d)) {
      platform = "surfaceless";
      return d;
    }
    tried = "the surfaceless platform did not initialise (" + egl_error_text() + ")";
  } else {
    tried = "no surfaceless platform (EGL_MESA_platform_surfaceless)";
  }
  const auto query_devices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (has_extension(client, "EGL_EXT_platform_device") && query_devices != nullptr) {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (query_devices(16, devices, &count) == EGL_TRUE) {
      for (EGLint i = 0; i < count; ++i) {
        const EGLDisplay d = get_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (start_display(d)) {
          platform = "device " + std::to_string(i);
          return d;
        }
      }
    }
    tried += "; none of " + std::to_string(count) + " EGL devices initialised";
  } else {
    tried += "; no EGL devices (EGL_EXT_platform_device)";
  }
  throw RenderError("EGL found no display without a window: " + tried);
}

// A framebuffer of one sample: the colour read back, and the depth when nothing is multisampled.
class SingleSampleTarget {
 public:
  SingleSampleTarget(const GlApi& gl, int width, int height, bool depth) : gl_(gl) {
    gl.GenRenderbuffers(1, &color_);
    gl.BindRenderbuffer(GL_RENDERBUFFER, color_);
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, 0, GL_RGBA8, width, height);
    if (depth) {
      gl.GenRenderbuffers(1, &depth_);
      gl.BindRenderbuffer(GL_RENDERBUFFER, depth_);
      gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, 0, GL_DEPTH_COMPONENT24, width, height);
    }
    gl.GenFramebuffers(1, &framebuffer_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    if (depth)
      gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
      throw RenderError("the EGL back end's framebuffer of " + std::to_string(width) + "x" +
                        std::to_string(height) + " is incomplete (status " +
                        std::to_string(status) + ")");
  }
  SingleSampleTarget(const SingleSampleTarget&) = delete;
  SingleSampleTarget& operator=(const SingleSampleTarget&) = delete;
  ~SingleSampleTarget() {
    gl_.DeleteFramebuffers(1, &framebuffer_);
    gl_.DeleteRenderbuffers(1, &color_);
    if (depth_ != 0) gl_.DeleteRenderbuffers(1, &depth_);
  }
  GLuint framebuffer() const { return framebuffer_; }

 private:
  const GlApi& gl_;
  GLuint framebuffer_ = 0;
  GLuint color_ = 0;
  GLuint depth_ = 0;
};

class EglContext final : public GlContext {
 public:
  explicit EglContext(const GlContextOptions& options)
      : width_(options.width), height_(options.height), samples_(options.samples) {
    display_ = open_display(platform_);
    try {
      const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
      if (!has_extension(extensions, "EGL_KHR_no_config_context") &&
          !has_extension(extensions, "EGL_MESA_configless_context"))
        throw RenderError(
            "EGL cannot make a context without a config "
            "(EGL_KHR_no_config_context)");
      if (!has_extension(extensions, "EGL_KHR_surfaceless_context"))
        throw RenderError(
            "EGL cannot make a context current without a surface "
            "(EGL_KHR_surfaceless_context)");
      if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE)
        throw RenderError("EGL offers no desktop OpenGL (" + egl_error_text() + ")");
      // OpenGL 3.3 core or newer (llvmpipe answers with 4.5 core).
      const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                   3,
                                   EGL_CONTEXT_MINOR_VERSION,
                                   3,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                   EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                   EGL_NONE};
      context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
      if (context_ == EGL_NO_CONTEXT)
        throw RenderError("EGL could not create an OpenGL 3.3 core context (" + egl_error_text() +
                          ")");
      make_current();
      gl_.load(&eglGetProcAddress, "egl");
      // Colour + depth in one sample when nothing is multisampled; else the multisampled target
      // takes the drawing and this one only the resolved colour.
      resolved_ = std::make_unique<SingleSampleTarget>(gl_, width_, height_, samples_ <= 1);
      if (samples_ > 1)
        target_ = std::make_unique<MultisampleTarget>(gl_, width_, height_, samples_);
      gl_.GenBuffers(kReadBuffers, read_buffers_.data());
      for (const GLuint buffer : read_buffers_) {
        gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, buffer);
        gl_.BufferData(GL_PIXEL_PACK_BUFFER, frame_bytes(), nullptr, GL_STREAM_READ);
      }
      gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
      gl_.check("creating the EGL context");
    } catch (...) {
      release();
      throw;
    }
  }

  ~EglContext() override { release(); }

  std::string_view backend_name() const override { return "egl"; }

  std::string description() const override {
    const auto text = [&](GLenum name) {
      const auto* s = reinterpret_cast<const char*>(gl_.GetString(name));
      return std::string(s == nullptr ? "?" : s);
    };
    return text(GL_VERSION) + ", " + text(GL_RENDERER) + " (EGL " + platform_ + ")";
  }

  void make_current() override {
    // EGL skips binding a context it believes current; another library (OSMesa shares Mesa's GL
    // dispatch) may have made its own current since, so bind again from scratch.
    if (eglGetCurrentContext() == context_)
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE)
      throw RenderError("EGL could not make its context current without a surface (" +
                        egl_error_text() + ")");
  }

  int width() const override { return width_; }
  int height() const override { return height_; }
  int samples() const override { return samples_; }
  const GlApi& gl() const override { return gl_; }
  unsigned frame_framebuffer() const override {
    return target_ ? target_->framebuffer() : resolved_->framebuffer();
  }

  void queue_frame() override {
    if (queued_ == kReadBuffers)
      throw std::logic_error("EglContext::queue_frame: every read buffer holds a frame not taken");
    unmap();
    if (target_) target_->resolve_into(resolved_->framebuffer());
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, resolved_->framebuffer());
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
    const std::size_t slot = (next_ + static_cast<std::size_t>(queued_)) % kReadBuffers;
    gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, read_buffers_[slot]);
    // Into the buffer object: GL copies when the frame is done, and this call returns at once.
    gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    gl_.check("reading the frame");
    ++queued_;
  }

  ImageView take_frame() override {
    if (queued_ == 0) throw std::logic_error("EglContext::take_frame: no frame is queued");
    unmap();
    gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, read_buffers_[next_]);
    // Waits for that frame's copy, not for the frames drawn since.
    const auto* rows = static_cast<const std::uint8_t*>(
        gl_.MapBufferRange(GL_PIXEL_PACK_BUFFER, 0, frame_bytes(), GL_MAP_READ_BIT));
    gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    gl_.check("mapping a read-back buffer");
    if (rows == nullptr) throw RenderError("EGL could not map a frame's read-back buffer");
    mapped_ = read_buffers_[next_];
    next_ = (next_ + 1) % kReadBuffers;
    --queued_;
    // GL's rows run bottom-up; frames are top-down: start at the last row and step back.
    const auto row = static_cast<std::ptrdiff_t>(width_) * 4;
    return ImageView{rows + row * (height_ - 1), width_, height_, -row};
  }

  int queued_frames() const override { return queued_; }
  int frames_behind() const override { return kReadBuffers - 1; }

 private:
  // Frames in flight: the one being taken and two more drawn behind it.
  static constexpr int kReadBuffers = 3;

  GLsizeiptr frame_bytes() const { return static_cast<GLsizeiptr>(width_) * height_ * 4; }

  // The buffer last handed out goes back to GL.
  void unmap() {
    if (mapped_ == 0) return;
    gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, mapped_);
    gl_.UnmapBuffer(GL_PIXEL_PACK_BUFFER);
    gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    mapped_ = 0;
  }

  void release() {
    if (display_ == EGL_NO_DISPLAY) return;
    if (context_ != EGL_NO_CONTEXT) {
      // GL objects must go while their context is current.
      if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) == EGL_TRUE) {
        unmap();
        if (read_buffers_[0] != 0) gl_.DeleteBuffers(kReadBuffers, read_buffers_.data());
        target_.reset();
        resolved_.reset();
      }
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display_, context_);
      context_ = EGL_NO_CONTEXT;
    }
    display_ = EGL_NO_DISPLAY;  // initialised for the process's life (start_display)
  }

  int width_;
  int height_;
  int samples_;
  std::string platform_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  GlApi gl_;
  std::unique_ptr<SingleSampleTarget> resolved_;
  std::unique_ptr<MultisampleTarget> target_;
  std::array<GLuint, kReadBuffers> read_buffers_{};
  std::size_t next_ = 0;  // the read buffer of the oldest queued frame
  int queued_ = 0;
  GLuint mapped_ = 0;  // the buffer whose pixels the last take_frame() handed out
};

}  // namespace

std::unique_ptr<GlContext> make_egl_context(const GlContextOptions& options) {
  return std::make_unique<EglContext>(options);
}

}  // namespace fl::render
