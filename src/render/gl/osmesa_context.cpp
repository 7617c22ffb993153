// The OSMesa back end: software rendering by Mesa's llvmpipe into a buffer we own. Rows are
// stored top-down (OSMESA_Y_UP = 0), so the finished frame needs no flip and no glReadPixels:
// after glFinish the buffer holds it.
// glcorearb.h first: osmesa.h brings GL/gl.h, which would hide glcorearb.h's GL 1.1 typedefs.
#include "render/gl/gl_api.hpp"

#include <GL/osmesa.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/components.hpp"
#include "render/gl/frame_target.hpp"
#include "render/gl/gl_backends.hpp"

namespace fl::render {
namespace {

class OsmesaContext final : public GlContext {
 public:
  explicit OsmesaContext(const GlContextOptions& options)
      : width_(options.width), height_(options.height), samples_(options.samples) {
    // OpenGL 3.3 core or newer (llvmpipe answers with 4.5 core).
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr)
      throw RenderError("OSMesa could not create an OpenGL 3.3 core context");
    buffer_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4, 0);
    try {
      make_current();
      OSMesaPixelStore(OSMESA_Y_UP, 0);
      gl_.load(&OSMesaGetProcAddress, "osmesa");
      if (samples_ > 1)
        target_ = std::make_unique<MultisampleTarget>(gl_, width_, height_, samples_);
      gl_.check("creating the OSMesa context");
    } catch (...) {
      target_.reset();
      OSMesaDestroyContext(context_);
      throw;
    }
  }

  ~OsmesaContext() override {
    // GL objects must go while their context is current.
    OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_);
    target_.reset();
    OSMesaDestroyContext(context_);
  }

  std::string_view backend_name() const override { return "osmesa"; }

  std::string description() const override {
    const auto text = [&](GLenum name) {
      const auto* s = reinterpret_cast<const char*>(gl_.GetString(name));
      return std::string(s == nullptr ? "?" : s);
    };
    return text(GL_VERSION) + ", " + text(GL_RENDERER) + " (OSMesa)";
  }

  void make_current() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
      throw RenderError("OSMesa could not make its context current on a " + std::to_string(width_) +
                        "x" + std::to_string(height_) + " buffer");
  }

  int width() const override { return width_; }
  int height() const override { return height_; }
  int samples() const override { return samples_; }
  const GlApi& gl() const override { return gl_; }
  unsigned frame_framebuffer() const override { return target_ ? target_->framebuffer() : 0; }

  // The frame is finished in OSMesa's own buffer, which the next frame draws over: it is taken
  // where it is drawn.
  void queue_frame() override {
    if (queued_) throw std::logic_error("OsmesaContext::queue_frame: the last frame is not taken");
    if (target_) target_->resolve_into(0);
    gl_.Finish();
    gl_.check("finishing the frame");
    queued_ = true;
  }
  ImageView take_frame() override {
    if (!queued_) throw std::logic_error("OsmesaContext::take_frame: no frame is queued");
    queued_ = false;
    return ImageView{buffer_.data(), width_, height_, static_cast<std::ptrdiff_t>(width_) * 4};
  }
  int queued_frames() const override { return queued_ ? 1 : 0; }
  int frames_behind() const override { return 0; }

 private:
  int width_;
  int height_;
  int samples_;
  OSMesaContext context_ = nullptr;
  std::vector<std::uint8_t> buffer_;
  GlApi gl_;
  std::unique_ptr<MultisampleTarget> target_;
  bool queued_ = false;
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context(const GlContextOptions& options) {
  return std::make_unique<OsmesaContext>(options);
}

}  // namespace fl::render
