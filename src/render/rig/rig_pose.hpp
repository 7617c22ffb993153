// The rig's moving parts at one instant: the physics' state after a step, or interpolated
// between two steps to a frame's time (frames follow the video's clock, not the physics step).
// Coordinates are the scene's: x along the plate's motion, z up, metres.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "scene/compiled_rig.hpp"

namespace fl::render {

// The moving parts at one instant (the physics' state, interpolated to a frame's time).
struct RigPose {
  double plate_x = 0.0;  // m, the plate's centre of mass
  double plate_y = 0.0;  // m
  double plate_z = 0.0;  // m
  double pitch = 0.0;    // rad about +y
  double yaw = 0.0;      // rad about +z
  // Every shaft's angle and speed about +y, in drive_layout order (rollers first). For a scene
  // without a drive: the two rollers.
  std::vector<double> shaft_angles;  // rad, unwrapped
  std::vector<double> shaft_speeds;  // rad/s
};

// The rig at the start of a run: the plate at its offset, resting on the rollers, every angle 0.
RigPose rest_pose(const CompiledRig& rig);
// (1 - f) a + f b, part by part (angles unwrapped, so linear is right).
RigPose interpolate(const RigPose& a, const RigPose& b, double f);

// The plate's body frame (centre of mass) in the world at a pose.
Eigen::Affine3f plate_transform(const RigPose& pose);

}  // namespace fl::render
