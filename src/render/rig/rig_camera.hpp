// The rig's cameras and light: a video's camera preset fitted around the rig model (or the
// scene's placed camera), the slow orbit, and the light of every frame.
#pragma once

#include "render/camera.hpp"
#include "render/rig/rig_model.hpp"
#include "scene/video_yaml.hpp"

namespace fl::render {

// The camera of a video: its preset framed around the rig (the parts the overlay leaves free),
// or the placed camera. Fitting a preset projects a few thousand points: call it once a video.
Camera rig_camera(const RigModel& model, const VideoDesc& video);
// The camera turned by `radians` about the vertical through its target (the slow orbit).
Camera orbit_camera(const Camera& camera, double radians);
// The light of every frame.
DirectionalLight rig_light();

}  // namespace fl::render
