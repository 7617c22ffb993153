// Where each part of the rig model is at a pose, and which of its blurred meshes a frame draws.
#include <cmath>

#include "render/rig/rig_geometry.hpp"
#include "render/rig/rig_model.hpp"

namespace fl::render {
namespace {

// The nearest blur level to a sweep.
std::size_t blur_level(double sweep) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < kBlurSweeps.size(); ++i)
    if (std::fabs(kBlurSweeps[i] - sweep) < std::fabs(kBlurSweeps[best] - sweep)) best = i;
  return best;
}

}  // namespace

PlacedPart place_part(const RigModel& model, const RigPart& part, const RigPose& pose,
                      double exposure) {
  PlacedPart placed{part.mesh, part.local};
  switch (part.body) {
    case RigPart::Body::kWorld:
      break;
    case RigPart::Body::kPlate:
      placed.pose = plate_transform(pose) * part.local;
      break;
    case RigPart::Body::kShaft: {
      const auto s = static_cast<std::size_t>(part.shaft);
      const RigShaft& shaft = model.shafts.at(s);
      const double angle = s < pose.shaft_angles.size() ? pose.shaft_angles[s] : 0.0;
      const double speed = s < pose.shaft_speeds.size() ? pose.shaft_speeds[s] : 0.0;
      placed.pose = rig::translation(Eigen::Vector3f(static_cast<float>(shaft.x), 0.0f,
                                                     static_cast<float>(shaft.z))) *
                    rig::about_y(angle + part.phase) * part.local;
      if (!part.blur_variants.empty())
        placed.mesh = part.blur_variants[blur_level(std::fabs(speed) * exposure)];
      break;
    }
  }
  return placed;
}

std::size_t RigModel::triangles(const RigPose& pose, double exposure) const {
  std::size_t n = meshes[ground].triangle_count();
  for (const RigPart& part : parts)
    n += meshes[place_part(*this, part, pose, exposure).mesh].triangle_count();
  return n;
}

}  // namespace fl::render
