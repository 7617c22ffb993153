// The GL back end behind one small interface. A GlContext is an OpenGL 3.3+ core context with
// a frame of a fixed size: the renderer draws into frame_framebuffer() (multisampled when
// samples() > 1) and read_frame() resolves it and returns the finished pixels, rows top-down.
// A stream of frames can also be read back a few frames behind the drawing: queue_frame() starts
// a frame's copy out of GL and take_frame() hands back the oldest queued one, so that GL draws
// the next frames while the copies finish (pixel buffer objects where the back end reads with
// glReadPixels).
// Back ends: "osmesa" (software, llvmpipe; FRICTIONLAB_WITH_OSMESA) and "egl" (no display:
// Mesa's surfaceless platform or an EGL device; FRICTIONLAB_WITH_EGL). A build without any makes
// no context: make_gl_context says which it has.
// Adding one means a class deriving from GlContext and a line in make_gl_context; the renderer
// does not change.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "render/image.hpp"

namespace fl::render {

struct GlApi;

enum class GlBackend { kOsmesa, kEgl };

// "osmesa", "egl".
std::string_view gl_backend_name(GlBackend backend);
// Every name make_gl_context accepts: the back ends and "auto".
std::span<const std::string_view> gl_backend_names();
// Whether this build has the back end compiled in.
bool gl_backend_compiled(GlBackend backend);
// The back ends this build has compiled in, in the order "auto" tries them ("egl, osmesa"), or
// "none".
std::string compiled_gl_backends();

// The environment variable that chooses the back end when the command line does not.
inline constexpr const char* kGlBackendVariable = "FRICTIONLAB_GL";

// What the user asked for, in order: `requested` (e.g. from --gl), then $FRICTIONLAB_GL, then
// "auto". Returns the name and where it came from ("--gl", "FRICTIONLAB_GL", "default").
struct GlBackendRequest {
  std::string name;
  std::string source;
};
GlBackendRequest gl_backend_request(std::string_view requested = {});

struct GlContextOptions {
  int width = 640;          // pixels
  int height = 360;         // pixels
  int samples = 4;          // multisampling: 1 (none) or 4 (llvmpipe offers only 4)
  std::string backend;      // "osmesa", "egl", "auto"; empty: $FRICTIONLAB_GL, then auto
  std::string source = "";  // where `backend` came from, for messages (a request's field)
};

class GlContext {
 public:
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  virtual ~GlContext() = default;

  // "osmesa", "egl".
  virtual std::string_view backend_name() const = 0;
  // GL_VERSION and GL_RENDERER, e.g. "4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6)".
  virtual std::string description() const = 0;
  // Makes the context current on the calling thread (contexts start current on the thread that
  // made them).
  virtual void make_current() = 0;

  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual int samples() const = 0;
  // The functions of this context.
  virtual const GlApi& gl() const = 0;
  // The framebuffer the renderer draws a frame into (multisampled, with depth).
  virtual unsigned frame_framebuffer() const = 0;
  // Resolves the frame, waits for GL to finish it, and returns its RGBA pixels, rows top-down.
  // The view stays valid until the next frame is drawn. No frame may be queued (a logic error
  // otherwise: take them first). Throws RenderError on a GL error.
  ImageView read_frame();

  // Resolves the frame just drawn and starts copying it out of GL; the caller may draw the next
  // frame at once. At most frames_behind() + 1 frames may be queued: with that many, take one
  // before queueing another (a logic error otherwise).
  virtual void queue_frame() = 0;
  // The oldest queued frame's RGBA pixels, rows top-down, once its copy is done (a logic error
  // when none is queued). The view stays valid until the next queue_frame(), take_frame() or
  // draw. Throws RenderError on a GL error.
  virtual ImageView take_frame() = 0;
  // Frames queued and not yet taken.
  virtual int queued_frames() const = 0;
  // How many frames the read-back may lag the drawing: 0 where a frame is read where it is drawn
  // (OSMesa's own buffer), 2 where pixel buffer objects carry it.
  virtual int frames_behind() const = 0;
};

// Makes a context of the chosen back end. Throws RenderError for an unknown name (listing the
// valid ones) or a back end that fails to start, MissingComponent for one not compiled in (and
// for "auto" when none is), naming the back ends this build has. "auto" tries EGL, then OSMesa;
// when one did not start before the one made, `note` (if given) says so in one line, e.g.
// "GL back end egl did not start (...); using osmesa", and is empty otherwise.
std::unique_ptr<GlContext> make_gl_context(const GlContextOptions& options,
                                           std::string* note = nullptr);

}  // namespace fl::render
