// The magnets on the plate as point dipoles carried by it: their field at a point of the world,
// for the plate at a pose. The Hall sensor reads one component of it, a phone's magnetometer all
// three.
#pragma once

#include <vector>

#include "scene/compiled_rig.hpp"
#include "sensor/plate_pose.hpp"

namespace fl {

class PlateMagnets {
 public:
  explicit PlateMagnets(const CompiledRig& rig);

  // The magnets' field [T] at `point` [m, world frame] with the plate at `pose`.
  Vec3 field(const PlatePose& pose, const Vec3& point) const;
  // Its component along the unit vector `axis`, summed magnet by magnet.
  double field_along(const PlatePose& pose, const Vec3& point, const Vec3& axis) const;

 private:
  struct MagnetOnPlate {
    Vec3 offset;    // m, from the plate's centre of mass in the plate's frame
    double moment;  // A m^2 along the plate's +z
  };
  // Calls `add` with each magnet's field at `point`.
  template <class Add>
  void each_field(const PlatePose& pose, const Vec3& point, Add add) const;
  std::vector<MagnetOnPlate> magnets_;
};

}  // namespace fl
