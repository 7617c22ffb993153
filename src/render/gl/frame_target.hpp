// A multisampled colour + depth framebuffer that a back end resolves into its output
// framebuffer (internal to the render library; any back end can use it).
#pragma once

#include "render/gl/gl_api.hpp"

namespace fl::render {

class MultisampleTarget {
 public:
  // Needs a current context. samples > 1.
  MultisampleTarget(const GlApi& gl, int width, int height, int samples);
  MultisampleTarget(const MultisampleTarget&) = delete;
  MultisampleTarget& operator=(const MultisampleTarget&) = delete;
  ~MultisampleTarget();

  GLuint framebuffer() const { return framebuffer_; }
  // Blits (resolves) the samples into `output` (0: the back end's default framebuffer).
  void resolve_into(GLuint output) const;

 private:
  const GlApi& gl_;
  int width_;
  int height_;
  GLuint framebuffer_ = 0;
  GLuint color_ = 0;
  GLuint depth_ = 0;
};

}  // namespace fl::render
