// The minimal drawing layer the rig renderer builds on: meshes uploaded once and drawn with a
// model matrix each frame, a perspective camera, one directional light with a shadow map, and
// the 2D overlay drawn last. Every frame:
//
//   renderer.begin_frame(camera, light);
//   renderer.draw(roller_mesh, roller_pose);           // as many as there are parts
//   renderer.overlay().text("T = 0.79 s", {12, 10}, 16, white);
//   ImageView frame = renderer.end_frame();            // RGBA, rows top-down
//   sink.write(frame);
//
// The context must be current on the calling thread. Throws RenderError on any GL failure, so
// a frame is either drawn or an error, never a silently blank picture.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

#include "render/camera.hpp"
#include "render/gl/gl_context.hpp"
#include "render/image.hpp"
#include "render/mesh_data.hpp"
#include "render/overlay.hpp"

namespace fl::render {

struct RendererOptions {
  bool shadows = true;
  int shadow_map_size = 2048;  // texels per side
  bool soft_shadows = false;   // 4 filtered lookups instead of 1: softer edges, ~7 ms more at 720p
  Color background{0.93f, 0.94f, 0.96f, 1.0f};  // the clear colour (sRGB)
  std::string font_path = default_font_path();
};

// The region the shadow map covers, in world metres.
struct ShadowBounds {
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  float radius = 0.0f;
};

struct FrameStats {
  std::size_t draws = 0;
  std::size_t triangles = 0;         // in the camera pass
  std::size_t shadow_triangles = 0;  // in the shadow pass
  std::size_t overlay_vertices = 0;
};

using MeshId = std::uint32_t;

class Renderer {
 public:
  // Compiles the shaders and makes the shadow map. `context` must outlive the Renderer.
  explicit Renderer(GlContext& context, RendererOptions options = {});
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  ~Renderer();

  // Uploads a mesh; it stays on the GPU as long as the Renderer. Throws std::invalid_argument
  // for an inconsistent mesh.
  MeshId upload(const MeshData& mesh);

  // Starts a frame: forgets the previous frame's draws and overlay.
  void begin_frame(const Camera& camera, const DirectionalLight& light);
  // Draws a mesh placed by `model` (part frame to world).
  void draw(MeshId mesh, const Eigen::Affine3f& model, bool casts_shadow = true);
  // Fixes the region the shadow map covers (keeps shadows still when parts move). Without it,
  // the region is fitted around each frame's shadow casters.
  void set_shadow_bounds(std::optional<ShadowBounds> bounds);
  // The 2D layer of this frame, drawn over the scene.
  Overlay& overlay();
  // Renders the shadow map, the scene and the overlay, and returns the finished frame (valid
  // until the next frame is drawn). No frame may be queued (submit_frame).
  ImageView end_frame();
  // The same for a stream of frames read back behind the drawing: renders the frame and queues
  // its read-back (GlContext::queue_frame). With frames_behind() + 1 queued, take one first.
  void submit_frame();

  const FrameStats& last_frame_stats() const;
  GlContext& context();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fl::render
