#include "render/gl/frame_target.hpp"

#include <string>

#include "render/components.hpp"

namespace fl::render {

MultisampleTarget::MultisampleTarget(const GlApi& gl, int width, int height, int samples)
    : gl_(gl), width_(width), height_(height) {
  GLint max_samples = 0;
  gl.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (samples > max_samples)
    throw RenderError("the GL back end offers at most " + std::to_string(max_samples) +
                      " samples, not " + std::to_string(samples));
  gl.GenRenderbuffers(1, &color_);
  gl.BindRenderbuffer(GL_RENDERBUFFER, color_);
  gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  gl.GenRenderbuffers(1, &depth_);
  gl.BindRenderbuffer(GL_RENDERBUFFER, depth_);
  gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  gl.GenFramebuffers(1, &framebuffer_);
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw RenderError("the " + std::to_string(samples) + "x multisampled framebuffer of " +
                      std::to_string(width) + "x" + std::to_string(height) +
                      " is incomplete (status " + std::to_string(status) + ")");
  gl.check("creating the multisampled framebuffer");
}

MultisampleTarget::~MultisampleTarget() {
  gl_.DeleteFramebuffers(1, &framebuffer_);
  gl_.DeleteRenderbuffers(1, &color_);
  gl_.DeleteRenderbuffers(1, &depth_);
}

void MultisampleTarget::resolve_into(GLuint output) const {
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, output);
  gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace fl::render
