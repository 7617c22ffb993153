// The rig model (rig_model.hpp) uploaded to a renderer and drawn at a pose: the GL side of the
// rig renderer. Its cameras and light are in rig_camera.hpp.
#pragma once

#include <vector>

#include "render/gl/renderer.hpp"
#include "render/rig/rig_model.hpp"
#include "render/rig/rig_pose.hpp"

namespace fl::render {

// The model uploaded to a renderer, drawn at a pose.
class RigView {
 public:
  RigView(Renderer& renderer, RigModel model);

  // Adds the rig's draws to the current frame. `exposure`: the simulated seconds one frame's
  // shutter stays open (half the frame interval); fast parts are drawn blurred over it.
  void draw(const RigPose& pose, double exposure) const;

  const RigModel& model() const { return model_; }

 private:
  Renderer& renderer_;
  RigModel model_;
  std::vector<MeshId> ids_;
};

}  // namespace fl::render
