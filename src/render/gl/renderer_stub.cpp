// Built instead of the renderer (renderer.cpp, shader.cpp, gl_api.cpp, frame_target.cpp) when
// FRICTIONLAB_WITH_RENDER is OFF: the constructor throws MissingComponent naming it; the other
// members exist so that code using them still links.
#include "render/components.hpp"
#include "render/gl/renderer.hpp"

namespace fl::render {

struct Renderer::Impl {};
Renderer::Renderer(GlContext&, RendererOptions) {
  missing_drawing_layer("the renderer");
}
Renderer::~Renderer() = default;
MeshId Renderer::upload(const MeshData&) {
  missing_drawing_layer("the renderer");
}
void Renderer::begin_frame(const Camera&, const DirectionalLight&) {
  missing_drawing_layer("the renderer");
}
void Renderer::draw(MeshId, const Eigen::Affine3f&, bool) {
  missing_drawing_layer("the renderer");
}
void Renderer::set_shadow_bounds(std::optional<ShadowBounds>) {
  missing_drawing_layer("the renderer");
}
Overlay& Renderer::overlay() {
  missing_drawing_layer("the renderer");
}
ImageView Renderer::end_frame() {
  missing_drawing_layer("the renderer");
}
const FrameStats& Renderer::last_frame_stats() const {
  missing_drawing_layer("the renderer");
}
GlContext& Renderer::context() {
  missing_drawing_layer("the renderer");
}

}  // namespace fl::render
