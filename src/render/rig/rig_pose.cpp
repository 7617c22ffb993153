#include "render/rig/rig_pose.hpp"

#include <algorithm>

#include "render/rig/rig_geometry.hpp"

namespace fl::render {

RigPose rest_pose(const CompiledRig& rig) {
  RigPose pose;
  pose.plate_x = rig.plate_desc.offset;
  pose.plate_z = rig.plate.h_c;
  const std::size_t shafts = rig.drive ? rig.drive->layout.shafts.size() : 2;
  pose.shaft_angles.assign(shafts, 0.0);
  pose.shaft_speeds.assign(shafts, 0.0);
  return pose;
}

RigPose interpolate(const RigPose& a, const RigPose& b, double f) {
  const auto mix = [f](double x, double y) { return x + (y - x) * f; };
  RigPose out;
  out.plate_x = mix(a.plate_x, b.plate_x);
  out.plate_y = mix(a.plate_y, b.plate_y);
  out.plate_z = mix(a.plate_z, b.plate_z);
  out.pitch = mix(a.pitch, b.pitch);
  out.yaw = mix(a.yaw, b.yaw);
  const std::size_t n = std::min(a.shaft_angles.size(), b.shaft_angles.size());
  out.shaft_angles.resize(n);
  out.shaft_speeds.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.shaft_angles[i] = mix(a.shaft_angles[i], b.shaft_angles[i]);
    out.shaft_speeds[i] = mix(a.shaft_speeds[i], b.shaft_speeds[i]);
  }
  return out;
}

Eigen::Affine3f plate_transform(const RigPose& pose) {
  return rig::translation(Eigen::Vector3f(static_cast<float>(pose.plate_x),
                                          static_cast<float>(pose.plate_y),
                                          static_cast<float>(pose.plate_z))) *
         rig::about_z(pose.yaw) * rig::about_y(pose.pitch);
}

}  // namespace fl::render
