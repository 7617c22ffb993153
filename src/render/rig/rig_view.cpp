#include "render/rig/rig_view.hpp"

#include <utility>

namespace fl::render {

RigView::RigView(Renderer& renderer, RigModel model)
    : renderer_(renderer), model_(std::move(model)) {
  for (const MeshData& mesh : model_.meshes) ids_.push_back(renderer_.upload(mesh));
  renderer_.set_shadow_bounds(model_.shadow);
}

void RigView::draw(const RigPose& pose, double exposure) const {
  for (const RigPart& part : model_.parts) {
    const PlacedPart placed = place_part(model_, part, pose, exposure);
    renderer_.draw(ids_[placed.mesh], model_.tilt * placed.pose, part.casts_shadow);
  }
  // The ground last: where the rig covers it, its fragments fail the depth test before they are
  // shaded.
  renderer_.draw(ids_[model_.ground], model_.tilt, false);
}

}  // namespace fl::render
